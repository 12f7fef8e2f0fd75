#!/usr/bin/env bash
# Submits a gap-eval campaign to Slurm: an array of N shards, then a merge that runs once all of them succeeded.
# Usage: scripts/slurm/submit-gap-eval.sh [--wait] N OUT [gap-eval options...]
#   N     shards (array tasks 0..N-1); OUT  a folder every node can reach (the parts, the logs, the result)
#   --wait  return when the merge has ended: non-zero if a task or the merge failed (OUT/campaign.json then absent)
# DRIFTLAB (default: driftlab on the PATH) names the executable the tasks run. Prints the two job ids.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
wait=()
if [ "${1:-}" = "--wait" ]; then wait=(--wait); shift; fi
if [ $# -lt 2 ]; then
  echo "usage: $0 [--wait] N OUT [gap-eval options...]" >&2
  exit 2
fi
shards=$1 out=$2
shift 2
mkdir -p "$out"
out=$(cd "$out" && pwd)
export SHARDS=$shards OUT=$out CAMPAIGN="$*" DRIFTLAB=${DRIFTLAB:-driftlab}
array=$(sbatch --parsable --array="0-$((shards - 1))" --output="$out/shard_%a.log" --export=ALL \
  "$here/gap-eval.sbatch")
rm -f "$out/campaign.md" "$out/campaign.json"
# afterok: a failed task leaves the merge never to run (Slurm cancels it).
merge=$(sbatch --parsable "${wait[@]}" --kill-on-invalid-dep=yes --dependency="afterok:${array%%;*}" \
  --output="$out/merge.log" --export=ALL "$here/merge.sbatch")
echo "array ${array%%;*} merge ${merge%%;*}"
# A merge Slurm cancelled ends "successfully" for sbatch --wait: the result's presence is what says it ran.
if [ ${#wait[@]} -gt 0 ] && [ ! -e "$out/campaign.json" ]; then
  echo "$0: the campaign failed: no merge result (see $out/shard_*.log and $out/merge.log)" >&2
  exit 1
fi
