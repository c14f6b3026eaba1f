#!/usr/bin/env bash
# Third-party check of tessera's MCAP reader: converts the two real rosbag2 sqlite3 bags to MCAP
# with @mcap/core's writer (npm; zstd chunks from @foxglove/wasm-zstd for one bag, uncompressed
# chunks for the other; sql.js reads the .db3), then checks that `tessera info` lists the same
# topics, types, counts and first/last stamps for the MCAP file as for the sqlite original, and
# that `tessera slam --bag` gives the same trajectory from both (the same scans, first to last,
# with the same stamps and odometry).
# The npm packages go to a folder outside the source tree. Without npm or the registry the test
# is skipped (exit 77), except with CI=true, where it fails.
# Usage: mcap_thirdparty_test.sh TESSERA_CLI SOURCE_DIR DEFAULT_DATA_DIR
set -euo pipefail
cli=$1
src=$2
data=${TESSERA_DATA_DIR:-$3}

# shellcheck source=../../support/npm_packages.sh
. "$src/tests/support/npm_packages.sh"

bags=(ros2_neato_finite_state_controller ros2_neato_obstacle_avoider)
for b in "${bags[@]}"; do
  [ -d "$data/bags/$b" ] || skip "dataset missing: $data/bags/$b (set TESSERA_DATA_DIR)"
done
npm_packages "${TMPDIR:-/tmp}/tessera-npm-mcap-check" "@mcap/core@2.2.2" "sql.js@1.17.0" \
  "@foxglove/wasm-zstd@1.0.1"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0
compressions=(zstd none)
for i in "${!bags[@]}"; do
  b=${bags[$i]}
  folder="$data/bags/$b"
  db3=$(ls "$folder"/*.db3 | head -n 1)
  mcap="$work/$b.mcap"
  node "$src/tests/io/mcap_thirdparty/sqlite_to_mcap.cjs" \
    "$db3" "$mcap" "${compressions[$i]}"
  "$cli" info --json "$folder" > "$work/sqlite.json"
  "$cli" info --json "$mcap" > "$work/mcap.json"
  # Same topics (name, type, serialization, count, first and last log time) in either order.
  if node -e '
    const fs = require("fs");
    const key = (f) => JSON.parse(fs.readFileSync(f)).topics
      .map((t) => [t.name, t.type, t.serialization, t.message_count, t.first_s, t.last_s].join(" "))
      .sort().join("\n");
    const a = key(process.argv[1]), b = key(process.argv[2]);
    if (a !== b) { console.error("sqlite:\n" + a + "\nmcap:\n" + b); process.exit(1); }
    if (!a.includes("/scan sensor_msgs/msg/LaserScan cdr")) process.exit(1);
  ' "$work/sqlite.json" "$work/mcap.json"; then
    echo "$b: tessera info lists the same topics, types, counts and stamps for the MCAP file"
  else
    echo "FAIL $b: tessera info differs between the sqlite bag and its MCAP conversion"
    failed=$((failed + 1))
    continue
  fi
  "$cli" slam --bag "$folder" --scan-topic /scan --no-loop-closure --quiet --out "$work/a"
  "$cli" slam --bag "$mcap" --scan-topic /scan --no-loop-closure --quiet --out "$work/b"
  if cmp -s "$work/a/trajectory.txt" "$work/b/trajectory.txt" &&
    [ "$(grep -c . "$work/a/trajectory.txt")" -gt 100 ]; then
    echo "$b: the same trajectory from both, scan for scan"
    passed=$((passed + 1))
  else
    echo "FAIL $b: slam --bag reads different scans from the MCAP conversion"
    failed=$((failed + 1))
  fi
  rm -rf "$work/a" "$work/b"
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
