#!/usr/bin/env bash
# Benchmark (not a test): one uniform-mesh deck with Output/Measure Contact Overhead = true; prints
# the phase split per step and the contact overhead ratio R = time(contact solve) / time(unconstrained
# solve). Usage: bash bench/run-contact-bench.sh DECK [-np N]
set -euo pipefail
cd "$(dirname "$0")/.."
deck=$1
shift
bash tools/build.sh > /dev/null
np=1
if [ "${1:-}" = "-np" ]; then np=$2; fi
name=$(basename "$deck" .xml).np$np
mkdir -p out/bench
log=out/bench/$name.log
mpirun --allow-run-as-root --oversubscribe -np "$np" ./build/src/signorini --output-dir out/bench \
  --set "Output/Basename=$name" "$deck" | tee "$log"
/usr/bin/python3 bench/summarize.py "out/bench/$name.steps.csv" "$log"
