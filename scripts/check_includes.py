#!/usr/bin/env python3
"""The module include check (docs/architecture.md): a module's sources (src/<m>/) and public headers
(include/tessera/<m>/) may include tessera/<other>/... only for a module they link, directly or
transitively. The allowed edges come from one place, the DEPS and PRIVATE_DEPS of each module's
tessera_add_module() call: CMake writes them to a file, one module a line ("name: dep dep ...").
apps/, bench/, tests/, fuzz/ and firmware/ are exempt (they link what they use).

Usage: check_includes.py DEPS_FILE SOURCE_ROOT
Prints one line per violation (file:line: what, and the fix) and exits 1 when there is any; exits 2
on a malformed deps file.
"""
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]tessera/([A-Za-z0-9_]+)/')
SUFFIXES = {".hpp", ".cpp", ".h", ".cc", ".ipp"}


def read_deps(path):
    deps = {}
    for number, line in enumerate(path.read_text().splitlines(), 1):
        if not line.strip():
            continue
        name, sep, rest = line.partition(":")
        if not sep or not name.strip():
            raise ValueError(f"{path}:{number}: expected 'module: dep dep ...', got '{line}'")
        deps[name.strip()] = rest.split()
    return deps


def closure(deps, module):
    seen, todo = {module}, [module]
    while todo:
        for d in deps.get(todo.pop(), []):
            if d not in seen:
                seen.add(d)
                todo.append(d)
    return seen


def module_files(root, module):
    for base in (root / "src" / module, root / "include" / "tessera" / module):
        if base.is_dir():
            yield from sorted(p for p in base.rglob("*") if p.suffix in SUFFIXES and p.is_file())


def check(deps, root):
    problems = []
    for module in sorted(deps):
        allowed = closure(deps, module)
        for path in module_files(root, module):
            lines = path.read_text(errors="replace").splitlines()
            for number, line in enumerate(lines, 1):
                m = INCLUDE.match(line)
                if m and m.group(1) not in allowed:
                    other = m.group(1)
                    known = "" if other in deps else f" ('{other}' is no module)"
                    problems.append(
                        f"{path.relative_to(root)}:{number}: module {module} includes "
                        f"tessera/{other}/ but does not link tessera::{other}{known}; add it to "
                        f"DEPS in src/{module}/CMakeLists.txt or move the code")
    return problems


def main(argv):
    if len(argv) != 3:
        print("usage: check_includes.py DEPS_FILE SOURCE_ROOT", file=sys.stderr)
        return 2
    deps_file, root = pathlib.Path(argv[1]), pathlib.Path(argv[2])
    try:
        deps = read_deps(deps_file)
    except (OSError, ValueError) as e:
        print(e, file=sys.stderr)
        return 2
    problems = check(deps, root)
    for p in problems:
        print(p)
    if problems:
        print(f"include check: {len(problems)} include(s) of modules not linked")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
