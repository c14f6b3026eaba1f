#!/usr/bin/env python3
"""Looks for a room that reproduces the lecture's similarity table (a.t) ("Numerical example for a
SLAM algorithm"), whose figures are not in the notes: every room of a family consistent with the
text (a left wall, a pillar one or two cells wide on it, the wall ahead 6-10 cells up, the right side
open or walled, the robot 1-4 cells from the left wall) is drawn as a map, `tessera gridmatch` runs
the lecture's step in it (map made at cell row 3, one cell up, turned 15 deg clockwise), and the
rooms are ranked by the summed difference of their 15 S values from the lecture's. Decision 0026
reports what it found.

usage: scripts/gridmatch_rooms.py [--tessera build/dev/apps/tessera/tessera] [--top 5]
"""
import argparse
import json
import math
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
LECTURE = [[22, 32, 20], [23, 25, 16], [19, 28, 21], [6, 7, 18], [22, 18, 18]]
ROWS = [(0, 0), (0, 1), (0, -1), (-1, 0), (1, 0)]  # intended, up, down, left, right
COLUMNS = [0, -1, 1]  # intended heading, 15 deg CW, 15 deg CCW
CELL_M = 0.3


def rooms():
    """(name, rows top first, robot column) for every room of the family."""
    for rx in (1, 2, 3, 4):
        for pw in (1, 2):
            for py0 in range(3, 8):
                for py1 in range(py0, 9):
                    for ahead in (6, 7, 8, 9, 10):
                        for right in (None, 6, 7, 8):
                            if pw >= rx or py1 >= ahead or (right is not None and right <= rx + 1):
                                continue
                            g = [["."] * 12 for _ in range(ahead + 1)]
                            for x in range(12):
                                g[0][x] = g[ahead][x] = "#"
                            for y in range(ahead + 1):
                                g[y][0] = "#"
                                if right is not None:
                                    g[y][right] = "#"
                            for y in range(py0, py1 + 1):
                                for x in range(1, 1 + pw):
                                    g[y][x] = "#"
                            if g[3][rx] == "#" or g[4][rx] == "#":
                                continue
                            name = f"robot{rx}_pillar{pw}x{py0}-{py1}_ahead{ahead}_right{right}"
                            yield name, ["".join(r) for r in reversed(g)], rx


def table_of(tessera, folder, name, rows, rx):
    pgm, yaml = folder / f"{name}.pgm", folder / f"{name}.yaml"
    with open(pgm, "wb") as f:
        f.write(f"P5\n{len(rows[0])} {len(rows)}\n255\n".encode())
        for row in rows:
            f.write(bytes(0 if c == "#" else 254 for c in row))
    yaml.write_text(f"image: {pgm.name}\nresolution: {CELL_M}\norigin: [0.0, 0.0, 0.0]\n"
                    "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")
    out = folder / f"out_{name}"
    run = subprocess.run([tessera, "gridmatch", "--quiet", "--world", str(yaml), "--before",
                          f"{(rx + 0.5) * CELL_M},{3.5 * CELL_M},{math.pi / 2}", "--out", str(out)],
                         capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"{name}: exit {run.returncode}: {run.stdout}{run.stderr}")
    report = json.loads((out / "report.json").read_text())["gridmatch"]
    s = {(c["dx_steps"], c["dy_steps"], c["dheading_steps"]): c["similarity"]
         for c in report["candidates"]}
    return [[s[(dx, dy, dh)] for dh in COLUMNS] for dx, dy in ROWS], report["chosen"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--tessera", default=str(ROOT / "build/dev/apps/tessera/tessera"))
    ap.add_argument("--top", type=int, default=5)
    args = ap.parse_args()
    ranked = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, rows, rx in rooms():
            table, chosen = table_of(args.tessera, pathlib.Path(tmp), name, rows, rx)
            distance = sum(abs(table[i][j] - LECTURE[i][j]) for i in range(5) for j in range(3))
            ranked.append((distance, name, chosen, table))
    ranked.sort()
    right = [r for r in ranked if r[2] == "intended position, 15 deg CW"]
    print(f"{len(ranked)} rooms; {len(right)} choose the lecture's pose")
    print("closest of all:")
    for r in ranked[:args.top]:
        print(f"  {r[0]:3d}  {r[1]}  chooses {r[2]}  {r[3]}")
    print("closest that choose the lecture's pose:")
    for r in right[:args.top]:
        print(f"  {r[0]:3d}  {r[1]}  {r[3]}")
    left = min(min(r[3][3][:2]) for r in ranked)
    print(f"lowest S left one cell (intended or CW) in any room: {left} (lecture: 6, 7)")


if __name__ == "__main__":
    main()
