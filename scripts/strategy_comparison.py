#!/usr/bin/env python3
"""Issue 18 item 8 (lecture: "priority might be more efficient"): nearest (Algo 9.1) against the
a/d priority rule on every shared map, from the "Every run" tables of docs/exploration-results.md
(scripts/explore_table.py writes them). Prints, per sensor and team size, how often each rule has
the shorter summed path and the fewer steps to 99 % coverage (a difference under 1 % is a tie),
the medians of priority's change, and the maps where either rule wins by more than 10 %.

usage: scripts/strategy_comparison.py [docs/exploration-results.md]
"""
import pathlib
import statistics
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent


def runs(text):
    out = {}
    for section in text.split("\n## "):
        sensor = ("cells" if section.startswith("The lecture's cell robot")
                  else "lidar" if section.startswith("The lidar robot") else None)
        if sensor is None or "### Every run" not in section:
            continue
        for line in section.split("### Every run")[1].splitlines():
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if len(cells) < 15 or cells[0] in ("group", "---"):
                continue
            group, name, _, strategy, robots = cells[:5]
            out[(sensor, group, name, int(robots), strategy)] = {
                "path": float(cells[6]), "turns": int(cells[8]), "s99": int(cells[11])}
    return out


def change(a, b):
    return 100.0 * (b - a) / max(a, 1e-9)


def main():
    doc = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "docs" / "exploration-results.md"
    table = runs(doc.read_text(encoding="utf-8"))
    print("| sensor | robots | maps | shorter path: priority / nearest / tie | fewer steps to 99 %: "
          "priority / nearest / tie | median change with priority: path, steps to 99 %, turns |")
    print("|---|---:|---:|---|---|---|")
    big = []
    for sensor in ("cells", "lidar"):
        for robots in (1, 2, 4):
            rows = []
            for (s, group, name, r, strategy), near in table.items():
                if s != sensor or r != robots or strategy != "nearest":
                    continue
                prio = table.get((s, group, name, r, "priority"))
                if prio is None:
                    continue
                rows.append((group, name, change(near["path"], prio["path"]),
                             change(near["s99"], prio["s99"]), change(near["turns"], prio["turns"])))
                if abs(rows[-1][2]) > 10:
                    big.append((sensor, robots, group, name, rows[-1][2], rows[-1][3]))
            def split(k):
                p = sum(1 for x in rows if x[k] < -1)
                n = sum(1 for x in rows if x[k] > 1)
                return f"{p} / {n} / {len(rows) - p - n}"
            print(f"| {sensor} | {robots} | {len(rows)} | {split(2)} | {split(3)} | "
                  f"{statistics.median(x[2] for x in rows):+.1f} %, "
                  f"{statistics.median(x[3] for x in rows):+.1f} %, "
                  f"{statistics.median(x[4] for x in rows):+.1f} % |")
    print()
    print("Path differences over 10 % (priority against nearest; negative: priority shorter):")
    print()
    print("| sensor | robots | group | map | path | steps to 99 % |")
    print("|---|---:|---|---|---:|---:|")
    for sensor, robots, group, name, dp, ds in sorted(big, key=lambda x: (x[0], x[1], x[4])):
        print(f"| {sensor} | {robots} | {group} | {name} | {dp:+.1f} % | {ds:+.1f} % |")


if __name__ == "__main__":
    main()
