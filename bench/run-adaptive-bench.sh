#!/usr/bin/env bash
# Benchmark (not a test): the paper's adaptive run (inputs/membrane.xml, 5 cycles) with the
# unconstrained solve timed in every step; prints the wall time, the phase split per cycle and the
# cost of a whole adaptive step in unconstrained solves of the same size (target <= 6).
# The same run without the transfer-energy columns, and in ordinary arithmetic (the deck switches on
# Parallel/Reproducible Arithmetic).
# Usage: bash bench/run-adaptive-bench.sh [-np N] [-r R]
# -r R: the three runs R times, interleaved (the machine's speed drifts), and the cost's median and
# range over the repetitions (the first repetition's full summary as without -r).
# (SIGNORINI_NO_BUILD=1: use the existing build/src/signorini instead of building it first; -h, --help: this text)
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/bench_args.sh
help_only "$@"
parse_ranks_and_repeats "usage: bash bench/run-adaptive-bench.sh [-np N] [-r R]" "$@"
build_and_describe
mkdir -p out/bench
rm -f out/bench/adaptive*.np"$np".* out/bench/adaptive*.np"$np"-r*.*  # nothing of an earlier run can be summarised as this one's
run() {  # basename, extra --set arguments
  local name=$1
  shift
  "${mpirun[@]}" ./build/src/signorini --output-dir out/bench \
    --set "Output/Basename=$name" --set "Output/Measure Contact Overhead=true" "$@" inputs/membrane.xml
}
run "adaptive.np$np" | grep -E "^signorini: (cycle|.* done)"
/usr/bin/python3 bench/summarize_adaptive.py out/bench/adaptive.np$np
# What the step tables' transfer-energy columns cost (one more projected field per mesh change):
# the same run without them.
echo "without Adaptivity/Report Transfer Energy:"
run "adaptive-noenergy.np$np" --set "Adaptivity/Report Transfer Energy=false" > /dev/null
/usr/bin/python3 bench/summarize_adaptive.py out/bench/adaptive-noenergy.np$np | tail -3
# What reproducible arithmetic costs (the same bits on any number of ranks, docs/reproducibility.md):
# the run again in ordinary arithmetic, the first run's wall time against its, both without the
# benchmark's own extra solves (time_unconstrained, a different solver in each arithmetic): what a
# user's run costs.
echo "in ordinary arithmetic (Parallel/Reproducible Arithmetic=false):"
run "adaptive-ordinary.np$np" --set "Parallel/Reproducible Arithmetic=false" > /dev/null
/usr/bin/python3 bench/summarize_adaptive.py out/bench/adaptive-ordinary.np$np | tail -3
/usr/bin/python3 - "out/bench/adaptive-ordinary.np$np.cycles.csv" "out/bench/adaptive.np$np.cycles.csv" <<'PY2'
import csv, sys
wall = [sum(float(r["wall_seconds"]) - float(r["time_unconstrained"]) for r in csv.DictReader(open(f))) for f in sys.argv[1:]]
print(f"reproducible arithmetic: whole run without the benchmark's extra solves {wall[1]:.1f} s against {wall[0]:.1f} s: "
      f"{wall[1] / wall[0]:.2f} times the time")
PY2
if [ "$repeats" -gt 1 ]; then
  for r in $(seq 2 "$repeats"); do
    run "adaptive.np$np-r$r" > /dev/null
    run "adaptive-noenergy.np$np-r$r" --set "Adaptivity/Report Transfer Energy=false" > /dev/null
    run "adaptive-ordinary.np$np-r$r" --set "Parallel/Reproducible Arithmetic=false" > /dev/null
  done
  for v in adaptive adaptive-noenergy adaptive-ordinary; do
    bases=("out/bench/$v.np$np")
    for r in $(seq 2 "$repeats"); do bases+=("out/bench/$v.np$np-r$r"); done
    echo "$v: $(/usr/bin/python3 bench/summarize_adaptive.py --ratios "${bases[@]}")"
  done
fi
