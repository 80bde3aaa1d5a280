#!/usr/bin/env bash
# Benchmark (not a test): the uniform membrane at 263,169 unknowns per step; prints the phase
# split per step and the contact overhead ratio R. Usage: bash bench/run-membrane-bench.sh [-np N]
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh > /dev/null
np=1
if [ "${1:-}" = "-np" ]; then np=$2; fi
mkdir -p out/bench
log=out/bench/membrane-250k.np$np.log
mpirun --allow-run-as-root --oversubscribe -np "$np" ./build/src/signorini --output-dir out/bench \
  --set "Output/Basename=membrane-250k.np$np" bench/membrane-250k.xml | tee "$log"
/usr/bin/python3 bench/summarize.py out/bench/membrane-250k.np$np.steps.csv "$log"
