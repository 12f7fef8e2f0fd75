#!/usr/bin/env bash
# Throughput of a sharded gap-eval campaign on one machine: the one-process run on one core against N shards on N
# cores (each pinned to its own with taskset), in one stage (every shard measures a_50 itself) and in two (the
# generators' a_50 measured in N shards and merged once, then the cases in N shards reading them), each with its
# merges. Prints the wall times, their ratio against the ideal 1/N and whether each merge is the one-process output
# (docs/cluster.md §Throughput). Usage: bench/shards.sh [N] [gap-eval options...]   (default: N = nproc, --quick)
set -euo pipefail
driftlab=${DRIFTLAB:-build/native/bin/driftlab}
n=${1:-$(nproc)}
shift || true
campaign=("$@")
[ ${#campaign[@]} -gt 0 ] || campaign=(--quick)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
now() { date +%s.%N; }
# N shards of gap-eval with extra options EXTRA (a word list) writing PREFIX_k, each pinned to a core; waits.
shards() {
  local prefix=$1
  shift
  for ((k = 0; k < n; k++)); do
    taskset -c $((k % $(nproc))) "$driftlab" gap-eval "${campaign[@]}" "$@" --shard "$k/$n" -o "${prefix}_$k" \
      2>/dev/null &
  done
  wait
}
t0=$(now)
taskset -c 0 "$driftlab" gap-eval "${campaign[@]}" --json > "$dir/one.json" 2>/dev/null
t1=$(now)
shards "$dir/part"
"$driftlab" merge --json "$dir"/part_* > "$dir/merged.json"
t2=$(now)
shards "$dir/sizes" --measure-sizes
"$driftlab" merge "$dir"/sizes_* -o "$dir/sizes" 2>/dev/null
shards "$dir/staged" --sizes "$dir/sizes"
"$driftlab" merge --json "$dir"/staged_* > "$dir/staged.json"
t3=$(now)
cmp -s "$dir/one.json" "$dir/merged.json" && same=yes || same=NO
cmp -s "$dir/one.json" "$dir/staged.json" && staged_same=yes || staged_same=NO
awk -v t0="$t0" -v t1="$t1" -v t2="$t2" -v t3="$t3" -v n="$n" -v same="$same" -v staged_same="$staged_same" \
  -v what="${campaign[*]}" 'BEGIN {
    one = t1 - t0; single = t2 - t1; staged = t3 - t2
    printf "gap-eval %s: one process on one core %.1f s; on %d cores (goal <= %.2f of it, ideal %.2f):\n", what, one, n, 1.2 / n, 1 / n
    printf "  one stage  (every shard measures a_50)        %.1f s = %.2f; merged = one-process: %s\n", single, single / one, same
    printf "  two stages (a_50 in shards, merged, then cases) %.1f s = %.2f; merged = one-process: %s\n", staged, staged / one, staged_same }'
