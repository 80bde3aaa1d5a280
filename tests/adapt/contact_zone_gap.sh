#!/usr/bin/env bash
# Adaptivity/Contact Zone Gap resolves a contact zone the estimate cannot foresee: an elastic block
# falling rigidly onto a curved floor (tests/driver/decks/rigid-drop.xml, fixed fraction 20%, 2
# cycles) has a zero estimate before contact. Without the option cycle 1 refines only from
# cycle 0's first contact (step 111) on, meets there a body that the coarse step before let
# penetrate the finer segments, and gains more than 20% energy; with it (2e-4, the fall of 20 steps)
# cycle 1 finds the first contact in the step the uniformly refined mesh finds it, and the
# energy stays within 1% of E(0) (the uniform meshes keep it to 0.1%); with coarsening at the
# Maximum Level the zone stays refined in later cycles. Cycles are numbered from 0.
# Usage: contact_zone_gap.sh SIGNORINI SOURCE_DIR WORK_DIR
set -uo pipefail
signorini=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
run() {  # basename, [--set ...]
  local base=$1
  shift
  "$signorini" --output-dir "$work" --set "Output/Basename=$base" --set 'Output/Write Exodus=false' "$@" \
    "$src/tests/driver/decks/rigid-drop.xml" > "$work/$base.log" 2>&1 || { cat "$work/$base.log"; fail "$base"; }
}
run off
run on --set 'Adaptivity/Contact Zone Gap=2e-4'
run uniform --set 'Adaptivity/Strategy=uniform'
run coarsening --set 'Adaptivity/Contact Zone Gap=2e-4' --set 'Adaptivity/Coarsening Fraction=0.5' \
  --set 'Adaptivity/Maximum Level=2' --set 'Adaptivity/Cycles=4'
/usr/bin/python3 - "$work" <<'PY'
import sys
import numpy as np
work = sys.argv[1]
def summary(table):
    s = np.genfromtxt(f"{work}/{table}.steps.csv", delimiter=",", names=True)
    return int(s["step"][s["active"] > 0][0]), s["newmark_energy"].max() / s["newmark_energy"][0], int(s["dofs"].sum())
fails = []
coarse, _, _ = summary("off.cycle0")
off, off_gain, _ = summary("off")
on, on_gain, on_dofs = summary("on")
fine, fine_gain, fine_dofs = summary("uniform")
if not (on == fine < coarse):
    fails.append(f"first contact with the option in step {on}, on the uniformly refined mesh {fine}, on the deck's {coarse}")
if not on_gain < 1.01 or not fine_gain < 1.001:
    fails.append(f"largest Newmark energy / E(0): with the option {on_gain:.4f}, uniform {fine_gain:.4f}")
if not (off == coarse and off_gain > 1.2):
    fails.append(f"control: without the option first contact in step {off} (deck's mesh {coarse}), energy gain {off_gain:.4f}: "
                 "the test cannot fail")
# With coarsening and the Maximum Level reached, the contact zone's cells (whose indicators are 0
# before contact, so that they would be coarsened first) stay refined in every later cycle.
for table in ("coarsening.cycle1", "coarsening.cycle2", "coarsening"):
    first, gain, _ = summary(table)
    if first != fine or gain >= 1.02:
        fails.append(f"{table}: first contact in step {first} (uniformly refined: {fine}), energy gain {gain:.4f}")
print("\n".join(fails) or f"first contact in step {on} as on the uniform mesh ({fine_dofs} total unknowns; the option "
      f"{on_dofs}); energy {on_gain:.4f} E(0); without the option step {off}, {off_gain:.3f} E(0)")
sys.exit(1 if fails else 0)
PY
