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
# Inputs refused in one line before anything is printed: empty tables; a cycle table missing
# (summarize_adaptive.py); a driver log that is missing, a folder, or of another run (summarize.py: the
# adaptive run's log for the uniform run's table).
: > "$work/empty.steps.csv" && : > "$work/empty.cycles.csv"
cp "$work/membrane.cycles.csv" "$work/nocycle.cycles.csv" && cp "$work/membrane.steps.csv" "$work/nocycle.steps.csv"
level2=$work/membrane-level2.steps.csv
for cmd in "summarize_adaptive.py|$work/empty|$work/empty.cycles.csv: empty" \
    "summarize.py|$work/empty.steps.csv|$work/empty.steps.csv: empty" \
    "summarize_adaptive.py|$work/nocycle|$work/nocycle.cycle0.steps.csv: no such file" \
    "summarize.py|$level2 $work/nothing.log|$work/nothing.log: no such file" \
    "summarize.py|$level2 $work|$work: a directory, not a file" \
    "summarize.py|$level2 $work/adaptive.log|$work/adaptive.log: not the log of the run that wrote $level2"; do
  IFS='|' read -r script arguments message <<< "$cmd"
  # shellcheck disable=SC2086
  /usr/bin/python3 "$src/bench/$script" $arguments > "$work/refused.out" 2> "$work/refused.err" && fail "$script $arguments: accepted"
  [ ! -s "$work/refused.out" ] && [ "$(wc -l < "$work/refused.err")" -eq 1 ] &&
    grep -qF "$script: error: $message" "$work/refused.err" ||
    { cat "$work/refused.out" "$work/refused.err"; fail "$script $arguments: not one line '$message' before any output"; }
done
/usr/bin/python3 "$src/bench/summarize.py" --help | grep -q "^usage: summarize.py" || fail "summarize.py --help"
# The bench scripts, copied into a sandbox whose tools/build.sh and launcher (mpiexec: there is no
# build/CMakeCache.txt) are stubs: -h/--help print the header, each script names itself in its usage;
# SIGNORINI_NO_BUILD=0 builds; run-contact-bench.sh takes DECK from the caller's folder (a short real
# run); run-adaptive-bench.sh's arithmetic ratio leaves out the benchmark's own solves (time_unconstrained;
# its runs stubbed with the tables of the runs above).
box=$work/sandbox
mkdir -p "$box/bench" "$box/tools" "$box/build/src" "$box/stubs" "$box/caller"
cp "$src"/bench/*.sh "$src"/bench/*.py "$box/bench/"
cp "$src/tools/script_args.sh" "$src/tools/tool_errors.py" "$box/tools/"
printf '#!/usr/bin/env bash\necho build >> "%s"\n' "$box/build.calls" > "$box/tools/build.sh"
printf '#!/usr/bin/env bash\nshift 4\nexec "$@"\n' > "$box/stubs/mpiexec"  # -n N --oversubscribe --allow-run-as-root
cat > "$box/build/src/signorini" <<SH
#!/usr/bin/env bash
[ -n "\${CANNED:-}" ] || exec "$signorini" "\$@"
prev="" out="" name=""
for a in "\$@"; do
  case \$prev in --output-dir) out=\$a ;; --set) [[ \$a != Output/Basename=* ]] || name=\${a#Output/Basename=} ;; esac
  prev=\$a
done
from=\$CANNED/membrane
[[ \$name != adaptive-ordinary* ]] || from=\$CANNED/second
for f in "\$from".*csv; do cp "\$f" "\$out/\$name\${f#"\$from"}"; done
echo "signorini: cycle 0: canned"
echo "signorini: canned done"
SH
chmod +x "$box/stubs/mpiexec" "$box/build/src/signorini"
for s in run-contact-bench run-membrane-bench run-bar-bench run-adaptive-bench; do
  for h in -h --help; do
    bash "$box/bench/$s.sh" "$h" > "$work/$s-help.out" 2>&1 && grep -q "^Benchmark (not a test)" "$work/$s-help.out" &&
      ! grep -q "^#" "$work/$s-help.out" || { cat "$work/$s-help.out"; fail "$s.sh $h"; }
  done
done
for s in run-membrane-bench run-bar-bench; do
  bash "$box/bench/$s.sh" --bogus > "$work/$s-bad.out" 2>&1
  [ $? = 2 ] && grep -q "^usage: bash bench/$s.sh \[-np N\] (got: --bogus)" "$work/$s-bad.out" ||
    { cat "$work/$s-bad.out"; fail "$s.sh --bogus: not its own usage"; }
done
sed -e 's/"Refinement Level" type="int" value="[0-9]*"/"Refinement Level" type="int" value="1"/' \
  -e 's/"Final Time" type="double" value="[0-9.e-]*"/"Final Time" type="double" value="0.075"/' \
  "$src/bench/membrane-250k.xml" > "$box/caller/small.xml"
(cd "$box/caller" && PATH="$box/stubs:$PATH" SIGNORINI_NO_BUILD=0 bash "$box/bench/run-contact-bench.sh" small.xml) \
  > "$work/contact-bench.out" 2>&1 || { cat "$work/contact-bench.out"; fail "run-contact-bench.sh with a deck in the caller's folder"; }
grep -q "^R = " "$work/contact-bench.out" && grep -q "^whole-run phase totals" "$work/contact-bench.out" &&
  grep -q "^note: no build/CMakeCache.txt" "$work/contact-bench.out" || { cat "$work/contact-bench.out"; fail "run-contact-bench.sh: summary"; }
grep -qx build "$box/build.calls" 2> /dev/null || fail "run-contact-bench.sh with SIGNORINI_NO_BUILD=0 did not build"
# The canned tables: the second run (the ordinary arithmetic's stand-in) spends 40% of its wall time in
# the benchmark's solves and the first none, so that leaving them out or not gives ratios apart.
mkdir -p "$work/canned"
cp "$work"/membrane.*csv "$work"/second.*csv "$work/canned/"
expected=$(/usr/bin/python3 - "$work/canned" <<'PY'
import csv, sys
def scale(base, share):  # time_unconstrained = share of each cycle's wall_seconds
    with open(f"{sys.argv[1]}/{base}.cycles.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        r["time_unconstrained"] = repr(share * float(r["wall_seconds"]))
    with open(f"{sys.argv[1]}/{base}.cycles.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    return sum(float(r["wall_seconds"]) for r in rows), sum(float(r["time_unconstrained"]) for r in rows)
(wall0, extra0), (wall1, extra1) = scale("membrane", 0.0), scale("second", 0.4)
right, wrong = (wall0 - extra0) / (wall1 - extra1), wall0 / wall1
if not abs(right - wrong) > 0.1:
    sys.exit(f"the canned ratios {right:.2f} and {wrong:.2f} do not tell the formulas apart")
print(f"{wall0 - extra0:.1f} s against {wall1 - extra1:.1f} s: {right:.2f} times the time")
PY
) && [ -n "$expected" ] || fail "the canned tables of the arithmetic ratio: $expected"
(cd "$box/caller" && PATH="$box/stubs:$PATH" SIGNORINI_NO_BUILD=1 CANNED=$work/canned bash "$box/bench/run-adaptive-bench.sh") \
  > "$work/adaptive-bench.out" 2>&1 || { cat "$work/adaptive-bench.out"; fail "run-adaptive-bench.sh (stubbed runs)"; }
grep -qF "reproducible arithmetic: whole run without the benchmark's extra solves $expected" "$work/adaptive-bench.out" ||
  { cat "$work/adaptive-bench.out"; fail "run-adaptive-bench.sh: the arithmetic ratio is not $expected"; }
echo "bench summaries: OK"
