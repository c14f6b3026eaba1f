#!/usr/bin/env python3
"""Draws tessera's module graph as an SVG (docs/architecture.md) from the modules' CMake DEPS: the
tessera::<m> entries of each tessera_add_module() call in src/<module>/CMakeLists.txt, the same
entries the include check (scripts/check_includes.py) allows. Modules sit in layers by their
longest dependency chain (core at the bottom); an arrow points from a module to one it links.
Edges implied by a longer path are left out (transitive reduction) so the picture stays readable.

Usage: module_graph.py OUT.svg [--rev GIT_REVISION] [--title TEXT]
With --rev the CMake files are read from that revision (the "before" picture), else from the
working tree. Run from anywhere inside the repository.
"""
import argparse
import pathlib
import re
import subprocess
import sys
from xml.sax.saxutils import escape

CALL = re.compile(r"tessera_add_module\(\s*(\w+)(.*?)\)\s*(?:\n|$)", re.S)
DEP = re.compile(r"tessera::(\w+)")


def repo_root():
    out = subprocess.run(["git", "rev-parse", "--show-toplevel"], capture_output=True, text=True,
                         check=True)
    return pathlib.Path(out.stdout.strip())


def cmake_files(root, rev):
    if rev is None:
        for path in sorted((root / "src").glob("*/CMakeLists.txt")):
            yield path.read_text()
        return
    listing = subprocess.run(["git", "ls-tree", "--name-only", f"{rev}:src"], cwd=root,
                             capture_output=True, text=True, check=True).stdout.split()
    for name in sorted(listing):
        show = subprocess.run(["git", "show", f"{rev}:src/{name}/CMakeLists.txt"], cwd=root,
                              capture_output=True, text=True)
        if show.returncode == 0:
            yield show.stdout


def read_graph(root, rev):
    deps = {}
    for text in cmake_files(root, rev):
        for m in CALL.finditer(text):
            name = m.group(1)
            deps[name] = sorted({d for d in DEP.findall(m.group(2)) if d != name})
    return deps


def reachable(deps, start):
    seen, todo = set(), list(deps.get(start, []))
    while todo:
        d = todo.pop()
        if d not in seen:
            seen.add(d)
            todo.extend(deps.get(d, []))
    return seen


def reduce(deps):
    """Keeps an edge m -> d only when no other dependency of m reaches d."""
    out = {}
    for m, ds in deps.items():
        out[m] = [d for d in ds if not any(d in reachable(deps, o) for o in ds if o != d)]
    return out


def layers(deps):
    level = {}

    def depth(m):
        if m not in level:
            level[m] = 1 + max((depth(d) for d in deps.get(m, [])), default=-1)
        return level[m]

    for m in deps:
        depth(m)
    rows = [[] for _ in range(max(level.values()) + 1)]
    for m in sorted(deps):
        rows[level[m]].append(m)
    # Order each row by the mean position of its dependencies (barycentre), bottom up, twice.
    for _ in range(2):
        for r in range(1, len(rows)):
            below = {m: i for row in rows[:r] for i, m in enumerate(row)}
            rows[r].sort(key=lambda m: (sum(below.get(d, 0) for d in deps[m]) /
                                        max(1, len(deps[m])), m))
    return rows


def svg(deps, title):
    edges = reduce(deps)
    rows = layers(deps)
    box_w, box_h, gap_x, gap_y, margin = 96, 30, 28, 58, 24
    width = max(max(len(r) for r in rows) * (box_w + gap_x) - gap_x, 8 * len(title)) + 2 * margin
    height = len(rows) * (box_h + gap_y) - gap_y + 2 * margin + 28
    pos = {}
    for r, row in enumerate(rows):
        row_w = len(row) * (box_w + gap_x) - gap_x
        x0 = (width - row_w) / 2
        y = height - margin - box_h - r * (box_h + gap_y)
        for i, m in enumerate(row):
            pos[m] = (x0 + i * (box_w + gap_x), y)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width:.0f}" height="{height:.0f}" '
           f'viewBox="0 0 {width:.0f} {height:.0f}" font-family="sans-serif" font-size="13">',
           '<defs><marker id="arrow" viewBox="0 0 10 10" refX="10" refY="5" markerWidth="7" '
           'markerHeight="7" orient="auto-start-reverse"><path d="M 0 0 L 10 5 L 0 10 z" '
           'fill="#555"/></marker></defs>',
           '<rect width="100%" height="100%" fill="white"/>',
           f'<text x="{margin}" y="{margin}" font-size="15" font-weight="bold">'
           f'{escape(title)}</text>']
    for m in sorted(edges):
        for d in edges[m]:
            (x1, y1), (x2, y2) = pos[m], pos[d]
            out.append(f'<line x1="{x1 + box_w / 2:.1f}" y1="{y1 + box_h:.1f}" '
                       f'x2="{x2 + box_w / 2:.1f}" y2="{y2:.1f}" stroke="#555" '
                       f'stroke-width="1.2" marker-end="url(#arrow)"/>')
    for m, (x, y) in sorted(pos.items()):
        out.append(f'<rect x="{x:.1f}" y="{y:.1f}" width="{box_w}" height="{box_h}" rx="5" '
                   f'fill="#eef3fb" stroke="#345"/>')
        out.append(f'<text x="{x + box_w / 2:.1f}" y="{y + box_h / 2 + 4.5:.1f}" '
                   f'text-anchor="middle">{escape(m)}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--rev")
    parser.add_argument("--title", default="tessera modules (arrow: links)")
    args = parser.parse_args(argv[1:])
    deps = read_graph(repo_root(), args.rev)
    if not deps:
        print("no tessera_add_module() calls found", file=sys.stderr)
        return 1
    pathlib.Path(args.out).write_text(svg(deps, args.title))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
