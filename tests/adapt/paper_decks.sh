#!/usr/bin/env bash
# The paper's two adaptive decks, first two cycles (about 10 s): the first cycle that changes the
# mesh from step to step, estimator and transfer included, runs through the whole interval, and
# the cycle table is what the step tables add up to: per cycle N + 1 steps (N = T / k from the
# deck), total_dofs the sum of the steps' dofs over steps 1..N, eta their maximum eta, and cycle 1,
# refined without coarsening, has more unknowns than cycle 0.
# Usage: paper_decks.sh SIGNORINI SOURCE_DIR WORK_DIR
set -euo pipefail
signorini=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
"$signorini" --output-dir "$work" --set Adaptivity/Cycles=2 --set "Output/Write Exodus=false" \
  "$src/inputs/membrane.xml" "$src/inputs/bar.xml"
/usr/bin/python3 - "$work" <<'PY'
import csv, sys
work = sys.argv[1]
def table(path):
    with open(path) as f:
        return list(csv.DictReader(f))
failed = []
for base, steps in (("membrane", 400), ("bar", 250)):  # 1.0 / 0.0025 and 2.5e-3 / 1e-5
    cycles = table(f"{work}/{base}.cycles.csv")
    if len(cycles) != 2:
        failed.append(f"{base}: {len(cycles)} cycles, not 2")
        continue
    for l, name in enumerate((f"{base}.cycle0.steps.csv", f"{base}.steps.csv")):
        rows = table(f"{work}/{name}")
        if [int(r["step"]) for r in rows] != list(range(steps + 1)):
            failed.append(f"{name}: steps are not 0..{steps}")
            continue
        dofs = sum(int(r["dofs"]) for r in rows[1:])
        eta = max(float(r["eta"]) for r in rows[1:])
        if int(cycles[l]["total_dofs"]) != dofs:
            failed.append(f"{base} cycle {l}: total_dofs {cycles[l]['total_dofs']}, the steps add up to {dofs}")
        if float(cycles[l]["eta"]) != eta:
            failed.append(f"{base} cycle {l}: eta {cycles[l]['eta']}, the steps' maximum is {eta!r}")
    if not int(cycles[1]["total_dofs"]) > int(cycles[0]["total_dofs"]):
        failed.append(f"{base}: cycle 1 has no more unknowns than cycle 0")
if failed:
    print("FAILED: " + "; ".join(failed))
    sys.exit(1)
print("paper decks, two cycles: step and cycle tables agree")
PY
