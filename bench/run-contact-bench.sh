#!/usr/bin/env bash
# Benchmark (not a test): one uniform-mesh deck with Output/Measure Contact Overhead = true; prints
# the phase split per step and the contact overhead ratio R = time(contact solve) / time(unconstrained
# solve). Usage: bash bench/run-contact-bench.sh DECK [-np N]   (DECK: a path from the current folder;
# the output goes to out/bench/ of the repository, -h, --help: this text)
# (SIGNORINI_NO_BUILD=1: use the existing build/src/signorini instead of building it first)
set -euo pipefail
source "$(dirname "$0")/bench_args.sh"
help_only "$@"
usage="usage: bash bench/run-contact-bench.sh DECK [-np N]"
[ $# -ge 1 ] && [ -f "$1" ] || { echo "$usage (no deck file '${1:-}')" >&2; exit 2; }
deck=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")  # from the caller's folder
shift
cd "$(dirname "$0")/.."
parse_ranks "$usage" "$@"
build_and_describe
name=$(basename "$deck" .xml).np$np
mkdir -p out/bench
log=out/bench/$name.log
rm -f "out/bench/$name".*  # nothing of an earlier run can be summarised as this one's
"${mpirun[@]}" ./build/src/signorini --output-dir out/bench \
  --set "Output/Basename=$name" --set "Output/Measure Contact Overhead=true" "$deck" | tee "$log"
/usr/bin/python3 bench/summarize.py "out/bench/$name.steps.csv" "$log"
