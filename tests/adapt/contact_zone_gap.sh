#!/usr/bin/env bash
# Adaptivity/Contact Zone Gap resolves a contact zone the estimate cannot foresee: an elastic block
# falling rigidly onto a curved floor (tests/driver/decks/rigid-drop.xml, fixed fraction 20%, 2
# cycles) has a zero estimate before contact. Without the option cycle 1 refines only from
# cycle 0's first contact (step 111) on, meets there a body that the coarse step before let
# penetrate the finer segments, and gains more than 20% energy; with it (2e-4, the fall of 20 steps)
# cycle 1 finds the first contact in the step the uniformly refined mesh finds it, and the
# energy stays within 1% of E(0) (the uniform meshes keep it to 0.1%); with coarsening at the
# Maximum Level the zone stays refined in later cycles. A block driven into a curved wall
# (tests/driver/decks/block-into-wall.xml, gap 1e-4 = the approach of 10 steps): the option takes
# the smallest gap of each segment, so every cycle keeps the energy within 2% of E(0) and finds
# the first contact earlier, the last within two steps of the exact step 50 (with each segment's
# mean gap, which stays positive while the block penetrates inside the segment, the energy grew
# 16-19 times; without the option 35-40 times, the control, with a warning that the estimate rose
# over the cycles). Cycles are numbered from 0.
# Usage: contact_zone_gap.sh SIGNORINI SOURCE_DIR WORK_DIR
set -uo pipefail
signorini=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
run_deck() {  # deck, basename, [--set ...]
  local deck=$1 base=$2
  shift 2
  "$signorini" --output-dir "$work" --set "Output/Basename=$base" --set 'Output/Write Exodus=false' "$@" \
    "$src/tests/driver/decks/$deck.xml" > "$work/$base.log" 2>&1 || { cat "$work/$base.log"; fail "$base"; }
}
run() { run_deck rigid-drop "$@"; }
run off
run on --set 'Adaptivity/Contact Zone Gap=2e-4'
run uniform --set 'Adaptivity/Strategy=uniform'
run coarsening --set 'Adaptivity/Contact Zone Gap=2e-4' --set 'Adaptivity/Coarsening Fraction=0.5' \
  --set 'Adaptivity/Maximum Level=2' --set 'Adaptivity/Cycles=4'
run_deck block-into-wall wall
run_deck block-into-wall wall-off --set 'Adaptivity/Contact Zone Gap=0'
# The estimate rising over the cycles draws a warning (without the option), and only then.
grep -q "warning: cycle 1's estimate .* is above cycle 0's" "$work/wall-off.log" ||
  { cat "$work/wall-off.log"; fail "no warning for an estimate that rose over the cycles"; }
# (The wall's surface slopes by up to 5.7 degrees at the block's corners, which draws its own warning.)
! grep -v "slopes across Contact Direction" "$work/wall.log" | grep -q "warning" ||
  { cat "$work/wall.log"; fail "a warning for a run whose estimate falls"; }
grep -q "slopes across Contact Direction" "$work/wall.log" || fail "the wall's slope drew no warning"
# The warning keeps the console's number format: the run's wall time after it still has decimals.
grep -Eq "done: .*, [0-9]+[.][0-9]+ s$" "$work/wall-off.log" ||
  { cat "$work/wall-off.log"; fail "the warning changed the number format of later output"; }
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
# The block into the wall: every cycle with the option, and the control without it.
wall = [summary(t) for t in ("wall.cycle0", "wall.cycle1", "wall.cycle2", "wall")]
for l, (first, gain, _) in enumerate(wall):
    if gain >= 1.02:
        fails.append(f"block into the wall, cycle {l}: largest Newmark energy {gain:.4f} E(0)")
    if l > 0 and first >= wall[l - 1][0]:
        fails.append(f"block into the wall, cycle {l}: first contact in step {first}, cycle {l - 1} in {wall[l - 1][0]}")
if not 50 <= wall[-1][0] <= 52:
    fails.append(f"block into the wall: the last cycle's first contact in step {wall[-1][0]}, the exact one 50")
_, wall_off_gain, _ = summary("wall-off")
if wall_off_gain < 2:
    fails.append(f"control: the block into the wall without the option gains only {wall_off_gain:.3f} E(0): the test cannot fail")
print("\n".join(fails) or f"first contact in step {on} as on the uniform mesh ({fine_dofs} total unknowns; the option "
      f"{on_dofs}); energy {on_gain:.4f} E(0); without the option step {off}, {off_gain:.3f} E(0); the block into the "
      f"wall: first contact in steps {[w[0] for w in wall]}, energy at most {max(w[1] for w in wall):.4f} E(0) "
      f"({wall_off_gain:.1f} without the option)")
sys.exit(1 if fails else 0)
PY
