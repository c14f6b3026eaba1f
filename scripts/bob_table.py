#!/usr/bin/env python3
"""Runs `tessera bob` on configurations cut from the shared floor plans (rooms and corridors of 50
to 320 robot cells of 0.22 m, closed and open, like BOBMapping's Table 1) plus the built-in
worlds, for both explorer variants, and prints a Table 1 in markdown on stdout.

Every world keeps its own resolution (0.011 to 0.25 m), finer than or out of step with the robot's
0.22 m grid, so obstacles straddle the robot's cells. A configuration is a rectangle (--crop) of a
floor plan; the robot's grid starts at its lower-left corner. "closed" means walls enclose the
space, "open" that the rectangle cuts through free space and its edge bounds the exploration.

usage: scripts/bob_table.py [--tessera build/dev/apps/tessera/tessera] [--noise on|off] [--resense on|off]
                            [--localisation beacons|perfect] [--seed 1] [--out out/bob_table]
"""
import argparse
import json
import os
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
# An empty TESSERA_DATA_DIR counts as unset, as in io/data_dir.hpp.
DATA = pathlib.Path(os.environ.get("TESSERA_DATA_DIR") or ROOT.parent / "shared" / "data")
MAPS = DATA / "maps"

# (label, map file under maps/, extra options, crop X0,Y0,X1,Y1 in metres)
CONFIGS = [
    ("turtlebot3 world, west half (open)", "ros_map_server/turtlebot3_world_humble/map.yaml", [],
     "-2.2,-2.2,0.44,0.66"),
    ("turtlebot3 world, north-east (open)", "ros_map_server/turtlebot3_world_humble/map.yaml", [],
     "-0.22,-0.66,2.42,2.2"),
    ("turtlebot3 sandbox, south (open)", "ros_map_server/nav2_tb3_sandbox/tb3_sandbox.yaml", [],
     "-1.76,-2.2,1.76,0.22"),
    ("Stage simple, one box (open)", "stage_bitmaps/simple.world", [], "-6.2,1.5,-2.46,5.02"),
    ("Stage simple, two boxes (open)", "stage_bitmaps/simple.world", [], "-6.5,-4.0,-3.2,-0.7"),
    ("Stage simple, long box (open)", "stage_bitmaps/simple.world", [], "-2.0,-1.5,1.52,2.02"),
    ("UoA robotics lab, north room (closed)", "stage_bitmaps/uoa_robotics_lab.world", [],
     "-2.4,4.0,0.68,7.74"),
    ("UoA robotics lab, south alcoves (closed)", "stage_bitmaps/uoa_robotics_lab.world", [],
     "-2.9,-7.7,0.18,-4.18"),
    ("HouseExpo, two rooms and a door (closed)", "houseexpo/json/0a1b29dba355df2ab02630133187bfab.json",
     [], "0.05,0.05,3.57,3.57"),
    ("HouseExpo, small room (closed)", "houseexpo/json/0a1b29dba355df2ab02630133187bfab.json", [],
     "5.0,2.2,8.08,5.5"),
    ("Moving AI room-32 at 0.25 m (closed)", "movingai/room-32-32-4.map",
     ["--map-resolution-m", "0.25"], "0.0,0.0,3.3,3.3"),
]
BUILTIN = ["labyrinth", "office"]
VARIANTS = ["trail", "map-aware"]


def run(tessera, world_args, variant, args, out):
    cmd = [tessera, "bob", *world_args, "--variant", variant, "--noise", args.noise,
           "--resense", args.resense,
           "--localisation", args.localisation, "--seed", str(args.seed), "--quiet", "--out",
           str(out)]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit("failed: %s\n%s" % (" ".join(cmd), done.stdout + done.stderr))
    report = json.loads((out / "report.json").read_text())
    row = report["map_accuracy"]
    row.update({"loc_" + k: v for k, v in report["localisation"].items()})
    return row


def table(rows, title):
    head = ("| Map | Cells | Re-sensed | Empty as occupied | Occupied as empty | Success rate | "
            "Strict: E as O / O as E / success | Path (cells) | Turns | Path / cells | C | E | "
            "Path / C | Path / (C + E/2 - 3) | Fixes | Repositionings | Bumps |")
    print("\n### %s\n" % title)
    print(head)
    print("|" + "---|" * (head.count("|") - 1))
    keys = ["cells", "resensed_cells", "empty_as_occupied", "occupied_as_empty",
            "empty_as_occupied_strict", "occupied_as_empty_strict", "path_cells", "turns",
            "free_reachable_c", "loc_fixes", "loc_repositionings", "loc_bumps"]
    tot = dict.fromkeys(keys, 0)
    tot["bound"] = 0.0
    for label, b in rows:
        print("| %s | %d | %d | %d | %d | %.2f%% | %d / %d / %.2f%% | %d | %d | %.0f%% | %d | %d | "
              "%.2f | %.2f | %d | %d | %d |" % (
                  label, b["cells"], b["resensed_cells"], b["empty_as_occupied"],
                  b["occupied_as_empty"], 100 * b["success_rate"], b["empty_as_occupied_strict"],
                  b["occupied_as_empty_strict"], 100 * b["success_rate_strict"], b["path_cells"],
                  b["turns"], 100 * b["path_share"], b["free_reachable_c"], b["boundary_edges_e"],
                  b["path_per_c"], b["path_per_smartdfs_bound"], b["loc_fixes"],
                  b["loc_repositionings"], b["loc_bumps"]))
        for k in keys:
            tot[k] += b[k]
        tot["bound"] += b["free_reachable_c"] + b["boundary_edges_e"] / 2 - 3
    errors = tot["empty_as_occupied"] + tot["occupied_as_empty"]
    strict = tot["empty_as_occupied_strict"] + tot["occupied_as_empty_strict"]
    print("| **Total** | %d | %d | %d | %d | %.2f%% | %d / %d / %.2f%% | %d | %d | %.0f%% | %d | | "
          "%.2f | %.2f | %d | %d | %d |" % (
              tot["cells"], tot["resensed_cells"], tot["empty_as_occupied"],
              tot["occupied_as_empty"], 100 * (tot["cells"] - errors) / tot["cells"],
              tot["empty_as_occupied_strict"], tot["occupied_as_empty_strict"],
              100 * (tot["cells"] - strict) / tot["cells"], tot["path_cells"], tot["turns"],
              100 * tot["path_cells"] / tot["cells"], tot["free_reachable_c"],
              tot["path_cells"] / tot["free_reachable_c"], tot["path_cells"] / tot["bound"],
              tot["loc_fixes"], tot["loc_repositionings"], tot["loc_bumps"]))
    return tot


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tessera", default=str(ROOT / "build" / "dev" / "apps" / "tessera" / "tessera"))
    ap.add_argument("--noise", default="on", choices=["on", "off"])
    ap.add_argument("--resense", default="on", choices=["on", "off"])
    ap.add_argument("--localisation", default="beacons", choices=["beacons", "perfect"])
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--out", default=str(ROOT / "out" / "bob_table"))
    args = ap.parse_args()
    out = pathlib.Path(args.out)

    worlds = []
    for label, name, extra, crop in CONFIGS:
        worlds.append((label, ["--world", str(MAPS / name), *extra, "--crop", crop]))
    for b in BUILTIN:
        worlds.append(("built-in %s (0.05 m)" % b, ["--builtin", b]))

    print("BOBMapping Table 1 from `tessera bob` (noise %s, re-sensing %s, localisation %s, seed %d, "
          "cell 0.22 m)." % (args.noise, args.resense, args.localisation, args.seed))
    for variant in VARIANTS:
        rows = []
        for i, (label, world_args) in enumerate(worlds):
            rows.append((label, run(args.tessera, world_args, variant, args,
                                    out / variant / str(i))))
        table(rows[:len(CONFIGS)], "%s: %d configurations from the shared floor plans"
              % (variant, len(CONFIGS)))
        table(rows[len(CONFIGS):], "%s: built-in worlds" % variant)
        table(rows, "%s: all" % variant)


if __name__ == "__main__":
    main()
