#!/usr/bin/env bash
# Third-party check of --record: `tessera explore` (two lidar robots), `tessera bob`, `tessera
# fusion` (a simulated run in the office, and a teach-and-repeat run) and `tessera slam` (a simulated run) write MCAP files that npm's @mcap/core reads through their summary (chunk
# indexes, statistics, CRCs, seek by time) and whose every message @foxglove/rosmsg2-serialization
# decodes against the ros2msg schema in the file (check_recording.cjs). Then the failures: a run
# that fails on its input (exit 3) and a recording that cannot be created (exit 4) leave no file.
# The npm packages go to a folder outside the source tree. Without npm or the registry the test is
# skipped (exit 77), except with CI=true, where it fails.
# Usage: mcap_recording_test.sh TESSERA_CLI TEST_DIR
set -euo pipefail
cli=$1
here=$2

# shellcheck source=../support/npm_packages.sh
. "$here/../support/npm_packages.sh"
npm_packages "${TMPDIR:-/tmp}/tessera-npm-mcap-record" "@mcap/core@2.2.2" "@foxglove/wasm-zstd@1.0.1" \
  "@foxglove/rosmsg@5.0.5" "@foxglove/rosmsg2-serialization@3.1.0" "@foxglove/crc@1.0.1"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
check() { node "$here/check_recording.cjs" "$@"; }

"$cli" explore --sensor lidar --robots 2 --out "$work/explore" --record "$work/explore.mcap" --quiet
check "$work/explore.mcap" /tf /map /frontier /robot0/path /robot1/path

"$cli" bob --out "$work/bob" --record "$work/bob.mcap" --quiet
check "$work/bob.mcap" /map /tf /path

"$cli" fusion --builtin office --duration-s 20 --out "$work/fusion" --record "$work/fusion.mcap" --quiet
check "$work/fusion.mcap" /tf /path /odometry_path /truth_path /hex_cells /image_nodes

"$cli" fusion --teach-and-repeat --builtin office --route-length-m 4 --seed 4 --out "$work/tr" \
  --record "$work/tr.mcap" --quiet
check "$work/tr.mcap" /tf /path /odometry_path /hex_cells /image_nodes /taught_path /repeated_path /truth_path

"$cli" slam --duration-s 40 --out "$work/slam" --record "$work/rec/slam.mcap" --quiet
check "$work/rec/slam.mcap" /scan /odom /tf /tf_static /map /path

# A run that fails on its input: exit 3 and no recording, not even its temporary.
mkdir -p "$work/bad"
set +e
"$cli" explore --start 1000,1000 --out "$work/bad/out" --record "$work/bad/run.mcap" --quiet 2>"$work/err"
code=$?
set -e
[ "$code" = 3 ] || { echo "FAIL: explore with a start outside the world exited $code, expected 3"; cat "$work/err"; exit 1; }
leftover=$(ls -A "$work/bad")
[ -z "$leftover" ] || { echo "FAIL: the failed run left: $leftover"; exit 1; }

# A recording that cannot be created: exit 4, one line naming it.
touch "$work/file"
set +e
"$cli" explore --out "$work/out2" --record "$work/file/run.mcap" --quiet 2>"$work/err"
code=$?
set -e
[ "$code" = 4 ] || { echo "FAIL: an unwritable --record exited $code, expected 4"; cat "$work/err"; exit 1; }
grep -q "run.mcap\|file" "$work/err" || { echo "FAIL: the error does not name the file:"; cat "$work/err"; exit 1; }
[ "$(wc -l < "$work/err")" = 1 ] || { echo "FAIL: the error is not one line:"; cat "$work/err"; exit 1; }
# --record with a fusion mode that does not record: a usage error.
set +e
"$cli" fusion --pair "$work" --record "$work/pair.mcap" --quiet 2>"$work/err"
code=$?
set -e
[ "$code" = 2 ] || { echo "FAIL: fusion --pair --record exited $code, expected 2"; cat "$work/err"; exit 1; }
[ ! -e "$work/pair.mcap" ] || { echo "FAIL: fusion --pair --record wrote a file"; exit 1; }
echo "PASS"
