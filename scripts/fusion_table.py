#!/usr/bin/env python3
"""Runs `tessera fusion --teach-and-repeat` (the Fusion SLAM thesis' two-stage experiment, Table 5.1,
in the simulator with the thesis' odometry drift) in the built-in office and three shared floor
plans, for each feature type and several seeds, and writes the Markdown tables of
docs/fusion-teach-and-repeat.md (per run, as the thesis' Tables 5.2-5.4: reached goal cell, final
error in x and y, distance, path ratio, ATE with drift correction vs odometry alone, image-node
search).

With --mapping it runs `tessera fusion --world` instead (one open-loop mapping run start -> goal ->
start per seed, scored against its ground truth) and writes the mapping table.

usage: scripts/fusion_table.py [--tessera build/dev/apps/tessera/tessera] [--seeds 1 2 3]
                               [--runs 1] [--features orb sift akaze] [--out out/fusion-table]
                               [--doc docs/fusion-teach-and-repeat.md] [--mapping]
                               [--appendix] [--drop-frames P] [--photos N]
                               [--candidates cells|whole-map] [--match-gate on|off]
--appendix prints the thesis' Appendix B and C figures of the runs instead (docs/fusion-claims.md);
--drop-frames and --photos test the thesis' claims that the map needs no continuous stream of
images and is not misled by repeated landmarks (issue 18 item 11); --candidates and --match-gate
take the cells or our graph gate away, to see which of the two keeps repeated landmarks out.
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
PHOTOS = DATA / "rgbd" / "rtabmap_loop_samples" / "images"

# (label, arguments naming the world)
WORLDS = [
    ("Built-in office (16 x 12 m)", ["--builtin", "office"]),
    ("Autolab (Stage, 20 x 20 m)", ["--world", str(DATA / "maps/stage_bitmaps/autolab.world")]),
    ("UoA robotics lab (Stage, 6.3 x 15.7 m)",
     ["--world", str(DATA / "maps/stage_bitmaps/uoa_robotics_lab.world")]),
    ("Hospital section, west half (Stage)",
     ["--world", str(DATA / "maps/stage_bitmaps/hospital_section.png"), "--map-resolution-m",
      "0.04", "--crop", "0,0,20,17.72"]),
]

BARS = ("Bars (issue 5): goal cell reached on every run; final error <= 0.1 m; path <= 1.15 x the "
        "shortest path over the learned cells; ATE with drift correction at least 5 x smaller "
        "than odometry alone; image-node search >= 90 %.")


# Extra arguments for every run (--drop-frames) and the poster photo folder (--photos N).
EXTRA = []
TEXTURES = [PHOTOS]
# --keep-going: runs that failed (tessera exit 4, e.g. a drive that never arrives), as
# "world seed: message", listed under the table instead of stopping it.
FAILED = []


def run(tessera, out_root, world, features, seed, runs, reuse, mapping=False, keep_going=False):
    label, args = world
    out = out_root / f"{label.split()[0].lower()}_{features}_{seed}"
    if reuse and (out / "report.json").exists():
        with open(out / "report.json") as f:
            return json.load(f)
    if reuse == "only":
        return None
    mode = [] if mapping else ["--teach-and-repeat", "--runs", str(runs)]
    cmd = [tessera, "fusion", "--quiet"] + mode + ["--features", features, "--seed", str(seed),
                                                   "--textures", str(TEXTURES[0]),
                                                   "--out", str(out)] + args + EXTRA
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode == 4 and keep_going:
        FAILED.append(f"{label} seed {seed}: {proc.stderr.strip()}")
        return None
    if proc.returncode != 0:
        sys.exit(f"{' '.join(cmd)}: exit {proc.returncode}: {proc.stderr.strip()}")
    with open(out / "report.json") as f:
        return json.load(f)


def mapping_table(args, out_root):
    """One row per world, feature type and seed: the ATE with drift correction against odometry's."""
    lines = ["| Features | World | Seed | Driven (m) | Frames used | Nodes | Cells | "
             "Matches acc. / rej. | ATE corrected (m) | ATE odometry (m) | Odometry / corrected |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for features in args.features:
        for world in WORLDS:
            for seed in args.seeds:
                reuse = "only" if args.reuse_only else args.reuse
                report = run(args.tessera, out_root, world, features, seed, 1, reuse, mapping=True)
                if report is None:
                    continue
                f, t = report["fusion"], report["trajectory"]
                lines.append(
                    f"| {features.upper()} | {world[0]} | {seed} | "
                    f"{report['run']['path_length_m']:.1f} | {f['frames_loaded']} | "
                    f"{f['image_nodes']} | {f['cells']} | {f['matches_accepted']} / "
                    f"{f['matches_rejected']} | {t['ate_rmse_m']:.3f} | "
                    f"{t['ate_odometry_rmse_m']:.3f} | {t['ate_ratio']:.1f} |")
    return "\n".join(lines) + "\n"


def appendix_table(args, out_root):
    """Per run, the thesis' Appendix B (image nodes, image nodes in the goal cell, cells, goal cell
    id) and Appendix C (the image-node search's first transform estimate against the odometry
    error when it began), with the per-feature means and standard deviations as the thesis gives
    them."""
    lines = ["| Features | World | Seed | Route (m) | Taught + driven (m) | Image nodes | "
             "In goal cell | Cells | Goal cell id | Search: first offset (m) | "
             "Odometry error at search (m) |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    summary = []
    for features in args.features:
        cols = {"nodes": [], "in_goal": [], "cells": [], "goal_id": []}
        for world in WORLDS:
            for seed in args.seeds:
                reuse = "only" if args.reuse_only else args.reuse
                report = run(args.tessera, out_root, world, features, seed, 1, reuse)
                if report is None:
                    continue
                r = report["teach_and_repeat"]["runs"][0]
                goal_search = r["searches"][-1]
                driven = 2 * r["taught_route_length_m"] + r["navigation_path_m"]
                cols["nodes"].append(r["image_nodes"])
                cols["in_goal"].append(r["goal_cell_image_nodes"])
                cols["cells"].append(r["cells"])
                cols["goal_id"].append(r["goal_cell"])
                lines.append(
                    f"| {features.upper()} | {world[0]} | {seed} | "
                    f"{r['taught_route_length_m']:.2f} | {driven:.1f} | {r['image_nodes']} | "
                    f"{r['goal_cell_image_nodes']} | {r['cells']} | {r['goal_cell']} | "
                    f"{goal_search['first_offset_m']:.3f} | {goal_search['odometry_error_m']:.3f} |")
        def stats(v):
            n = len(v)
            if n == 0:
                return "-"
            mean = sum(v) / n
            sd = (sum((x - mean) ** 2 for x in v) / (n - 1)) ** 0.5 if n > 1 else 0.0
            return f"{mean:.1f} +- {sd:.1f}"
        summary.append(f"| {features.upper()} | {stats(cols['nodes'])} | {stats(cols['in_goal'])} | "
                       f"{stats(cols['cells'])} | {stats(cols['goal_id'])} |")
    lines += ["", "| Features | Image nodes | In goal cell | Cells | Goal cell id |",
              "|---|---|---|---|---|"] + summary
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--tessera", default=str(ROOT / "build/dev/apps/tessera/tessera"))
    ap.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3])
    ap.add_argument("--runs", type=int, default=1, help="runs per seed (same route)")
    ap.add_argument("--features", nargs="+", default=["orb", "sift", "akaze"])
    ap.add_argument("--out", default=str(ROOT / "out/fusion-table"))
    ap.add_argument("--doc", default=None, help="also write the Markdown here")
    ap.add_argument("--reuse", action="store_true",
                    help="read the report.json of runs already in --out instead of running them")
    ap.add_argument("--reuse-only", action="store_true",
                    help="as --reuse, and skip the runs that are not there (no new runs)")
    ap.add_argument("--mapping", action="store_true",
                    help="tessera fusion --world mapping runs instead of teach-and-repeat")
    ap.add_argument("--appendix", action="store_true",
                    help="the thesis' Appendix B and C figures of the teach-and-repeat runs instead")
    ap.add_argument("--drop-frames", type=float, default=0.0,
                    help="lose each frame the SLAM asks for with this probability")
    ap.add_argument("--photos", type=int, default=0,
                    help="hang only the first N photos (repeated posters everywhere)")
    ap.add_argument("--candidates", default="cells", choices=["cells", "whole-map"],
                    help="match candidates from the cells (the thesis) or the whole map")
    ap.add_argument("--match-gate", default="on", choices=["on", "off"],
                    help="refuse matches that disagree with the pose graph (ours) or not")
    ap.add_argument("--keep-going", action="store_true",
                    help="list runs that fail at run time under the table instead of stopping")
    args = ap.parse_args()
    out_root = pathlib.Path(args.out)
    if args.drop_frames > 0.0:
        EXTRA.extend(["--drop-frames", str(args.drop_frames)])
    EXTRA.extend(["--candidates", args.candidates, "--match-gate", args.match_gate])
    if args.photos > 0:  # a folder of links to the first N photos, beside the runs
        few = out_root / f"photos_{args.photos}"
        few.mkdir(parents=True, exist_ok=True)
        for photo in sorted(p for p in PHOTOS.iterdir() if p.is_file())[:args.photos]:
            link = few / photo.name
            if not link.exists():
                link.symlink_to(photo)
        TEXTURES[0] = few
    other_table = appendix_table if args.appendix else mapping_table if args.mapping else None
    if other_table:
        text = other_table(args, out_root)
        print(text, end="")
        if args.doc:
            pathlib.Path(args.doc).write_text(text)
        return

    lines = []
    totals = {}
    for features in args.features:
        lines.append(f"### {features.upper()}")
        lines.append("")
        lines.append("| World | Seed | Run | Route (m) | Reached | Err x (m) | Err y (m) | Err (m) | "
                     "Nav. distance (m) | Path ratio | ATE corrected (m) | ATE odometry (m) | "
                     "Odometry / corrected | Odometry error at goal (m) | Node search | Nodes | "
                     "Cells | Matches acc. / rej. | Wrong matches (max error, m) |")
        lines.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        t = totals.setdefault(features, {"runs": 0, "reached": 0, "max_err": 0.0, "max_ratio": 0.0,
                                         "min_ate": float("inf"), "trials": 0, "found": 0,
                                         "ex": [], "ey": [], "accepted": 0, "wrong": 0,
                                         "max_match_err": 0.0, "ate": []})
        for world in WORLDS:
            for seed in args.seeds:
                reuse = "only" if args.reuse_only else args.reuse
                failed_before = len(FAILED)
                report = run(args.tessera, out_root, world, features, seed, args.runs, reuse,
                             keep_going=args.keep_going)
                if report is None:
                    t["runs"] += args.runs * (len(FAILED) - failed_before)  # none reached
                    continue
                for k, r in enumerate(report["teach_and_repeat"]["runs"]):
                    t["runs"] += 1
                    t["reached"] += int(r["reached_goal_cell"])
                    t["max_err"] = max(t["max_err"], r["final_error_m"])
                    t["max_ratio"] = max(t["max_ratio"], r["path_ratio"])
                    t["min_ate"] = min(t["min_ate"], r["ate_ratio"])
                    t["trials"] += r["search_trials"]
                    t["found"] += r["search_successes"]
                    t["ex"].append(abs(r["final_error_x_m"]))
                    t["ey"].append(abs(r["final_error_y_m"]))
                    t["accepted"] += r["matches_accepted"]
                    t["wrong"] += r["wrong_matches"]
                    t["max_match_err"] = max(t["max_match_err"], r["max_match_error_m"])
                    t["ate"].append(r["ate_corrected_m"])
                    lines.append(
                        f"| {world[0]} | {seed} | {k + 1} | {r['taught_route_length_m']:.2f} | "
                        f"{'yes' if r['reached_goal_cell'] else 'NO'} | "
                        f"{r['final_error_x_m']:+.3f} | {r['final_error_y_m']:+.3f} | "
                        f"{r['final_error_m']:.3f} | {r['navigation_path_m']:.2f} | "
                        f"{r['path_ratio']:.3f} | {r['ate_corrected_m']:.3f} | "
                        f"{r['ate_odometry_m']:.3f} | {r['ate_ratio']:.1f} | "
                        f"{r['odometry_error_at_goal_m']:.2f} | "
                        f"{r['search_successes']}/{r['search_trials']} | {r['image_nodes']} | "
                        f"{r['cells']} | {r['matches_accepted']} / {r['matches_rejected']} | "
                        f"{r['wrong_matches']} ({r['max_match_error_m']:.2f}) |")
        lines.append("")

    lines.append("### Summary per feature type (as the thesis' Table 5.4)")
    lines.append("")
    lines.append("| Features | Runs | Goal cell reached | Mean abs. err x (m) | Mean abs. err y (m) | "
                 "Max final error (m) | Max path ratio | Min odometry / corrected ATE | "
                 "Node search | ATE corrected, mean / max (m) | Matches accepted | Wrong matches "
                 "(max error, m) |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for features, t in totals.items():
        n = max(1, len(t["ex"]))
        share = 100.0 * t["found"] / max(1, t["trials"])
        lines.append(f"| {features.upper()} | {t['runs']} | {t['reached']}/{t['runs']} | "
                     f"{sum(t['ex']) / n:.3f} | {sum(t['ey']) / n:.3f} | {t['max_err']:.3f} | "
                     f"{t['max_ratio']:.3f} | {t['min_ate']:.1f} | {t['found']}/{t['trials']} "
                     f"({share:.0f} %) | {sum(t['ate']) / n:.3f} / {max(t['ate'], default=0.0):.3f} | "
                     f"{t['accepted']} | {t['wrong']} ({t['max_match_err']:.2f}) |")
    lines.append("")
    if FAILED:
        lines.append(f"Failed runs ({len(FAILED)}), not in the table:")
        lines.extend(f"- {f}" for f in FAILED)
        lines.append("")
    lines.append(BARS)
    text = "\n".join(lines) + "\n"
    print(text, end="")
    if args.doc:
        pathlib.Path(args.doc).write_text(text)


if __name__ == "__main__":
    main()
