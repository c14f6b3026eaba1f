#!/usr/bin/env python3
"""Issue 13's size rules: no apps/tessera/cmd_*.cpp over 250 lines and no function in src/ over
120 lines. Functions are found by layout (clang-format's): a definition's line ends with "{" at
indentation 0 (free functions, out-of-class members) or 2 (members defined in a class), and its
body ends at the next "}" line with the same indentation. Namespaces, classes, structs, enums and
initialiser lists are skipped. Exit 1 and one line per breach.
Usage: check_sizes.py SOURCE_DIR [MAX_COMMAND_LINES MAX_FUNCTION_LINES] (the limits for the test
of this script on a small fixture)"""
import pathlib
import re
import sys

MAX_COMMAND_LINES = 250
MAX_FUNCTION_LINES = 120
NOT_FUNCTION = re.compile(r"^\s*(namespace|class|struct|enum|union|extern)\b|=\s*\{$|^\s*(const|constexpr|static|inline)?\s*[\w:<>, ]+\s+k\w+.*=")


def long_functions(path, max_lines):
    lines = path.read_text(encoding="utf-8", errors="replace").splitlines()
    out = []
    i = 0
    while i < len(lines):
        line = lines[i]
        indent = len(line) - len(line.lstrip(" "))
        if indent in (0, 2) and line.rstrip().endswith("{") and "(" in "".join(lines[max(0, i - 4):i + 1]) \
                and not NOT_FUNCTION.search(line) and not line.lstrip().startswith(("//", "#", "}")):
            closing = " " * indent + "}"
            j = i + 1
            while j < len(lines) and not lines[j].startswith(closing):
                j += 1
            if j < len(lines) and (j - i + 1) > max_lines:
                out.append((i + 1, j - i + 1, line.strip()))
            i = j + 1 if j < len(lines) and indent == 0 else i + 1
            continue
        i += 1
    return out


def main():
    root = pathlib.Path(sys.argv[1])
    max_command, max_function = MAX_COMMAND_LINES, MAX_FUNCTION_LINES
    if len(sys.argv) == 4:
        max_command, max_function = int(sys.argv[2]), int(sys.argv[3])
    problems = []
    for cmd in sorted((root / "apps" / "tessera").glob("cmd_*.cpp")):
        n = len(cmd.read_text(encoding="utf-8").splitlines())
        if n > max_command:
            problems.append(f"{cmd.relative_to(root)}: {n} lines, more than {max_command}")
    for source in sorted((root / "src").rglob("*.cpp")):
        for line, n, head in long_functions(source, max_function):
            problems.append(f"{source.relative_to(root)}:{line}: a function of {n} lines, more than "
                            f"{max_function}: {head}")
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
