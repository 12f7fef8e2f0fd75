#!/usr/bin/env bash
# A gap-eval campaign and a fleet on a real Slurm: a single-node cluster on localhost (munged, slurmctld, slurmd, a slurm.conf of
# the test's own), the campaign submitted as an array job by scripts/slurm/submit.sh --wait, merged by its
# dependent job and compared byte for byte with the local run; an array whose tasks fail fails the campaign. Every
# daemon started here is stopped on the way out, pass or fail.
# Usage: slurm_campaign_test.sh DRIFTLAB SOURCE_DIR
set -euo pipefail
driftlab=$1 source=$2
for tool in munged slurmctld slurmd sbatch sinfo; do
  command -v "$tool" >/dev/null || { echo "FAIL: $tool is missing (scripts/setup.sh installs slurm-wlm and munge)"; exit 1; }
done
dir=$(mktemp -d /tmp/driftlab_slurm.XXXXXX)
chmod 755 "$dir"  # munged wants its socket's folder open to every user
cleanup() {
  for d in slurmd slurmctld; do
    if [ -f "$dir/$d.pid" ]; then kill "$(cat "$dir/$d.pid")" 2>/dev/null || true; fi
  done
  munged -s --socket="$dir/munge.sock" >/dev/null 2>&1 || true
  sleep 1
  rm -rf "$dir"
}
trap cleanup EXIT
fail() { echo "FAIL: $*"; for f in "$dir"/*.log; do echo "--- $f"; tail -20 "$f"; done; exit 1; }

host=$(hostname -s)
port=$((20000 + ($$ % 10000) * 2))  # two ports of this run's own: another test run may be up beside it
mkdir -p "$dir/state" "$dir/spool"
head -c 1024 /dev/urandom > "$dir/munge.key"
chmod 600 "$dir/munge.key"
munged -f --socket="$dir/munge.sock" --key-file="$dir/munge.key" --log-file="$dir/munged.log" \
  --pid-file="$dir/munged.pid" --seed-file="$dir/munged.seed" || fail "munged did not start"
cat > "$dir/slurm.conf" <<CONF
ClusterName=driftlab
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge.sock
CredType=cred/munge
SlurmctldPort=$port
SlurmdPort=$((port + 1))
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerParameters=sched_interval=1,bf_interval=1
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
ReturnToService=2
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=main Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$dir/slurm.conf
slurmctld -f "$SLURM_CONF" || fail "slurmctld did not start"
slurmd -f "$SLURM_CONF" || fail "slurmd did not start"
for _ in $(seq 60); do
  sinfo -h -o %t 2>/dev/null | grep -q idle && break
  sleep 0.5
done
sinfo -h -o %t | grep -q idle || fail "the node never became idle"

# A small campaign: the local run, then the same as an array of 4 shards and its merge.
# shellcheck disable=SC2054  # --effects takes a comma-separated list
campaign=(--quick --effects thermal_rc,burst_spikes --seeds-score 101..102)
"$driftlab" gap-eval "${campaign[@]}" --json > "$dir/local.json" 2>/dev/null
DRIFTLAB=$driftlab "$source/scripts/slurm/submit.sh" --wait gap-eval 4 "$dir/run" "${campaign[@]}" ||
  fail "the campaign's jobs failed"
cmp "$dir/local.json" "$dir/run/campaign.json" || fail "the merged campaign differs from the local run"
[ -s "$dir/run/campaign.txt" ] || fail "no text result"

# A fleet of five boards in 3 shards, one file in its folder no log: the merge names it (exit 3) and reports the rest.
# The folder's name has a blank: every task must get it as one argument.
boards="$dir/our boards"
mkdir -p "$boards"
for k in 1 2 3 4 5; do
  "$driftlab" hil --preset fig3 --duration 1500 --seed "$k" -o "$boards/b$k.csv" > /dev/null
done
echo "not a log" > "$boards/notes.csv"
"$driftlab" fleet "$boards" --no-cache --json > "$dir/fleet.json" 2>/dev/null && fail "a fleet with a non-log passed"
status=0
DRIFTLAB=$driftlab "$source/scripts/slurm/submit.sh" --wait fleet 3 "$dir/fleet" "$boards" --no-cache || status=$?
[ "$status" -eq 3 ] || fail "the fleet's campaign ended $status, not 3 (a log not analysed)"
cmp "$dir/fleet.json" "$dir/fleet/campaign.json" || fail "the merged fleet differs from the local run"
[ -s "$dir/fleet/report/fleet.md" ] || fail "no fleet report"

# Tasks that fail: the merge never runs and --wait says so.
if DRIFTLAB=/bin/false "$source/scripts/slurm/submit.sh" --wait gap-eval 3 "$dir/broken" --quick; then
  fail "an array whose tasks failed was reported a success"
fi
[ ! -e "$dir/broken/campaign.json" ] || fail "a merge ran after failed tasks"
echo "PASS: 4 gap-eval tasks and 3 fleet tasks merged to the local runs' bytes; failed tasks fail the campaign"
