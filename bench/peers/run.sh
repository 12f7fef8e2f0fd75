#!/usr/bin/env bash
# driftlab against its peers on the same machine, whole processes on the same input files (docs/performance.md):
#   fit   eq. 1 on a 10^6-row, four-channel driftlab log     vs numpy loadtxt + scipy curve_fit (fit_peer.py)
#   adev  overlapping ADEV at octave tau, 10^7 rate samples  vs numpy, allantools' algorithm (adev_peer.py)
#   gap   the diagnosis of 1 h and 2 h at 100 Hz with a second time constant planted (no peer: time and memory)
#   avr   the real firmware in simavr, default configuration (no peer: times real time)
# Prints each wall time, peak memory (GNU time's maximum resident set) and the ratio. Needs `scripts/setup.sh --bench`
# (numpy, scipy, GNU time). Usage: bench/peers/run.sh [WORK...]   (default: all four; DRIFTLAB names the executable)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
driftlab=${DRIFTLAB:-build/native/bin/driftlab}
works=("$@")
[ ${#works[@]} -gt 0 ] || works=(fit adev gap avr)
python=${PYTHON:-/usr/bin/python3}  # Debian's, whose numpy and scipy the bench step installs
for tool in /usr/bin/time "$python"; do
  command -v "$tool" > /dev/null || { echo "$0: $tool is missing: run scripts/setup.sh --bench" >&2; exit 2; }
done
"$python" -c "import numpy, scipy" 2> /dev/null || { echo "$0: numpy/scipy missing: scripts/setup.sh --bench" >&2; exit 2; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

# Runs a command under GNU time; sets seconds and megabytes.
measure() {
  /usr/bin/time -f "%e %M" -o "$dir/time" "$@" > "$dir/out" 2> "$dir/err" ||
    { echo "$0: failed: $*" >&2; cat "$dir/err" >&2; exit 1; }
  read -r seconds kilobytes < "$dir/time"
  megabytes=$((kilobytes / 1024))
}
row() {  # WORK PEER_S PEER_MB DRIFTLAB_S DRIFTLAB_MB
  awk -v w="$1" -v ps="$2" -v pm="$3" -v ds="$4" -v dm="$5" 'BEGIN {
    printf "%-5s peer %7.2f s %6d MB   driftlab %7.2f s %6d MB   %5.1fx faster, memory %.2f of the peer'"'"'s\n",
      w, ps, pm, ds, dm, ps / ds, dm / pm }'
}

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), commit $(git -C "$here" rev-parse --short HEAD 2>/dev/null || echo '?')"
for work in "${works[@]}"; do
  case "$work" in
    fit)
      "$driftlab" hil --model "$here/../../sim/models/hundred_hz.toml" --preset fig3 --duration 10000 --seed 7 \
        -o "$dir/fit.csv" > /dev/null
      measure "$python" "$here/fit_peer.py" "$dir/fit.csv"
      peer_s=$seconds peer_mb=$megabytes
      measure "$driftlab" fit "$dir/fit.csv" --json
      row fit "$peer_s" "$peer_mb" "$seconds" "$megabytes"
      ;;
    adev)
      "$python" -c "
import numpy as np
x = np.random.default_rng(1).normal(size=10**7)
np.savetxt('$dir/rate.txt', x, fmt='%.6f')"
      measure "$python" "$here/adev_peer.py" "$dir/rate.txt"
      peer_s=$seconds peer_mb=$megabytes
      measure "$driftlab" allan "$dir/rate.txt" --kind rate --tau0 1 --grid octave --json
      row adev "$peer_s" "$peer_mb" "$seconds" "$megabytes"
      ;;
    gap)
      printf '[effects.thermal_second_tc]\nc3_dps = 0.3\nt2_s = 2400.0\n' > "$dir/planted.toml"
      cat "$here/../../sim/models/hundred_hz.toml" "$dir/planted.toml" > "$dir/model.toml"
      # An hour and two: how time and memory grow with the log's length.
      for hours in 1 2; do
        "$driftlab" hil --model "$dir/model.toml" --preset fig3 --duration $((hours * 3600)) --seed 7 \
          -o "$dir/log.csv" > /dev/null
        measure "$driftlab" gap "$dir/log.csv" --json
        printf "gap   %d h at 100 Hz, second time constant planted: %.1f s, %d MB (verdict %s)\n" "$hours" \
          "$seconds" "$megabytes" "$(grep -m1 '"verdict"' "$dir/out" | tr -d ' ",' | cut -d: -f2)"
      done
      ;;
    avr)
      if ! "$driftlab" hil --target avr --duration 60 -o "$dir/avr.csv" > "$dir/avr.txt" 2>&1; then
        echo "avr   skipped: $(tail -1 "$dir/avr.txt")"
        continue
      fi
      "$driftlab" hil --target avr --duration 3600 -o "$dir/avr.csv" > "$dir/avr.txt"
      echo "avr   the firmware in simavr: $(grep -o '[0-9.]*x real time' "$dir/avr.txt")"
      ;;
    *) echo "$0: unknown work '$work' (fit, adev, gap, avr)" >&2; exit 2 ;;
  esac
done
