#!/usr/bin/env bash
# Submits a campaign to Slurm: an array of N shards, then a merge that runs once all of them succeeded (gap-eval: first
# an array measuring a_50 and its merge, then the case array reading it, then the merge).
# Usage: scripts/slurm/submit.sh [--wait] COMMAND N OUT [COMMAND's arguments...]
#   COMMAND  gap-eval, nav-eval or fleet (fleet's arguments hold its logs or their folder)
#   N        shards (array tasks 0..N-1); OUT  a folder every node can reach (the parts, the logs, the result)
#   --wait   return when the merge has ended: non-zero if a task or the merge failed (OUT/campaign.json then absent),
#            3 for a fleet with a log that could not be analysed (its results are there)
# DRIFTLAB (default: driftlab on the PATH) names the executable the tasks run. Prints the last two job ids.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
wait=()
if [ "${1:-}" = "--wait" ]; then wait=(--wait); shift; fi
if [ $# -lt 3 ] || ! [[ "$1" =~ ^(gap-eval|nav-eval|fleet)$ ]]; then
  echo "usage: $0 [--wait] gap-eval|nav-eval|fleet N OUT [arguments...]" >&2
  exit 2
fi
command=$1 shards=$2 out=$3
shift 3
mkdir -p "$out"
out=$(cd "$out" && pwd)
unset STAGE  # shard.sbatch and merge.sbatch read it: set below for gap-eval's stages only
# The arguments go to the tasks through a file, each ended by a NUL: a path with a blank in it stays one argument.
printf '%s\0' "$@" > "$out/campaign.args"
unset CAMPAIGN
export COMMAND=$command SHARDS=$shards OUT=$out CAMPAIGN_ARGS=$out/campaign.args DRIFTLAB=${DRIFTLAB:-driftlab}
rm -f "$out/campaign.txt" "$out/campaign.json" "$out/sizes"
# afterok: a failed task leaves every job after it never to run (Slurm cancels them).
after=()
if [ "$command" = gap-eval ]; then
  # a_50 measured once, in shards, and merged: the case shards read it instead of each measuring it again.
  sizes=$(sbatch --parsable --array="0-$((shards - 1))" --output="$out/sizes_%a.log" --export=ALL,STAGE=sizes \
    "$here/shard.sbatch")
  joined=$(sbatch --parsable --kill-on-invalid-dep=yes --dependency="afterok:${sizes%%;*}" \
    --output="$out/sizes_merge.log" --export=ALL,STAGE=sizes "$here/merge.sbatch")
  after=(--kill-on-invalid-dep=yes --dependency="afterok:${joined%%;*}")
  export STAGE=cases
fi
array=$(sbatch --parsable "${after[@]}" --array="0-$((shards - 1))" --output="$out/shard_%a.log" --export=ALL \
  "$here/shard.sbatch")
status=0
merge=$(sbatch --parsable "${wait[@]}" --kill-on-invalid-dep=yes --dependency="afterok:${array%%;*}" \
  --output="$out/merge.log" --export=ALL "$here/merge.sbatch") || status=$?
echo "array ${array%%;*} merge ${merge%%;*}"
[ ${#wait[@]} -gt 0 ] || exit 0
# A merge Slurm cancelled ends "successfully" for sbatch --wait: the result's presence is what says it ran.
if [ ! -e "$out/campaign.json" ]; then
  echo "$0: the campaign failed: no merge result (see $out/shard_*.log and $out/merge.log)" >&2
  exit 1
fi
exit "$status"
