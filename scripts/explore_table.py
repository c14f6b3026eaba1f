#!/usr/bin/env python3
"""Runs `tessera explore` on every shared floor plan for both strategies and 1, 2 and 4 robots and
writes the results table to docs/exploration-results.md (figures measured on this machine).

usage: scripts/explore_table.py [--tessera build/dev/apps/tessera/tessera] [--sensor cells]
                                [--jobs 2] [--out out/table]
"""
import argparse
import concurrent.futures
import json
import os
import pathlib
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
# An empty TESSERA_DATA_DIR counts as unset, as in io/data_dir.hpp.
DATA = pathlib.Path(os.environ.get("TESSERA_DATA_DIR") or ROOT.parent / "shared" / "data")

# (group, label, path relative to the data dir, extra arguments)
MAPS = [
    ("ROS map_server", "tb3_sandbox", "maps/ros_map_server/nav2_tb3_sandbox/tb3_sandbox.yaml", []),
    ("ROS map_server", "turtlebot3_world", "maps/ros_map_server/turtlebot3_world_humble/map.yaml", []),
    ("ROS map_server", "warehouse", "maps/ros_map_server/nav2_warehouse/warehouse.yaml", []),
    ("ROS map_server", "willow-full (0.1 m)", "maps/ros_map_server/willow_navigation_tutorials/willow-full.pgm",
     ["--map-resolution-m", "0.1"]),
    ("ROS map_server", "willow-full-0.05", "maps/ros_map_server/willow_navigation_tutorials/willow-full-0.05.pgm",
     ["--map-resolution-m", "0.05"]),
    ("ROS map_server", "explore_bench corridor", "maps/explore_bench/corridor.yaml", []),
    ("ROS map_server", "explore_bench loop", "maps/explore_bench/loop.yaml", []),
    ("ROS map_server", "explore_bench room", "maps/explore_bench/room.yaml", []),
    ("Stage", "willow (stage_ros)", "maps/ros_map_server/willow_stage_ros/willow-erratic.world", []),
    ("Stage", "cave", "maps/stage_bitmaps/simple.world", []),
    ("Stage", "hospital_section", "maps/stage_bitmaps/everything.world", []),
    ("Stage", "autolab", "maps/stage_bitmaps/autolab.world", []),
    ("Stage", "uoa_robotics_lab", "maps/stage_bitmaps/uoa_robotics_lab.world", []),
    ("Stage", "simple_rooms (0.05 m assumed)", "maps/stage_bitmaps/simple_rooms.png",
     ["--map-resolution-m", "0.05"]),
    ("Moving AI", "room-32-32-4", "maps/movingai/room-32-32-4.map", []),
    ("Moving AI", "room-64-64-8", "maps/movingai/room-64-64-8.map", []),
    ("Moving AI", "8room_000", "maps/movingai/8room_000.map", []),
    ("Moving AI", "maze-32-32-2", "maps/movingai/maze-32-32-2.map", []),
    ("Moving AI", "maze-128-128-2", "maps/movingai/maze-128-128-2.map", []),
    ("HouseExpo", "0a1b29db (JSON)", "maps/houseexpo/json/0a1b29dba355df2ab02630133187bfab.json", []),
]
for png in sorted((DATA / "maps/houseexpo/png").glob("*.png")):
    MAPS.append(("HouseExpo", png.stem[:8] + " (PNG)", str(png.relative_to(DATA)),
                 ["--map-resolution-m", "0.01"]))

CONFIGS = [(s, r) for s in ("nearest", "priority") for r in (1, 2, 4)]


def run(tessera, sensor, out_root, entry, strategy, robots):
    group, label, rel, extra = entry
    out = out_root / f"{label.split()[0]}_{sensor}_{strategy}_{robots}"
    cmd = [tessera, "explore", "--quiet", "--world", str(DATA / rel), "--sensor", sensor,
           "--strategy", strategy, "--robots", str(robots), "--out", str(out)] + extra
    t0 = time.time()
    proc = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.time() - t0
    if proc.returncode != 0:
        return entry, strategy, robots, None, proc.stderr.strip() or proc.stdout.strip(), wall
    with open(out / "report.json") as f:
        return entry, strategy, robots, json.load(f), "", wall


def fmt_opt(v, spec):
    return "-" if v is None else format(v, spec)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--tessera", default=str(ROOT / "build/dev/apps/tessera/tessera"))
    ap.add_argument("--sensor", default="cells")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--out", default=str(ROOT / "out/table"))
    ap.add_argument("--doc", default=None, help="markdown file to write (default: print)")
    args = ap.parse_args()
    out_root = pathlib.Path(args.out)
    jobs = [(e, s, r) for e in MAPS for (s, r) in CONFIGS]
    results = {}
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = [pool.submit(run, args.tessera, args.sensor, out_root, e, s, r) for e, s, r in jobs]
        for i, fut in enumerate(concurrent.futures.as_completed(futures)):
            entry, s, r, rep, err, wall = fut.result()
            results[(entry[1], s, r)] = (rep, err, wall)
            print(f"[{i + 1}/{len(jobs)}] {entry[1]} {s} x{r}: "
                  + (f"{rep['exploration']['coverage']:.4f}" if rep else "FAILED " + err),
                  file=sys.stderr)

    lines = [f"| group | map | cells (reachable free) | strategy | robots | coverage | path m | "
             f"path cells | turns | steps | steps to 90% | steps to 99% | occupied-as-empty | "
             f"success rate | wall s |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    worst = 1.0
    worst_oae = 0
    failures = []
    for e in MAPS:
        for s, r in CONFIGS:
            rep, err, wall = results[(e[1], s, r)]
            if rep is None:
                failures.append(f"{e[1]} {s} x{r}: {err}")
                lines.append(f"| {e[0]} | {e[1]} | - | {s} | {r} | FAILED | | | | | | | | | |")
                continue
            x, a, w = rep["exploration"], rep["map_accuracy"], rep["world"]
            worst = min(worst, x["coverage"])
            worst_oae = max(worst_oae, a["occupied_as_empty"])
            lines.append(
                f"| {e[0]} | {e[1]} | {w['width_cells']}x{w['height_cells']} @ {w['resolution_m']:g} m "
                f"({w['reachable_free_cells']}) | {s} | {r} | {100 * x['coverage']:.2f}% | "
                f"{x['path_length_m']:.1f} | {x['path_length_cells']} | {x['turns']} | {x['steps']} | "
                f"{fmt_opt(x['steps_to_90'], 'd')} | {fmt_opt(x['steps_to_99'], 'd')} | "
                f"{a['occupied_as_empty']} | {100 * a['success_rate']:.3f}% | {wall:.1f} |")
    summary = (f"{len(jobs)} runs, sensor `{args.sensor}`: lowest coverage {100 * worst:.2f}%, "
               f"largest occupied-as-empty count {worst_oae}, failures {len(failures)}.")
    # One row per map: the worst of its six runs, and the single nearest-frontier robot's figures.
    per_map = ["| group | map | grid (reachable free cells) | lowest coverage of 6 runs | "
               "most occupied-as-empty | 1 robot nearest: coverage | path m | turns | "
               "steps to 90% | steps to 99% | 1 robot priority: path m | steps to 99% | "
               "4 robots nearest: steps to 99% |",
               "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for e in MAPS:
        reps = [results[(e[1], s, r)][0] for s, r in CONFIGS]
        if any(rep is None for rep in reps):
            per_map.append(f"| {e[0]} | {e[1]} | FAILED | | | | | | | | | | |")
            continue
        by = {(s, r): results[(e[1], s, r)][0] for s, r in CONFIGS}
        n1, p1, n4 = by[("nearest", 1)], by[("priority", 1)], by[("nearest", 4)]
        w = n1["world"]
        x = n1["exploration"]
        per_map.append(
            f"| {e[0]} | {e[1]} | {w['width_cells']}x{w['height_cells']} @ {w['resolution_m']:g} m "
            f"({w['reachable_free_cells']}) | "
            f"{100 * min(r['exploration']['coverage'] for r in reps):.2f}% | "
            f"{max(r['map_accuracy']['occupied_as_empty'] for r in reps)} | "
            f"{100 * x['coverage']:.2f}% | {x['path_length_m']:.1f} | {x['turns']} | "
            f"{fmt_opt(x['steps_to_90'], 'd')} | {fmt_opt(x['steps_to_99'], 'd')} | "
            f"{p1['exploration']['path_length_m']:.1f} | "
            f"{fmt_opt(p1['exploration']['steps_to_99'], 'd')} | "
            f"{fmt_opt(n4['exploration']['steps_to_99'], 'd')} |")
    text = "\n".join([summary, "", "### One row per map", ""] + per_map +
                     ["", "### Every run", ""] + lines + [""] +
                     [f"- FAILED {f}" for f in failures]) + "\n"
    if args.doc:
        pathlib.Path(args.doc).write_text(text)
    print(text)
    return 0 if not failures else 1


if __name__ == "__main__":
    sys.exit(main())
