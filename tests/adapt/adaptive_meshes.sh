#!/usr/bin/env bash
# Checks the meshes of real adaptive runs with pure geometry (tools/check_adaptive_meshes.py,
# independent of the program and of p4est): at most one hanging node per cell edge (Algorithm 5.2)
# on every step's mesh, and no cell more than one level coarser than an overlapping cell of the
# previous or the next step's mesh (Algorithm 5.3). The membrane deck to t = 0.15 (graded meshes;
# contact from t = 0.0525), every step written so that written meshes are consecutive steps:
#   1. the paper's settings, 5 cycles (4 levels of refinement): the bounds are also reached (hanging
#      nodes exist, consecutive meshes differ by one level both ways; the uniform mesh must fail that);
#   2. with coarsening (Coarsening Fraction 0.3), 3 cycles: cycle 2's meshes must have cells
#      coarser than cycle 1's at the same step (the control without coarsening must have none);
#   3. Maximum Level = 2, 4 cycles: no cell above level 2, and level 2 is reached; Maximum Level = 1,
#      5 cycles: every cycle refines more (marking among the cells below the level).
# Usage: adaptive_meshes.sh SIGNORINI SOURCE_DIR WORK_DIR
set -euo pipefail
signorini=$1 src=$2 work=$3
check="/usr/bin/python3 $src/tools/check_adaptive_meshes.py"
rm -rf "$work" && mkdir -p "$work"
run() {  # basename, then --set arguments
  local name=$1
  shift
  "$signorini" --output-dir "$work" --set "Output/Basename=$name" --set 'Time Integration/Final Time=0.15' \
    --set 'Output/Exodus Interval=1' "$@" "$src/inputs/membrane.xml" > "$work/$name.log" 2>&1 ||
    { cat "$work/$name.log"; exit 1; }
}

run paper --set 'Adaptivity/Cycles=5'
$check "$work/paper" --graded
# Control: the initial (uniform) mesh of every step is not graded.
run uniform --set 'Adaptivity/Strategy=none'
if $check "$work/uniform" --graded > "$work/uniform-control.log"; then
  echo "control failed: the uniform mesh passed --graded"
  exit 1
fi
grep -q "VIOLATION: --graded: no edge has a hanging node" "$work/uniform-control.log" ||
  { cat "$work/uniform-control.log"; echo "control failed for another reason"; exit 1; }

run coarsening --set 'Adaptivity/Cycles=3' --set 'Adaptivity/Coarsening Fraction=0.3' --set 'Adaptivity/Write All Cycles=true'
$check "$work/coarsening" --coarser-than "$work/coarsening.cycle1" --in-every-step
run refining --set 'Adaptivity/Cycles=3' --set 'Adaptivity/Write All Cycles=true'
if $check "$work/refining" --coarser-than "$work/refining.cycle1" > "$work/control.log"; then
  echo "control failed: without coarsening, cells coarser than in the previous cycle were reported"
  cat "$work/control.log"
  exit 1
fi
grep -q "VIOLATION: no cell is coarser than in" "$work/control.log" || { cat "$work/control.log"; echo "control failed for another reason"; exit 1; }

run capped --set 'Adaptivity/Cycles=4' --set 'Adaptivity/Maximum Level=2'
$check "$work/capped" --max-level 2 | tee "$work/capped.check"
grep -q "largest level 2 " "$work/capped.check" || { echo "Maximum Level = 2 was not reached"; exit 1; }
# Marking spends the fraction on the cells that can still be refined: with Maximum Level = 1 every
# cycle refines (it used to mark cells at the level, refine nothing and repeat the cycle).
run level1 --set 'Adaptivity/Cycles=5' --set 'Adaptivity/Maximum Level=1' --set 'Output/Write Exodus=false'
/usr/bin/python3 - "$work/level1.cycles.csv" <<'PY'
import csv, sys
dofs = [int(r["total_dofs"]) for r in csv.DictReader(open(sys.argv[1]))]
print("Maximum Level = 1: total unknowns per cycle", dofs)
if len(dofs) != 5:
    sys.exit(f"{len(dofs)} cycles, not the deck's 5: growth not checked")
sys.exit(0 if all(a < b for a, b in zip(dofs, dofs[1:])) else "a cycle repeated the one before it")
PY
