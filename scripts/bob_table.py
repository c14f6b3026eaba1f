#!/usr/bin/env python3
"""Runs `tessera bob` on ten configurations cut from the shared Moving AI maps (one map cell = one
robot cell of 0.22 m, 50 to 320 cells, closed and open, like BOBMapping's Table 1) plus the built-in
worlds, for both explorer variants, and prints a Table 1 in markdown on stdout.

A closed configuration is the window with a wall ring added round it; an open one is the window
as cut, so the grid's edge bounds the space (the paper's open configurations).

usage: scripts/bob_table.py [--tessera build/dev/apps/tessera/tessera] [--noise on|off]
                            [--seed 1] [--out out/bob_table]
"""
import argparse
import json
import os
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
DATA = pathlib.Path(os.environ.get("TESSERA_DATA_DIR", ROOT.parent / "shared" / "data"))
MOVINGAI = DATA / "maps" / "movingai"

# (label, map file, first column, first row from the top, width, height, closed)
CONFIGS = [
    ("room-32 one room", "room-32-32-4.map", 1, 1, 7, 7, True),
    ("room-32 two rooms", "room-32-32-4.map", 0, 0, 9, 9, False),
    ("room-32 four rooms", "room-32-32-4.map", 1, 1, 11, 11, True),
    ("room-32 block", "room-32-32-4.map", 8, 8, 17, 17, False),
    ("maze-32 corner", "maze-32-32-2.map", 1, 1, 9, 9, True),
    ("maze-32 corridors", "maze-32-32-2.map", 0, 0, 11, 14, False),
    ("maze-32 wing", "maze-32-32-2.map", 16, 4, 14, 16, True),
    ("8room hall", "8room_000.map", 1, 1, 15, 15, True),
    ("8room doors", "8room_000.map", 4, 4, 11, 14, False),
    ("den312d room", "den312d.map", 20, 20, 16, 18, False),
]
BUILTIN = ["labyrinth", "office"]
VARIANTS = ["trail", "map-aware"]


def read_movingai(path):
    lines = path.read_text().splitlines()
    start = lines.index("map") + 1
    return lines[start:]


def write_window(rows, label, x0, y0, w, h, closed, out_dir):
    window = [r[x0:x0 + w] for r in rows[y0:y0 + h]]
    if closed:
        window = ["@" * (w + 2)] + ["@" + r + "@" for r in window] + ["@" * (w + 2)]
    height, width = len(window), len(window[0])
    path = out_dir / (label.replace(" ", "_") + ".map")
    path.write_text("type octile\nheight %d\nwidth %d\nmap\n%s\n" % (height, width,
                                                                   "\n".join(window)))
    return path


def run(tessera, world_args, variant, noise, seed, out):
    cmd = [tessera, "bob", *world_args, "--variant", variant, "--noise", noise, "--seed",
           str(seed), "--quiet", "--out", str(out)]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit("failed: %s\n%s" % (" ".join(cmd), done.stdout + done.stderr))
    return json.loads((out / "report.json").read_text())["bob"]


def table(rows, title):
    head = ("| Map | Cells | Re-sensed | Empty as occupied | Occupied as empty | Success rate | "
            "Path (cells) | Turns | Path / cells | C | E | Path / C | Path / (C + E/2 - 3) |")
    print("\n### %s\n" % title)
    print(head)
    print("|" + "---|" * (head.count("|") - 1))
    tot = dict(cells=0, resensed_cells=0, empty_as_occupied=0, occupied_as_empty=0,
               path_cells=0, turns=0, free_reachable_c=0, bound=0.0)
    for label, b in rows:
        bound = b["free_reachable_c"] + b["boundary_edges_e"] / 2 - 3
        print("| %s | %d | %d | %d | %d | %.2f%% | %d | %d | %.0f%% | %d | %d | %.2f | %.2f |" % (
            label, b["cells"], b["resensed_cells"], b["empty_as_occupied"],
            b["occupied_as_empty"], 100 * b["success_rate"], b["path_cells"], b["turns"],
            100 * b["path_share"], b["free_reachable_c"], b["boundary_edges_e"], b["path_per_c"],
            b["path_per_smartdfs_bound"]))
        for k in tot:
            tot[k] += bound if k == "bound" else b[k]
    errors = tot["empty_as_occupied"] + tot["occupied_as_empty"]
    print("| **Total** | %d | %d | %d | %d | %.2f%% | %d | %d | %.0f%% | %d | | %.2f | %.2f |" % (
        tot["cells"], tot["resensed_cells"], tot["empty_as_occupied"], tot["occupied_as_empty"],
        100 * (tot["cells"] - errors) / tot["cells"], tot["path_cells"], tot["turns"],
        100 * tot["path_cells"] / tot["cells"], tot["free_reachable_c"],
        tot["path_cells"] / tot["free_reachable_c"], tot["path_cells"] / tot["bound"]))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tessera", default=str(ROOT / "build" / "dev" / "apps" / "tessera" / "tessera"))
    ap.add_argument("--noise", default="on", choices=["on", "off"])
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--out", default=str(ROOT / "out" / "bob_table"))
    args = ap.parse_args()
    out = pathlib.Path(args.out)
    (out / "worlds").mkdir(parents=True, exist_ok=True)

    worlds = []
    for label, name, x0, y0, w, h, closed in CONFIGS:
        path = write_window(read_movingai(MOVINGAI / name), label, x0, y0, w, h, closed,
                            out / "worlds")
        kind = "closed" if closed else "open"
        worlds.append(("%s (%s)" % (label, kind),
                       ["--world", str(path), "--map-resolution-m", "0.22"]))
    for b in BUILTIN:
        worlds.append(("builtin %s" % b, ["--builtin", b]))

    print("BOBMapping Table 1 from `tessera bob` (noise %s, seed %d, cell 0.22 m, exact motion, "
          "perfect localisation)." % (args.noise, args.seed))
    for variant in VARIANTS:
        rows = []
        for i, (label, world_args) in enumerate(worlds):
            rows.append((label, run(args.tessera, world_args, variant, args.noise, args.seed,
                                    out / variant / str(i))))
        table(rows[:len(CONFIGS)], "%s: ten configurations from the Moving AI maps" % variant)
        table(rows[len(CONFIGS):], "%s: built-in worlds" % variant)


if __name__ == "__main__":
    main()
