#!/usr/bin/env bash
# Benchmark (not a test): one uniform-mesh deck with Output/Measure Contact Overhead = true; prints
# the phase split per step and the contact overhead ratio R = time(contact solve) / time(unconstrained
# solve). Usage: bash bench/run-contact-bench.sh DECK [-np N]
# (SIGNORINI_NO_BUILD=1: use the existing build/src/signorini instead of building it first)
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/bench_args.sh
usage="usage: bash bench/run-contact-bench.sh DECK [-np N]"
[ $# -ge 1 ] && [ -f "$1" ] || { echo "$usage (no deck file '${1:-}')" >&2; exit 2; }
deck=$1
shift
parse_ranks "$usage" "$@"
build_and_describe
name=$(basename "$deck" .xml).np$np
mkdir -p out/bench
log=out/bench/$name.log
rm -f "out/bench/$name".*  # nothing of an earlier run can be summarised as this one's
"${mpirun[@]}" ./build/src/signorini --output-dir out/bench \
  --set "Output/Basename=$name" --set "Output/Measure Contact Overhead=true" "$deck" | tee "$log"
/usr/bin/python3 bench/summarize.py "out/bench/$name.steps.csv" "$log"
