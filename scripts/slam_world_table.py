#!/usr/bin/env python3
"""Runs `tessera slam --world` (a simulated lidar run with odometry noise, scored against its ground
truth) on three shared floor plans for several seeds, and prints the Markdown table recorded in
docs/slam-results.md: ATE with SLAM, without loop closure and with odometry alone, and the map's
occupied-as-empty share.

usage: scripts/slam_world_table.py [--tessera build/dev/apps/tessera/tessera] [--seeds 1 2 3]
                                   [--out out/slam-worlds]
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

# (label, path relative to the data dir, extra arguments)
WORLDS = [
    ("Autolab (Stage, 20 x 20 m)", "maps/stage_bitmaps/autolab.world", []),
    ("Hospital section, west half (Stage)", "maps/stage_bitmaps/hospital_section.png",
     ["--map-resolution-m", "0.04", "--crop", "0,0,20,17.72"]),
    ("Brain Corp office (0.03 m)", "maps/braincorp/vw_ground_truth_full_edited.png",
     ["--map-resolution-m", "0.03", "--duration-s", "450"]),
]


def run(tessera, out_root, world, seed):
    label, rel, extra = world
    out = out_root / f"{pathlib.Path(rel).stem}_{seed}"
    cmd = [tessera, "slam", "--quiet", "--world", str(DATA / rel), "--seed", str(seed),
           "--out", str(out)] + extra
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"{' '.join(cmd)}: exit {proc.returncode}: {proc.stderr.strip()}")
    with open(out / "report.json") as f:
        return json.load(f)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--tessera", default=str(ROOT / "build/dev/apps/tessera/tessera"))
    ap.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3])
    ap.add_argument("--out", default=str(ROOT / "out/slam-worlds"))
    args = ap.parse_args()
    out_root = pathlib.Path(args.out)

    print("| World | Seed | Cell (m) | Drive (m, s) | Loop closures | ATE SLAM (m) | ATE no loop "
          "closure (m) | ATE odometry (m) | Odometry / SLAM | Occupied cells seen | Occupied as "
          "empty | Share | Real time |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    worst_ratio, worst_share = float("inf"), 0.0
    for world in WORLDS:
        for seed in args.seeds:
            r = run(args.tessera, out_root, world, seed)
            ate, m, sim = r["ate"], r["map_accuracy"], r["simulation"]
            worst_ratio = min(worst_ratio, ate["odometry_over_slam"])
            worst_share = max(worst_share, m["occupied_as_empty_share"])
            print(f"| {world[0]} | {seed} | {r['options']['map_resolution_m']:.3g} | "
                  f"{sim['path_length_m']:.0f}, {sim['duration_s']:.0f} | "
                  f"{r['slam']['loop_closures']} | {ate['slam_rmse_m']:.4f} | "
                  f"{ate['local_slam_rmse_m']:.4f} | {ate['odometry_rmse_m']:.3f} | "
                  f"{ate['odometry_over_slam']:.1f}x | {m['occupied_compared']} | "
                  f"{m['occupied_as_empty']} | {100 * m['occupied_as_empty_share']:.2f} % | "
                  f"{r['timing']['realtime_factor']:.0f}x |", flush=True)
    print(f"\nSmallest odometry / SLAM ATE ratio: {worst_ratio:.1f}x (bar: at least 5x); largest "
          f"occupied-as-empty share: {100 * worst_share:.2f} % (bar: under 0.5 %).")


if __name__ == "__main__":
    main()
