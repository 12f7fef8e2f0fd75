#!/usr/bin/env bash
# The sanitizer builds .ci/run adds to the plain one (README "Tests"):
#   asan  every test but the slow ones tests/sanitizers/asan_skip.txt names, on a build of everything with
#         AddressSanitizer + UBSan (build/native-asan);
#   tsan  the threaded parts' tests (host/util's parallel_for; gap and gap-eval at several thread counts) with
#         ThreadSanitizer (build/native-tsan).
# A sanitizer finding stops the program (no recovery), so it fails its test and this script.
# Usage: scripts/sanitize.sh [asan|tsan]...    (default: both)
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
# Reports with their stacks; a leak, an error or a race fails the process.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0:strict_string_checks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0}
export TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1}

# Every test but those tests/sanitizers/asan_skip.txt names (each too slow under ASan; the plain run has them).
asan() {
  local skip
  skip=$(grep -v '^\s*\(#\|$\)' tests/sanitizers/asan_skip.txt | sed 's/.*/^&$/' | paste -sd '|')
  cmake --preset native-asan >/dev/null
  cmake --build --preset native-asan -j "$jobs"
  ctest --preset native-asan -j "$jobs" -E "$skip"
}

# The threaded parts: parallel_for itself (every util test), and the gap diagnosis and the gap-eval benchmark run at
# several thread counts (their other tests repeat the same parallel paths on more data, at ThreadSanitizer's 5-15x).
tsan() {
  local runs=("host_util_tests:*" "host_gap_tests:Diagnose.TheResultDoesNotDependOnTheThreadCount"
              "host_gap_eval_tests:GapEval.AGeneratorsDetectionThresholdDoesNotDependOnTheOthersInTheRun")
  cmake --preset native-tsan >/dev/null
  cmake --build --preset native-tsan -j "$jobs" --target "${runs[@]%%:*}"
  for run in "${runs[@]}"; do
    # As ctest's presets give each test 20 minutes: a hang fails the run instead of stalling it.
    timeout 1800 build/native-tsan/tests/host/"${run%%:*}" --gtest_filter="${run#*:}" --gtest_brief=1
  done
}

for what in "${@:-asan tsan}"; do
  for w in $what; do
    case $w in
      asan) asan ;;
      tsan) tsan ;;
      *) echo "sanitize: '$w' is neither asan nor tsan" >&2; exit 2 ;;
    esac
  done
done
