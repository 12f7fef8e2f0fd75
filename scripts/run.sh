#!/usr/bin/env bash
# The main job on a fresh machine, no hardware needed: set up, build, then reproduce the paper's Fig. 3
# experiment (4000 s from power-on, one sample a second) with the firmware in the loop, fit the drift model
# (Table 1) and write the HTML report.   Usage: scripts/run.sh [extra driftlab hil options]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset native >/dev/null
cmake --build --preset native -j "$(nproc)" --target driftlab
bin=build/native/bin/driftlab
mkdir -p out
"$bin" hil --preset fig3 -o out/fig3.csv "$@"
"$bin" fit out/fig3.csv --plot out/plots
"$bin" report out/fig3.csv -o out/report.html
echo "main job done: out/fig3.csv, out/plots/, out/report.html"
