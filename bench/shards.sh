#!/usr/bin/env bash
# Throughput of a sharded gap-eval campaign on one machine: the one-process run on one core against N shards on N
# cores (each pinned to its own with taskset), and the merge. Prints the wall times and their ratio against the
# ideal 1/N (docs/cluster.md §Throughput). Usage: bench/shards.sh [N] [gap-eval options...]   (default: N = nproc,
# --quick)
set -euo pipefail
driftlab=${DRIFTLAB:-build/native/bin/driftlab}
n=${1:-$(nproc)}
shift || true
campaign=("$@")
[ ${#campaign[@]} -gt 0 ] || campaign=(--quick)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
now() { date +%s.%N; }
t0=$(now)
taskset -c 0 "$driftlab" gap-eval "${campaign[@]}" --json > "$dir/one.json" 2>/dev/null
t1=$(now)
for ((k = 0; k < n; k++)); do
  taskset -c $((k % $(nproc))) "$driftlab" gap-eval "${campaign[@]}" --shard "$k/$n" -o "$dir/part_$k" 2>/dev/null &
done
wait
t2=$(now)
"$driftlab" merge --json "$dir"/part_* > "$dir/merged.json"
t3=$(now)
cmp -s "$dir/one.json" "$dir/merged.json" && same=yes || same=NO
awk -v t0="$t0" -v t1="$t1" -v t2="$t2" -v t3="$t3" -v n="$n" -v same="$same" -v what="${campaign[*]}" 'BEGIN {
    one = t1 - t0; shards = t2 - t1; merge = t3 - t2
    printf "gap-eval %s: one process on one core %.1f s; %d shards on %d cores %.1f s (%.2f of it; ideal %.2f, goal <= %.2f); merge %.2f s; merged = one-process: %s\n",
      what, one, n, n, shards, shards / one, 1 / n, 1.2 / n, merge, same }'
