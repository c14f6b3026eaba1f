#!/usr/bin/env python3
"""Issue 14's throughput benchmark: `tessera team` on a world with 1, 3 and 8 robots (each robot a
process, all over Cyclone DDS on this machine), at --rate 1 so that simulated and wall seconds
agree. Prints per robot (mean over the team) the map traffic it sends (its own /rN/map and its
merged /team/map) and its claim traffic (/team/claims), in messages and bytes per second, and the
latency from a scan's receipt to the publication of the first map that holds it (median of the
robots' medians, largest 99th percentile), then the team's coverage and time. Exits 1 when a run
fails.

usage: scripts/team_bench.py [--tessera build/dev/apps/tessera/tessera] [--robots 1 3 8]
                             [--world-args "--builtin office"] [--max-s 300] [--out out/team-bench]
"""
import argparse
import json
import os
import pathlib
import shlex
import statistics
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent


def run_team(args, robots):
    out = pathlib.Path(args.out) / f"robots{robots}"
    domain = 1 + (os.getpid() + robots) % 200
    command = [args.tessera, "team", "--robots", str(robots), "--rate", "1", "--max-s",
               str(args.max_s), "--domain", str(domain), "--out", str(out), "--quiet"]
    command += shlex.split(args.world_args)
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        print(f"robots {robots}: tessera team failed ({done.returncode}): {done.stdout}{done.stderr}",
              file=sys.stderr)
        return None
    return json.loads((out / "report.json").read_text())


def row(robots, report):
    team = report["team"]
    traffic = [r["traffic"] for r in team["robots"] if r.get("traffic")]
    mean = lambda kind, key: statistics.fmean(t[kind][key] for t in traffic)
    latencies = [t["map_latency"] for t in traffic if t.get("map_latency")]
    median = statistics.median(l["median_s"] for l in latencies) if latencies else float("nan")
    p99 = max((l["p99_s"] for l in latencies), default=float("nan"))
    return (f"| {robots} | {mean('maps', 'messages_per_s'):.2f} | {mean('maps', 'bytes_per_s') / 1e3:.1f} | "
            f"{mean('claims', 'messages_per_s'):.3f} | {mean('claims', 'bytes_per_s'):.1f} | "
            f"{1e3 * median:.1f} | {1e3 * p99:.1f} | {100 * team['coverage']:.1f} | "
            f"{team['simulated_s']:.1f} | {report['timing']['wall_s']:.1f} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tessera", default=str(ROOT / "build/dev/apps/tessera/tessera"))
    parser.add_argument("--robots", type=int, nargs="+", default=[1, 3, 8])
    parser.add_argument("--world-args", default="--builtin office")
    parser.add_argument("--max-s", type=float, default=300.0)
    parser.add_argument("--out", default="out/team-bench")
    args = parser.parse_args()
    print("| robots | map msgs/s per robot | map kB/s per robot | claim msgs/s per robot | "
          "claim B/s per robot | scan-to-map latency median (ms) | p99 (ms) | coverage (%) | "
          "simulated s | wall s |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    failed = False
    for robots in args.robots:
        report = run_team(args, robots)
        if report is None:
            failed = True
            continue
        print(row(robots, report), flush=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
