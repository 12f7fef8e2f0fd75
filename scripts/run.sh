#!/usr/bin/env bash
# The main job on a fresh machine, no hardware needed: set up, build, then reproduce the paper's Fig. 3
# experiment (4000 s from power-on, one sample a second) with the firmware in the loop, fit the drift model
# (Table 1) and write the HTML report into the repository's out/.
# Usage: scripts/run.sh [driftlab hil options]   e.g. --model my.toml --seed 7 --duration 600
# --preset (fig3) and -o/--output (out/fig3.csv, which fit and report read) are fixed; --pty writes no log.
# Paths in the options are taken from the folder the script is called from.
set -euo pipefail
for arg in "$@"; do
  case "$arg" in
    --preset|--preset=*|-o|-o*|--output|--output=*|--pty)
      echo "run.sh: $arg: fixed by the main job (--preset fig3 -o out/fig3.csv); run build/native/bin/driftlab hil for others" >&2
      exit 2 ;;
  esac
done
# No cd: the options' relative paths (--model my.toml) stay the caller's; the repository is named absolutely.
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/setup.sh"
(cd "$root" && cmake --preset native >/dev/null && cmake --build --preset native -j "$(nproc)" --target driftlab)
bin="$root/build/native/bin/driftlab"
out="$root/out"
mkdir -p "$out"
"$bin" hil --preset fig3 -o "$out/fig3.csv" "$@"
"$bin" fit "$out/fig3.csv" --plot "$out/plots"
"$bin" report "$out/fig3.csv" -o "$out/report.html"
echo "main job done: $out/fig3.csv, $out/plots/, $out/report.html"
