#!/usr/bin/env bash
# The benchmarks' measurement and summaries on short runs (about 5 s): with Output/Measure Contact
# Overhead every step after step 0 times its unconstrained solve, and that solve is the step's own
# (in a step without contact whose QP made one A-solve, the unit takes exactly that solve's CG
# iterations: same matrix, right-hand side and start); bench/summarize_adaptive.py (also --ratios)
# and bench/summarize.py summarise such runs and refuse a run without the measurement, with one
# line and a non-zero exit status.
# Usage: bench_summaries.sh SIGNORINI SOURCE_DIR WORK_DIR
set -uo pipefail
signorini=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
short=(--output-dir "$work" --set 'Time Integration/Final Time=0.1')
measure=(--set 'Output/Measure Contact Overhead=true' --set 'Output/Write Exodus=false')
"$signorini" "${short[@]}" "${measure[@]}" --set 'Adaptivity/Cycles=2' "$src/inputs/membrane.xml" \
  > "$work/adaptive.log" 2>&1 || { cat "$work/adaptive.log"; fail "the adaptive run failed"; }
"$signorini" "${short[@]}" "${measure[@]}" --set 'Adaptivity/Cycles=2' --set 'Output/Basename=second' \
  "$src/inputs/membrane.xml" > /dev/null 2>&1 || fail "the second adaptive run failed"
"$signorini" "${short[@]}" "${measure[@]}" "$src/inputs/membrane-level2.xml" > "$work/uniform.log" 2>&1 ||
  { cat "$work/uniform.log"; fail "the uniform run failed"; }
"$signorini" "${short[@]}" --set 'Adaptivity/Cycles=1' --set 'Output/Basename=plain' --set 'Output/Write Exodus=false' \
  "$src/inputs/membrane.xml" > /dev/null 2>&1 || fail "the run without the measurement failed"

for table in "$work/membrane.cycle0.steps.csv" "$work/membrane.steps.csv" "$work/membrane-level2.steps.csv"; do
  /usr/bin/python3 - "$table" <<'PY' || fail "$table: the unconstrained solve is not the step's own"
import sys
import numpy as np
s = np.genfromtxt(sys.argv[1], delimiter=",", names=True)[1:]
if not ((s["time_unconstrained"] > 0).all() and (s["unconstrained_iterations"] > 0).all()):
    sys.exit(f"{sys.argv[1]}: a step without a timed unconstrained solve")
same = (s["active"] == 0) & (s["linear_solves"] == 1)
if same.sum() < 10:
    sys.exit(f"{sys.argv[1]}: only {same.sum()} steps without contact and with one A-solve")
differ = same & (s["linear_iterations"] != s["unconstrained_iterations"])
if differ.any():
    sys.exit(f"{sys.argv[1]}: steps {s['step'][differ][:5]}: the unit took other iterations than the step's solve")
print(f"{sys.argv[1]}: {same.sum()} steps: the unit's iterations are the step's")
PY
done

/usr/bin/python3 "$src/bench/summarize_adaptive.py" "$work/membrane" > "$work/summary.txt" 2>&1 ||
  { cat "$work/summary.txt"; fail "summarize_adaptive.py failed"; }
grep -q "^a whole adaptive step costs [0-9.]* unconstrained solves" "$work/summary.txt" &&
  grep -q "its Krylov iterations: median [0-9]" "$work/summary.txt" || { cat "$work/summary.txt"; fail "no cost in the summary"; }
/usr/bin/python3 "$src/bench/summarize_adaptive.py" --ratios "$work/membrane" "$work/second" > "$work/ratios.txt" 2>&1 &&
  grep -q "(median of 2 runs" "$work/ratios.txt" || { cat "$work/ratios.txt"; fail "summarize_adaptive.py --ratios"; }
/usr/bin/python3 "$src/bench/summarize.py" "$work/membrane-level2.steps.csv" "$work/uniform.log" > "$work/uniform.txt" 2>&1 ||
  { cat "$work/uniform.txt"; fail "summarize.py failed"; }
grep -q "^R = .* = [0-9.]*" "$work/uniform.txt" && grep -q "^whole-run phase totals" "$work/uniform.txt" ||
  { cat "$work/uniform.txt"; fail "no R or phase totals in summarize.py's summary"; }

for cmd in "summarize_adaptive.py $work/plain" "summarize.py $work/plain.steps.csv"; do
  # shellcheck disable=SC2086
  out=$(/usr/bin/python3 "$src/bench/"$cmd 2>&1) && fail "$cmd accepted a run without the measurement"
  [ "$(printf '%s\n' "$out" | wc -l)" -eq 1 ] && [[ $out == *"Measure Contact Overhead = true"* ]] ||
    fail "$cmd: not one line naming the option: $out"
done
echo "bench summaries: OK"
