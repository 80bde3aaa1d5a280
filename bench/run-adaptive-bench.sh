#!/usr/bin/env bash
# Benchmark (not a test): the paper's adaptive run (inputs/membrane.xml, 5 cycles) with the
# unconstrained solve timed in every step; prints the wall time, the phase split per cycle and the
# cost of a whole adaptive step in unconstrained solves of the same size (target <= 6).
# Usage: bash bench/run-adaptive-bench.sh [-np N]
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh > /dev/null
np=1
if [ "${1:-}" = "-np" ]; then np=$2; fi
mkdir -p out/bench
mpirun --allow-run-as-root --oversubscribe -np "$np" ./build/src/signorini --output-dir out/bench \
  --set "Output/Basename=adaptive.np$np" --set "Output/Measure Contact Overhead=true" inputs/membrane.xml \
  | grep -E "cycle|done"
/usr/bin/python3 bench/summarize_adaptive.py out/bench/adaptive.np$np
# What the step tables' transfer-energy columns cost (one more projected field per mesh change):
# the same run without them.
echo "without Adaptivity/Report Transfer Energy:"
mpirun --allow-run-as-root --oversubscribe -np "$np" ./build/src/signorini --output-dir out/bench \
  --set "Output/Basename=adaptive-noenergy.np$np" --set "Output/Measure Contact Overhead=true" \
  --set "Adaptivity/Report Transfer Energy=false" inputs/membrane.xml > /dev/null
/usr/bin/python3 bench/summarize_adaptive.py out/bench/adaptive-noenergy.np$np | tail -2
