#!/usr/bin/env bash
# Installs every Debian package driftlab needs. Idempotent: packages already present are left alone.
# Works as root or through sudo. Usage: scripts/setup.sh [--bench]
#   --bench  also the peers bench/peers/run.sh compares driftlab with (numpy, scipy) and GNU time for peak memory:
#            benchmark-only, never needed to build or test
set -euo pipefail

packages=(
  # native build and tests
  build-essential cmake ninja-build pkg-config clang-format
  libgtest-dev libgmock-dev libbenchmark-dev
  # host libraries
  libeigen3-dev libboost-math-dev libcli11-dev libtomlplusplus-dev nlohmann-json3-dev libnlopt-dev libfftw3-dev
  libserial-dev libusb-1.0-0-dev
  # tests: the gzip-compressed reference phase record (tests/host/stats)
  zlib1g-dev
  # plots
  gnuplot-nox
  # tests: the HTML report opened in a headless browser (tests/e2e/report_browser_test.cpp)
  chromium
  # CI's sanitizer and fuzzing jobs (scripts/sanitize.sh, scripts/fuzz.sh): clang with libFuzzer, readable stacks
  clang libclang-rt-14-dev llvm
  # AVR cross build, flashing and emulation
  gcc-avr binutils-avr avr-libc avrdude gdb-avr simavr libsimavr-dev
  # campaigns on a cluster (docs/cluster.md), and the single-node cluster its test starts (tests/slurm)
  slurm-wlm munge
)
if [ "${1:-}" = "--bench" ]; then
  packages+=(python3-numpy python3-scipy time)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
  sudo=()
elif command -v sudo >/dev/null 2>&1; then
  sudo=(sudo)
else
  echo "setup: missing packages: ${missing[*]}" >&2
  echo "setup: installing them needs root, and sudo is not installed: run scripts/setup.sh as root" >&2
  exit 1
fi
echo "setup: installing ${missing[*]}"
# env after sudo: sudo resets the environment, so a variable set before it never reached apt-get.
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
