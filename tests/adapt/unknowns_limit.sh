#!/usr/bin/env bash
# Adaptivity/Unknowns Limit = do not exceed counts a cycle's total unknowns on its meshes before
# it runs, and that count is the one the cycle has when it runs: for the membrane (graded meshes,
# hanging nodes, compact forests) and the bar (two unknowns per node) on 2 ranks, a run with
# Maximum Total Unknowns one below cycle 2's total (from a run without a limit) ends with cycle 1,
# names cycle 2's total exactly, and its results are cycle 1's of the run without a limit (the step
# tables equal but for the timings; the cycle table's rows 0 and 1 likewise). A limit equal to
# cycle 2's total runs cycle 2 (about 15 s).
# Usage: unknowns_limit.sh SIGNORINI MPIEXEC SOURCE_DIR WORK_DIR
source "$(dirname "$0")/../dynamics/run_helpers.sh" "$@"
quiet=(--set "Output/Progress Interval=100000" --set "Output/Write Exodus=false" --set "Adaptivity/Cycles=3")
for deck in membrane:0.2 bar:1e-4; do
  name=${deck%%:*} final=${deck#*:}
  args=("${quiet[@]}" --set "Time Integration/Final Time=$final")
  run "$name-free" 2 "${args[@]}" "$src/inputs/$name.xml"
  total2=$($py -c "import csv,sys; print([r for r in csv.DictReader(open(sys.argv[1]))][2]['total_dofs'])" \
             "$work/$name-free/$name.cycles.csv")
  limit=(--set "Adaptivity/Unknowns Limit=do not exceed")
  run "$name-below" 2 "${args[@]}" "${limit[@]}" --set "Adaptivity/Maximum Total Unknowns=$((total2 - 1))" "$src/inputs/$name.xml"
  grep -q "the run ends with cycle 1: cycle 2 would have $total2 total unknowns, above Adaptivity/Maximum Total Unknowns = $((total2 - 1))" \
    "$work/$name-below.log" || { cat "$work/$name-below.log"; fail "$name: the message naming cycle 2's total $total2"; }
  $py - "$work/$name-free" "$work/$name-below" "$name" <<'PY' || fail "$name: the limited run's results are not cycle 1's"
import sys
from step_tables import fail, table
free, below, name = sys.argv[1:]
def same(a, b, what):
    keys = [k for k in a[0] if not (k.startswith("time_") or k == "wall_seconds")]
    if len(a) != len(b) or any(ra[k] != rb[k] for ra, rb in zip(a, b) for k in keys):
        fail(f"{name}: {what} differ")
same(table(f"{free}/{name}.cycle1.steps.csv"), table(f"{below}/{name}.steps.csv"), "cycle 1's step tables")
cycles = table(f"{below}/{name}.cycles.csv")
if len(cycles) != 2:
    fail(f"{name}: the limited run has {len(cycles)} cycles, not 2")
same(table(f"{free}/{name}.cycles.csv")[:2], cycles, "the cycle tables' rows 0 and 1")
PY
  run "$name-at" 2 "${args[@]}" "${limit[@]}" --set "Adaptivity/Maximum Total Unknowns=$total2" "$src/inputs/$name.xml"
  grep -q "cycle 2: total unknowns $total2," "$work/$name-at.log" || { cat "$work/$name-at.log"; fail "$name: cycle 2 at the limit did not run"; }
done
echo "unknowns limit: ok"
