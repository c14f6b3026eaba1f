#!/usr/bin/env bash
# Issue 14's wire compatibility, checked by an implementation we did not write. net_wire_tool
# captures one sample of each of the 14 message types tessera sends as it arrives over DDS (a
# second participant receives it); npm's @foxglove/rosmsg2-serialization decodes each against its
# ROS 2 .msg definition and must find every field of the expected message, then encodes that
# message itself (wire_check.cjs); tessera decodes foxglove's bytes field for field, and sends them
# through DDS, whose validator checks them against the IDL type (net_wire_tool check). Each half
# must report all 14 types. The npm packages go to a folder outside the source tree. Without npm or
# the registry the test is skipped (exit 77), except with CI=true, where it fails.
# Usage: wire_compat_test.sh WIRE_TOOL TEST_DIR
set -euo pipefail
tool=$1
here=$2
expected_types=14

# shellcheck source=../support/npm_packages.sh
. "$here/../support/npm_packages.sh"
npm_packages "${TMPDIR:-/tmp}/tessera-npm-wire" "@foxglove/rosmsg@5.0.5" \
  "@foxglove/rosmsg2-serialization@3.1.0"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Runs one half of the check, shows its output, and records a failure unless it exited 0 and
# reported "ok" for every type; both halves run, so that one run reports every mismatch.
failed=0
step() {
  local name=$1 code=0 ok
  shift
  echo "== $name"
  "$@" > "$work/out" 2>&1 || code=$?
  cat "$work/out"
  ok=$(grep -c '^ok ' "$work/out" || true)
  if [ "$code" != 0 ]; then
    echo "FAIL: $name exited $code"
    failed=1
  elif [ "$ok" != "$expected_types" ]; then
    echo "FAIL: $name checked $ok types, expected $expected_types"
    failed=1
  fi
}

mkdir "$work/wire"
echo "== capture from DDS (net_wire_tool capture)"
"$tool" capture "$work/wire"
captured=$(find "$work/wire" -name '*.cdr' | wc -l)
if [ "$captured" != "$expected_types" ]; then
  echo "FAIL: captured $captured types, expected $expected_types"
  exit 1
fi
step "foxglove decodes tessera's wire bytes, encodes its own (wire_check.cjs)" \
  node "$here/wire_check.cjs" "$work/wire"
step "tessera decodes foxglove's bytes, directly and over DDS (net_wire_tool check)" \
  "$tool" check "$work/wire"
[ "$failed" = 0 ] || exit 1
echo "PASS: $expected_types types decode both ways"
