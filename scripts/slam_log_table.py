#!/usr/bin/env python3
"""The real-log SLAM table of docs/slam-results.md (issue 12's protocol): every dev log gets a seeded
drifting odometry from ../shared/tools/perturb_carmen.py (restamped 0.2 s per scan), `tessera slam`
runs on it with its defaults, and ../shared/tools/ate2d.py scores the trajectory and the odometry
against the corrected poses (rigid 2D ATE, m). Prints the Markdown rows and a summary; exits 1 when a
run is worse than its odometry or fails.

usage: scripts/slam_log_table.py [--tessera build/dev/apps/tessera/tessera] [--seeds 1 2 3]
                                 [--drifts 0.15 0.3] [--logs fr079 aces fhw intel] [--jobs 2]
                                 [--out out/slam-logs] [--images DIR]
"""
import argparse
import concurrent.futures
import gzip
import os
import pathlib
import shutil
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
# An empty TESSERA_DATA_DIR counts as unset, as in io/data_dir.hpp.
DATA = pathlib.Path(os.environ.get("TESSERA_DATA_DIR") or ROOT.parent / "shared" / "data")
TOOLS = DATA.parent / "tools"

# name -> (corrected log relative to the data folder, label, peer ATE at seed 1 / 0.15 deg/m:
# GMapping, Cartographer, measured by the author on this machine; the bar at
# 0.15 deg/m: "within 1.5x GMapping's seed-1 figure (at most 0.13 / 0.54 / 0.35 / 0.10 m)" and
# better than Cartographer's)
LOGS = {
    "fr079": ("laser/fr079/freiburg-079-corrected.log", "FR079", 0.088, 0.078, 0.13),
    "aces": ("maps/radish_carmen/aces-corrected.log.gz", "ACES", 0.36, 1.28, 0.54),
    "fhw": ("maps/radish_carmen/fhw-corrected.log.gz", "FHW", 0.23, 12.1, 0.35),
    "intel": ("maps/radish_carmen/intel-corrected.log.gz", "Intel corrected", 0.061, 0.57, 0.10),
}


def plain_log(name, out_root):
    """The corrected log, unzipped once into out_root."""
    rel = LOGS[name][0]
    dst = out_root / f"{name}.log"
    if not dst.exists():
        src = DATA / rel
        tmp = dst.with_suffix(".tmp")
        with (gzip.open(src, "rb") if rel.endswith(".gz") else open(src, "rb")) as f, \
                open(tmp, "wb") as g:
            shutil.copyfileobj(f, g)
        tmp.rename(dst)
    return dst


def ate(est, ref):
    """ate2d.py's RMSE (m) of est against ref (both 't x y theta' files)."""
    out = subprocess.run([sys.executable, str(TOOLS / "ate2d.py"), str(est), str(ref)],
                         capture_output=True, text=True, check=True).stdout.split()
    return float(out[out.index("ate_rmse_m") + 1])


def tum_to_xyt(tum, xyt):
    with open(tum) as f, open(xyt, "w") as g:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            v = line.split()
            g.write(f"{v[0]} {v[1]} {v[2]} 0\n")


def odometry_xyt(log, xyt):
    """The perturbed log's robot poses (the odometry SLAM is given), as 't x y theta'."""
    with open(log) as f, open(xyt, "w") as g:
        for line in f:
            v = line.split()
            if not v or v[0] != "FLASER":
                continue
            p = 2 + int(v[1])
            g.write(f"{v[p + 6]} {v[p + 3]} {v[p + 4]} {v[p + 5]}\n")


def run_one(tessera, slam_args, out_root, name, seed, drift):
    case = out_root / f"{name}_d{drift}_s{seed}"
    case.mkdir(parents=True, exist_ok=True)
    log, truth = case / "input.log", case / "truth.xyt"
    subprocess.run([sys.executable, str(TOOLS / "perturb_carmen.py"), str(plain_log(name, out_root)),
                    str(log), "--seed", str(seed), "--restamp", "0.2", "--drift-deg-per-m",
                    str(drift), "--truth", str(truth)], check=True)
    odometry_xyt(log, case / "odometry.xyt")
    t0 = time.monotonic()
    proc = subprocess.run([tessera, "slam", "--quiet", "--log", str(log), "--out",
                           str(case / "slam")] + slam_args, capture_output=True, text=True)
    wall_s = time.monotonic() - t0
    if proc.returncode != 0:
        return dict(name=name, seed=seed, drift=drift, error=proc.stderr.strip())
    tum_to_xyt(case / "slam" / "trajectory.txt", case / "slam.xyt")
    return dict(name=name, seed=seed, drift=drift, wall_s=wall_s, case=case,
                odometry=ate(case / "odometry.xyt", truth), slam=ate(case / "slam.xyt", truth))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--tessera", default=str(ROOT / "build/dev/apps/tessera/tessera"))
    ap.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3])
    ap.add_argument("--drifts", type=float, nargs="+", default=[0.15, 0.3])
    ap.add_argument("--logs", nargs="+", default=list(LOGS), choices=list(LOGS))
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--out", default=str(ROOT / "out/slam-logs"))
    ap.add_argument("--images", help="copy each log's first-seed map here")
    ap.add_argument("--slam-args", default="",
                    help="more options for every tessera slam run, e.g. '--manhattan'")
    ap.add_argument("--check-bar", action="store_true",
                    help="also fail (exit 1) when a run is over the issue's bar")
    args = ap.parse_args()
    missing = [n for n in args.logs if not (DATA / LOGS[n][0]).exists()]
    if missing:
        print(f"missing data: {', '.join(str(DATA / LOGS[n][0]) for n in missing)}", file=sys.stderr)
        # ctest reads 77 as skipped; with CI=true a missing dataset is a failure.
        return 1 if os.environ.get("CI") == "true" else 77
    out_root = pathlib.Path(args.out)
    out_root.mkdir(parents=True, exist_ok=True)
    for name in args.logs:
        plain_log(name, out_root)

    t0 = time.monotonic()
    cases = [(n, s, d) for n in args.logs for d in args.drifts for s in args.seeds]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(
            lambda c: run_one(args.tessera, args.slam_args.split(), out_root, *c), cases))
    total_s = time.monotonic() - t0

    print("| Log | Drift (deg/m) | Seed | ATE odometry (m) | ATE tessera (m) | Odometry / tessera "
          "| Bar (m) | GMapping seed 1 (m) | Cartographer seed 1 (m) | Wall (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    failures = 0
    for r in results:
        label, gmapping, cartographer, within = LOGS[r["name"]][1:]
        if "error" in r:
            failures += 1
            print(f"| {label} | {r['drift']} | {r['seed']} | run failed: {r['error']} |")
            continue
        # The bar: at most its figure and below Cartographer's at 0.15 deg/m; at most
        # twice that at 0.3 deg/m.
        bar = min(within, cartographer) * (2.0 if r["drift"] > 0.2 else 1.0)
        ok = r["slam"] <= bar and r["slam"] < r["odometry"]
        failures += 0 if (ok if args.check_bar else r["slam"] < r["odometry"]) else 1
        mark = "" if ok else " (over)"
        print(f"| {label} | {r['drift']} | {r['seed']} | {r['odometry']:.3f} | {r['slam']:.3f}{mark} "
              f"| {r['odometry'] / max(r['slam'], 1e-9):.1f} | {bar:.3f} | {gmapping} | "
              f"{cartographer} | {r['wall_s']:.1f} |")
        if args.images and r["seed"] == args.seeds[0]:
            dst = pathlib.Path(args.images)
            dst.mkdir(parents=True, exist_ok=True)
            shutil.copy(r["case"] / "slam" / "map.png", dst / f"slam-log-{r['name']}-d{r['drift']}.png")
    print(f"\n{len(results)} runs in {total_s:.0f} s ({args.jobs} at a time); "
          f"{failures} failed, worse than odometry{' or over the bar' if args.check_bar else ''}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
