#!/usr/bin/env bash
# make bob-firmware-test: the BOBMapping firmware images (make bob-firmware) run on an emulated
# Cortex-M4 (QEMU mps2-an386) against the host simulator, on two worlds and both variants, with
# sensor noise on; `tessera bob --firmware` fails unless the firmware's final map and route are the
# host build's own, byte for byte. tessera starts QEMU itself, waits at most --firmware-timeout
# seconds for any answer, and stops it in every case (QEMU also dies with tessera); `timeout`
# bounds each whole run.
#
# usage: scripts/bob_firmware_test.sh TESSERA FIRMWARE_DIR   (e.g. build/ci/apps/tessera/tessera
#                                                             build/cortex-m/firmware/bob)
set -euo pipefail
tessera=${1:?tessera binary}
firmware=${2:?folder of bob_firmware.elf and bob_firmware_map_aware.elf}
out=$(mktemp -d "${TMPDIR:-/tmp}/bob-firmware-test.XXXXXX")
trap 'rm -rf "$out"' EXIT
# The closed arena, and the open one cut to its 11 x 14 grid (builtin_world.hpp).
for world in bob-arena bob-arena-open; do
  crop=()
  [ "$world" = bob-arena-open ] && crop=(--crop 0.44,0.44,2.86,3.52)
  for variant in trail map-aware; do
    elf="$firmware/bob_firmware.elf"
    [ "$variant" = map-aware ] && elf="$firmware/bob_firmware_map_aware.elf"
    timeout --kill-after=5 120 "$tessera" bob --builtin "$world" "${crop[@]}" --variant "$variant" --seed 1 \
      --firmware "$elf" --firmware-timeout 20 --quiet --out "$out/$world-$variant"
    grep -q '"final_map_identical_to_host": true' "$out/$world-$variant/report.json"
    echo "bob-firmware-test: $world, $variant: the firmware's final map is the host's"
  done
done
