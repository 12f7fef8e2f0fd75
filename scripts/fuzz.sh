#!/usr/bin/env bash
# Builds the libFuzzer harnesses (tests/fuzz, clang with ASan + UBSan) and runs each for a bounded time from its
# checked-in corpus. Fails when a harness finds a crash, a sanitizer error, a broken property or an input slower than
# the timeout; the input is kept in build/fuzz/artifacts/ (replay: build/fuzz/fuzz/<name>_fuzz FILE).
# Usage: scripts/fuzz.sh [SECONDS_EACH]    (default 30; .ci/run uses the default)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$(nproc)"

bin=build/fuzz/fuzz
artifacts=build/fuzz/artifacts
mkdir -p "$artifacts"
# New inputs a run finds go to a scratch folder; the checked-in corpus is only read.
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# The checked-in corpus of a harness: its own seeds, or the model files the project ships.
corpus_of() {
  case $1 in
    model_file) echo sim/models ;;
    *) echo "tests/fuzz/corpus/$1" ;;
  esac
}

# One harness: -timeout makes an input that takes longer than 2 s a failure (a reader must be linear), -rss_limit_mb
# one that needs more memory than any input of -max_len could justify.
run_one() {
  local name=$1
  mkdir -p "$scratch/$name"
  set +e
  "$bin/${name}_fuzz" "$scratch/$name" "$(corpus_of "$name")" \
    -max_total_time="$seconds" -timeout=2 -rss_limit_mb=1024 -max_len=65536 \
    -artifact_prefix="$artifacts/${name}-" -print_final_stats=1 >"$scratch/$name.log" 2>&1
  echo $? >"$scratch/$name.rc"
}

names=(frame_decoder capture_decode log_reader numeric_table model_file)
jobs=$(nproc)
failed=()
for name in "${names[@]}"; do
  # No more harnesses at once than cores: each is timed against the wall clock.
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do sleep 1; done
  run_one "$name" &
done
wait
for name in "${names[@]}"; do
  if [ "$(cat "$scratch/$name.rc")" = 0 ]; then
    runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$scratch/$name.log" | grep -o '[0-9]*$' || echo '?')
    echo "fuzz: $name: $runs inputs in ${seconds} s, nothing found"
  else
    failed+=("$name")
    echo "fuzz: $name: FAILED; its log:" >&2
    tail -n 60 "$scratch/$name.log" >&2
  fi
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: ${#failed[@]} harness(es) found something: ${failed[*]}; inputs in $artifacts/" >&2
  exit 1
fi
