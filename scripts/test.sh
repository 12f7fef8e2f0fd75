#!/usr/bin/env bash
# Sets up a fresh machine, builds the native tree and the ATmega328P firmware, and runs every test.
# Usage: scripts/test.sh        (this is what .ci/run calls)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
jobs=$(nproc)
cmake --preset native >/dev/null
cmake --build --preset native -j "$jobs"
cmake --preset avr >/dev/null
cmake --build --preset avr -j "$jobs"
ctest --preset native -j "$jobs"
