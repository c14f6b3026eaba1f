#!/usr/bin/env bash
# Third-party checks of --serve (issue 15): npm's @foxglove/ws-protocol client decodes a map while
# `tessera explore` runs (ws_client_check.cjs), and headless Chromium opens the live page of an
# explore, a SLAM, a BOB and a Fusion SLAM run and checks the drawing (page_check.cjs). Every tessera process
# listens on 127.0.0.1 on a port the system picks (--serve 0; the port is read from its first
# line) and is stopped when the test ends, however it ends. The npm packages go to a folder
# outside the source tree. Without node/npm/chromium or the registry the test is skipped
# (exit 77), except with CI=true, where it fails.
# Usage: live_view_test.sh TESSERA_CLI TEST_DIR [SCREENSHOT_DIR]
set -euo pipefail
cli=$1
here=$2
shots=${3:-}

# shellcheck source=../support/npm_packages.sh
. "$here/../support/npm_packages.sh"
chromium=$(command -v chromium || true)
[ -n "$chromium" ] || skip "chromium is not installed"
npm_packages "${TMPDIR:-/tmp}/tessera-npm-live" "@foxglove/ws-protocol@0.8.0" "ws@8.18.0" \
  "@foxglove/rosmsg@5.0.5" "@foxglove/rosmsg2-serialization@3.1.0" "puppeteer-core@24.10.0"

work=$(mktemp -d)
pids=()
cleanup() {
  local p
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  for p in "${pids[@]}"; do wait "$p" 2>/dev/null || true; done
  rm -rf "$work"
}
trap cleanup EXIT
node_run() { node "$@"; }

# start NAME ARGS...: runs `tessera ARGS --serve 0 --quiet` in the background; sets $port.
start() {
  local name=$1
  shift
  # The files exist before the program starts: the background child opens them only when it
  # runs, and a sed that finds none would end the script (set -e) on a busy machine.
  : > "$work/$name.out"
  : > "$work/$name.err"
  "$cli" "$@" --serve 0 --quiet > "$work/$name.out" 2> "$work/$name.err" &
  pids+=($!)
  port=""
  for _ in $(seq 1 200); do
    port=$(sed -n 's|^live view: http://127\.0\.0\.1:\([0-9]*\)/.*|\1|p' "$work/$name.out")
    [ -n "$port" ] && return 0
    kill -0 "${pids[-1]}" 2>/dev/null || break
    sleep 0.05
  done
  echo "FAIL: $name: no live view address printed"; cat "$work/$name.err"; exit 1
}

# The Foxglove client, connected while the run goes on (20 ms per step keeps it going ~10 s).
start ws explore --sensor lidar --robots 3 --out "$work/ws" --step-delay-ms 20 --serve-linger 30
node_run "$here/ws_client_check.cjs" "$port" 60
kill "${pids[-1]}"

# The page, for each kind of run; it must see the run finish.
shot() { if [ -n "$shots" ]; then echo "$shots/$1"; else echo "$work/$1"; fi; }
start explore explore --sensor lidar --robots 3 --out "$work/explore" --step-delay-ms 20 --serve-linger 120
node_run "$here/page_check.cjs" "$chromium" "$port" explore "$(shot live-explore.png)" 120
kill "${pids[-1]}"

start slam slam --duration-s 60 --out "$work/slam" --step-delay-ms 2 --serve-linger 120
node_run "$here/page_check.cjs" "$chromium" "$port" slam "$(shot live-slam.png)" 120
kill "${pids[-1]}"

start bob bob --out "$work/bob" --step-delay-ms 5 --serve-linger 120
node_run "$here/page_check.cjs" "$chromium" "$port" bob "$(shot live-bob.png)" 120
kill "${pids[-1]}"

start fusion fusion --builtin office --duration-s 20 --out "$work/fusion" --serve-linger 120
node_run "$here/page_check.cjs" "$chromium" "$port" fusion "$(shot live-fusion.png)" 120
kill "${pids[-1]}"

# A port in use: exit 4 naming it, and no outputs.
start busy explore --out "$work/busy" --step-delay-ms 50 --serve-linger 30
set +e
"$cli" explore --out "$work/second" --serve "$port" --quiet 2> "$work/second.err"
rc=$?
set -e
[ $rc -eq 4 ] || { echo "FAIL: a port in use gave exit $rc, expected 4"; cat "$work/second.err"; exit 1; }
grep -q "$port" "$work/second.err" || { echo "FAIL: the error does not name the port"; cat "$work/second.err"; exit 1; }
[ ! -e "$work/second" ] || { echo "FAIL: a run that could not serve wrote outputs"; exit 1; }
# Pacing without a live view is a usage error.
set +e
"$cli" explore --out "$work/paced" --step-delay-ms 5 --quiet 2> "$work/paced.err"
rc=$?
set -e
[ $rc -eq 2 ] || { echo "FAIL: --step-delay-ms without --serve gave exit $rc, expected 2"; exit 1; }
echo "live view test: PASS"
