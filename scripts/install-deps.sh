#!/usr/bin/env bash
# Installs tessera's build and test dependencies from Debian 12 packages.
# Idempotent: when every package is already installed it does nothing (no network).
set -euo pipefail

packages=(
  build-essential cmake make pkg-config python3
  libeigen3-dev libceres-dev libopencv-dev libnanoflann-dev libcli11-dev libfmt-dev
  nlohmann-json3-dev libyaml-cpp-dev libgtest-dev libgmock-dev libbenchmark-dev
  # ROS bag input (io/ros*): bz2 and lz4 chunks of ROS 1 bags, zstd/lz4 MCAP chunks, rosbag2 sqlite3.
  libbz2-dev liblz4-dev libzstd-dev libsqlite3-dev
  gcc-arm-none-eabi libnewlib-arm-none-eabi
  # The C++ headers for arm-none-eabi (<cstddef>, <cstdint>, ...): only a Recommends of
  # gcc-arm-none-eabi, so --no-install-recommends leaves them out and make bob-firmware fails.
  libstdc++-arm-none-eabi-dev
  # make bob-firmware-test runs the firmware on an emulated Cortex-M4 (the MPS2 AN386 board).
  qemu-system-arm
  # The fuzz preset (make fuzz, make fuzz-smoke): clang and its runtime libraries, which hold
  # libFuzzer (libclang_rt.fuzzer) and the sanitizer runtimes.
  clang libclang-rt-14-dev
  # The live view (--serve, src/live): a WebSocket server on standalone asio (header-only).
  libasio-dev
  # The live page's test opens it in headless Chromium (tests/live).
  chromium
  # Nodes and robot teams over DDS with ROS 2's names (src/net): Cyclone DDS's C library and idlc,
  # which compiles the message IDL at build time.
  cyclonedds-dev cyclonedds-tools
)

# Tests that check tessera's files with third-party readers (npm's @mcap/core, Foxglove's message
# decoders; tests/io/mcap_thirdparty, tests/record) run them on Node.js and install them with npm
# into a folder outside the source tree. Debian's nodejs and npm, unless a node and an npm are
# already there (a NodeSource nodejs bundles its own npm and conflicts with Debian's npm package).
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  packages+=(nodejs npm)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
