#!/usr/bin/env bash
# Sets up a fresh machine, builds the native tree and the ATmega328P firmware, runs every test, then the sanitizer
# and fuzzing jobs (README "Tests under the sanitizers and a fuzzer").
# Usage: scripts/test.sh        (this is what .ci/run calls)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
# Every C++ source file as .clang-format says (column limit 120; firmware/ and common/ indent by two).
mapfile -t sources < <(find common firmware sim host tests bench \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' -o -name '*.c' \) | sort)
clang-format --dry-run --Werror "${sources[@]}"
echo "format: ${#sources[@]} source files as .clang-format says"
jobs=$(nproc)
cmake --preset native >/dev/null
cmake --build --preset native -j "$jobs"
cmake --preset avr >/dev/null
cmake --build --preset avr -j "$jobs"
ctest --preset native -j "$jobs"
scripts/sanitize.sh asan tsan
scripts/fuzz.sh
