#!/usr/bin/env python3
"""The obstacle course of the Fusion SLAM thesis' chapter 5 (issue 18 item 9): `tessera fusion
--teach-and-repeat` in the built-in office and three shared floor plans (the worlds of
scripts/fusion_table.py), seeds 1-3, ORB, with boxes put on the taught route before the repeat stage
and the reactive avoidance in the navigation loop. For each world and seed it runs our navigation
(cell polyline + pure pursuit) and the thesis' (re-decide the best neighbour at every border), both
without and with the boxes (and, with --configs 4, ours with the thesis' own avoidance rule); it
prints the Markdown table of docs/fusion-navigation.md ("The obstacle course") and, with --images,
copies the hex-map pictures of the office's runs of ours with boxes that reached the goal.

usage: scripts/obstacle_course_table.py [--tessera build/dev/apps/tessera/tessera] [--seeds 1 2 3]
                                        [--obstacles 2] [--jobs 2] [--out out/obstacle-course]
                                        [--images docs/images] [--worlds N] [--configs K ...]
                                        [--check]
--worlds N and --configs K (indices into CONFIGS) run a part of the table (the ctest smoke: the
office, seed 2, ours with boxes); --check exits 1 unless every run of ours with boxes reached the
goal cell. Exits 77 (skip) when the photos are missing, or 1 when CI=true.
"""
import argparse
import concurrent.futures
import json
import os
import pathlib
import shutil
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from fusion_table import PHOTOS, ROOT, WORLDS  # noqa: E402

# (label, navigation, obstacles?, avoidance)
CONFIGS = [
    ("ours, no boxes", "ours", False, "strip"),
    ("thesis, no boxes", "thesis", False, "strip"),
    ("ours, boxes", "ours", True, "strip"),
    ("thesis, boxes", "thesis", True, "strip"),
    ("ours, boxes, thesis' avoidance rule", "ours", True, "thesis"),
]


def run(tessera, out_root, world, seed, config, obstacles, reuse=False):
    label, args = world
    name, navigation, boxes, avoidance = config
    out = out_root / f"{label.split()[0].lower()}_{seed}_{navigation}_{int(boxes)}_{avoidance}"
    if reuse and (out / "report.json").exists():
        with open(out / "report.json") as f:
            return out, json.load(f)["teach_and_repeat"]["runs"][0]
    cmd = [tessera, "fusion", "--quiet", "--teach-and-repeat", "--features", "orb", "--seed",
           str(seed), "--textures", str(PHOTOS), "--out", str(out), "--navigation", navigation,
           "--obstacles", str(obstacles if boxes else 0), "--avoidance", avoidance] + args
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        # A run that fails (a drive over its time limit) is a row too: the table says so.
        return out, {"error": proc.stderr.strip().splitlines()[-1] if proc.stderr else "failed"}
    with open(out / "report.json") as f:
        return out, json.load(f)["teach_and_repeat"]["runs"][0]


def row(world, seed, config, r):
    head = f"| {world[0]} | {seed} | {config[0]} |"
    if "error" in r:
        return head + f" **no**: {r['error']} | | | | | | | |"
    course = r.get("obstacle_course", {})
    return (head + f" {'yes' if r['reached_goal_cell'] else '**no**'} | "
            f"{r['navigation_path_m']:.2f} | {r['navigation_time_s']:.1f} | "
            f"{r['heading_reversals']} | {course.get('avoidance_updates', '-')} | "
            f"{course.get('detours', '-')} | "
            f"{course.get('bumper_hits', '-')} | {course.get('blocked_steps', '-')} | "
            f"{r['final_error_m']:.3f} |")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--tessera", default=str(ROOT / "build/dev/apps/tessera/tessera"))
    ap.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3])
    ap.add_argument("--obstacles", type=int, default=2)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--out", default=str(ROOT / "out/obstacle-course"))
    ap.add_argument("--images", help="copy seed 1's office pictures here")
    ap.add_argument("--worlds", type=int, default=len(WORLDS), help="the first N worlds only")
    ap.add_argument("--configs", type=int, nargs="+", default=[0, 1, 2, 3])
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--reuse", action="store_true",
                    help="read the report.json of runs already in --out (failed runs have none and run "
                         "again)")
    args = ap.parse_args()
    if not PHOTOS.is_dir():
        print(f"{PHOTOS}: missing (the poster photos)", file=sys.stderr)
        sys.exit(1 if os.environ.get("CI") == "true" else 77)
    out_root = pathlib.Path(args.out)
    configs = [CONFIGS[k] for k in args.configs]
    jobs = [(w, s, c) for w in WORLDS[:args.worlds] for s in args.seeds for c in configs]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(
            lambda j: run(args.tessera, out_root, j[0], j[1], j[2], args.obstacles, args.reuse),
            jobs))
    print("| World | Seed | Navigation | Reached | Distance (m) | Time (s) | Heading reversals | "
          "Avoidance updates | Detours | Bumper hits | Blocked steps | Final error (m) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for (w, s, c), (_, r) in zip(jobs, results):
        print(row(w, s, c, r))
    print()
    for name, *_ in configs:
        rows = [r for (w, s, c), (_, r) in zip(jobs, results) if c[0] == name]
        ok = [r for r in rows if "error" not in r]
        reached = sum(1 for r in ok if r["reached_goal_cell"])
        rev = [r["heading_reversals"] for r in ok]
        mean = sum(rev) / len(rev) if rev else float("nan")
        print(f"- {name}: goal cell reached {reached}/{len(rows)}, heading reversals "
              f"{min(rev, default=0)}-{max(rev, default=0)} (mean {mean:.1f})")
    if args.images:  # the office's runs of ours with boxes that got through
        dest = pathlib.Path(args.images)
        dest.mkdir(parents=True, exist_ok=True)
        for (w, s, c), (out, r) in zip(jobs, results):
            if w is WORLDS[0] and c == CONFIGS[2] and "error" not in r:
                shutil.copy(out / "hex_map_run1.png", dest / f"obstacle_course_office_seed{s}.png")
    if args.check:
        ours = [r for (w, s, c), (_, r) in zip(jobs, results) if c[1] == "ours" and c[2]
                and c[3] == "strip"]
        if not all("error" not in r and r["reached_goal_cell"] for r in ours):
            sys.exit("obstacle course: a run of ours with boxes did not reach the goal cell")


if __name__ == "__main__":
    main()
