#!/usr/bin/env bash
# The step tables' reaction forces (reaction_force: the rows that the Dirichlet elimination drops)
# and momentum (runs on one mesh) satisfy the momentum balance of the Newmark scheme in every step
# (check_momentum_balance.py: momentum(n) - momentum(n-1) = k ((1 - alpha) G(n-1) + alpha G(n)),
# G = applied_load + contact force + reaction), to the solves' tolerance, with the applied_load
# columns equal to the loads' resultant computed by hand (to 1e-9):
#  - the membrane through contact (clamped left, contact right), also with Alpha = 0.6;
#  - the membrane under a body force varying in time and space and a traction on its top edge,
#    both non-zero on the clamped edge (their shares there are the support's);
#  - the membrane clamped along its bottom with the contact on its right side, whose first segment
#    ends at the clamped corner and is pressed (its contact force there is carried by the support:
#    without that share the balance misses by 4.5% of the largest force), with consistent and with
#    lumped boundary mass (the lumped rows keep their couplings to the clamped corner);
#  - the bar of paper Example 6.2 under its load on 2 ranks (elasticity, two components);
#  - the block on the floor held in x along its left side (a roller) under a traction on its top that
#    varies in time and along x, both components non-zero at the roller's corner, on 2 ranks;
#  - the contact stabilisation's projected predictor (the clamped corner run);
#  - the block dropped onto the floor: no Dirichlet conditions, no reaction_force column;
#  - the block spinning freely about its centre at 100 rad/s (no force at all): its angular momentum
#    is rho I_p omega = 2770 x 0.1 x 0.05 x (0.1^2 + 0.05^2) / 12 x 100 = 1.4427 N m s/m at t = 0 (Q1
#    holds the rigid rotation exactly) and stays so (to 1e-9), its momentum 0;
#  - elasticity's angular momentum about Output/Moment Point in every elastic run (the default origin,
#    and other points), with applied_moment equal to the loads' moment computed by hand: a block
#    clamped along its left side pressed onto the floor under a body force varying in time, with lumped
#    boundary mass, on 2 ranks (every contact segment pressed, the first ending at the clamped corner:
#    without the contact's share of the held rows the angular balance misses by 7.5%, without the
#    lumping in M r by 3e-4);
#  - a block hanging from its clamped top under its weight (no contact): the mean reaction over 600
#    steps is its weight, 27173.7 N/m^3 x 0.005 m^2 = 135.87 N/m upwards, and the mean reaction
#    moment about the origin balances the weight's, 135.87 N/m x 0.05 m = 6.7934 N m/m clockwise;
#  - controls: the Alpha = 0.6 table checked as Alpha = 1/2, a zeroed reaction_force, a reaction_force
#    one step late, a halved momentum and a halved applied_load (against --load, and in the balance),
#    a halved angular_momentum, a zeroed reaction_moment and a halved applied_moment (against
#    --applied-moment) fail the checker;
#  - adaptive runs have reaction_force and momentum columns; a problem without loads has no
#    applied_load column;
#  - adaptive runs of a free body (the disc of tests/driver/decks/disc-drop.xml on a 10 degree slope,
#    cycle 1 with 49 meshes and 76 steps in contact): the L2 projection between the step meshes keeps
#    m . v and (M r) . v, since constants and the rigid rotation lie in every step's space, so the
#    linear and angular momentum balance hold through the mesh changes as on one mesh (to 1e-7);
#    control: nodal interpolation breaks them (by 1e-2 of the largest |k G|).
# Usage: momentum_balance.sh SIGNORINI MPIEXEC SOURCE_DIR WORK_DIR
# (MPIEXEC: the launcher of cmake/SignoriniTesting.cmake; run_helpers.sh reads the arguments.)
source "$(dirname "$0")/run_helpers.sh" "$@"
check="$py $src/tests/dynamics/check_momentum_balance.py"
membrane=(--set "Time Integration/Final Time=1.2" --set "Output/Write Exodus=false" "$decks/good.xml")
corner=(--set "Mesh/Boundary Segments/clamped=bottom" --set "Problem/Obstacle=-0.05"
        --set "Problem/Initial Velocity=-sin(pi*x/2)*sin(pi*y/2)")
run membrane 1 "${membrane[@]}"
run membrane_alpha 1 --set "Time Integration/Alpha=0.6" --set "Time Integration/Beta=0.4" "${membrane[@]}"
run membrane_loaded 1 --set "Problem/Body Force=1 - 2*sin(3*t)*x" --set "Mesh/Boundary Segments/loaded=top" \
  --set "Problem/Neumann Segments=loaded" --set "Problem/Neumann Data=2*(1 + t) + cos(t)*x" "${membrane[@]}"
run corner 1 "${corner[@]}" "${membrane[@]}"
run corner_lumped 1 "${corner[@]}" --set "Contact/Boundary Mass=lumped" "${membrane[@]}"
run corner_projected 1 "${corner[@]}" --set "Time Integration/Contact Stabilisation=predictor projection" "${membrane[@]}"
run bar 2 --set "Adaptivity/Strategy=none" --set "Time Integration/Final Time=1e-3" --set "Output/Write Exodus=false" \
  "$src/inputs/bar.xml"
run block 1 "$decks/block-on-floor.xml"
run spin 1 --set "Problem/Contact Segments=" --set "Problem/Obstacle=" --set "Time Integration/Final Time=2e-4" \
  --set "Problem/Initial Velocity=-100*(y - 0.025), 100*(x - 0.05)" "$decks/block-on-floor.xml"
run roller 2 --set "Mesh/Boundary Segments/left=left" --set "Mesh/Boundary Segments/top=top" \
  --set "Problem/Dirichlet X Segments=left" --set "Problem/Neumann Segments=top" --set "Output/Moment Point=0.05, 0.1" \
  --set "Problem/Neumann Data=-1e5*(1 + 1000*t), 2e5*(x - 0.2)" "$decks/block-on-floor.xml"
run hanging 1 --set "Problem/Initial Velocity=0, 0" --set "Problem/Contact Segments=" --set "Problem/Obstacle=" \
  --set "Mesh/Boundary Segments/floor=top" --set "Problem/Dirichlet Segments=floor" \
  --set "Problem/Body Force=0, -27173.7" --set "Time Integration/Final Time=6e-3" "$decks/block-on-floor.xml"
run clamped 2 --set "Mesh/Boundary Segments/left=left" --set "Problem/Dirichlet Segments=left" \
  --set "Contact/Boundary Mass=lumped" --set "Problem/Initial Velocity=0, 0" --set "Problem/Obstacle=0" \
  --set "Problem/Body Force=0, -3e6*(1 + sin(2e4*t))" --set "Output/Moment Point=0.1, 0.05" "$decks/block-on-floor.xml"
run adaptive 1 --set "Adaptivity/Strategy=fixed fraction" --set "Adaptivity/Cycles=2" "${membrane[@]}"
slope=(--set "Adaptivity/Contact Zone Gap=1e-5" --set "Output/Progress Interval=100000"
       --set "Problem/Obstacle=-0.05/cos(10*_pi/180) - 2e-5 + x*tan(10*_pi/180) - y")
run slope 1 "${slope[@]}" "$decks/disc-drop.xml"
run slope_interpolated 1 "${slope[@]}" --set "Adaptivity/Transfer=interpolation" "$decks/disc-drop.xml"

$check "$work/membrane/good.steps.csv" 1e-6 || fail "membrane: momentum balance"
$check "$work/membrane_alpha/good.steps.csv" 1e-6 --alpha 0.6 || fail "membrane, Alpha = 0.6: momentum balance"
$check "$work/membrane_loaded/good.steps.csv" 1e-6 "--load=1 - sin(3*t) + 2*(1 + t) + 0.5*cos(t)" ||
  fail "membrane under a body force and a traction: momentum balance"
$check "$work/corner/good.steps.csv" 1e-6 || fail "membrane clamped at the contact's end: momentum balance"
$check "$work/corner_lumped/good.steps.csv" 1e-6 || fail "the same with lumped boundary mass: momentum balance"
$check "$work/corner_projected/good.steps.csv" 1e-6 || fail "the same with the predictor projection: momentum balance"
# the traction's moment about (0.05, 0.1): int_0^0.1 (x - 0.05) q_y dx - (0.05 - 0.1) int_0^0.1 q_x dx
$check "$work/roller/block-on-floor.steps.csv" 1e-7 "--load=-1e5*(1 + 1000*t)*0.1" "--load=2e5*(0.005 - 0.02)" --contact 1:+1 \
  "--applied-moment=2e5*(0.1**3/3 - 0.25*0.1**2/2 + 0.01*0.1) - 500*(1 + 1000*t)" ||
  fail "block on a roller under a traction on 2 ranks: momentum balance"
# the traction -3.75e7 N/m^2 on x in [0.1, 0.2]: moment -3.75e7 (0.2^2 - 0.1^2) / 2 about the origin
$check "$work/bar/bar.steps.csv" 1e-7 --load 0 "--load=-3.75e7*0.1" --contact 1:+1 --applied-moment=-562500 ||
  fail "bar on 2 ranks: momentum balance"
# the body force -3e6 (1 + sin(2e4 t)) N/m^3 on [0, 0.1] x [0, 0.05], its moment about (0.1, 0.05)
$check "$work/clamped/block-on-floor.steps.csv" 1e-7 --load 0 "--load=-3e6*(1 + sin(2e4*t))*0.005" --contact 1:+1 \
  "--applied-moment=3e6*(1 + sin(2e4*t))*0.05*0.1**2/2" || fail "block clamped at its side on the floor: momentum balance"
$check "$work/block/block-on-floor.steps.csv" 1e-7 --free --contact 1:+1 || fail "block: momentum balance"
$check "$work/hanging/block-on-floor.steps.csv" 1e-7 --load 0 "--load=-27173.7*0.1*0.05" \
  "--applied-moment=-27173.7*0.05*0.1**2/2" || fail "hanging block: momentum balance"

$py - "$work" <<'PY' || exit 1
import sys
from step_tables import fail, table
work = sys.argv[1]
for name in ("membrane", "membrane_alpha", "membrane_loaded", "corner", "corner_lumped", "corner_projected"):
    t = table(f"{work}/{name}/good.steps.csv")
    if not (any(int(r["active"]) > 0 for r in t) and max(abs(float(r["reaction_force"])) for r in t) > 0):
        fail(f"{name}: no contact or no reaction: the balance was not checked through both")
roller = table(f"{work}/roller/block-on-floor.steps.csv")
if not (any(int(r["active"]) > 0 for r in roller) and max(abs(float(r["reaction_force_x"])) for r in roller) > 1e3
        and all(float(r["reaction_force_y"]) == 0 for r in roller)):
    fail("roller: no contact, no reaction in x, or a reaction in y (the roller holds x only)")
bar = table(f"{work}/bar/bar.steps.csv")
if not (any(int(r["active"]) > 0 for r in bar) and max(abs(float(r["reaction_force_x"])) for r in bar) > 1e4):
    fail("bar: no contact or no horizontal reaction")
clamped = table(f"{work}/clamped/block-on-floor.steps.csv")
if not (max(int(r["active"]) for r in clamped) == 8 and max(abs(float(r["contact_moment"])) for r in clamped) > 100):
    fail("clamped block: not every contact segment pressed, or no contact moment")
spin = table(f"{work}/spin/block-on-floor.steps.csv")
L0 = 2770 * 0.1 * 0.05 * (0.1 ** 2 + 0.05 ** 2) / 12 * 100
if not (abs(float(spin[0]["angular_momentum"]) / L0 - 1) <= 1e-9 and
        all(abs(float(r["angular_momentum"]) / L0 - 1) <= 1e-9 for r in spin)):
    fail(f"spinning block: angular_momentum {spin[0]['angular_momentum']} .. {spin[-1]['angular_momentum']}, "
         f"rho I_p omega = {L0!r}")
# its linear momentum is 0: against the mass times the mean speed, 2770 x 0.005 x 2.79 = 38.6 N s/m
if not all(abs(float(r[c])) <= 1e-9 * 38.6 for r in spin for c in ("momentum_x", "momentum_y")):
    fail("spinning block: a linear momentum")
hanging_rows = table(f"{work}/hanging/block-on-floor.steps.csv")[1:]
hanging = [float(r["reaction_force_y"]) for r in hanging_rows]
mean = sum(hanging) / len(hanging)
if not abs(mean / 135.87 - 1) <= 0.01:
    fail(f"hanging block: mean reaction_force_y {mean:.6g} N/m over {len(hanging)} steps, its weight is 135.87 N/m")
moment = sum(float(r["reaction_moment"]) for r in hanging_rows) / len(hanging_rows)
if not abs(moment / 6.793425 - 1) <= 0.01:
    fail(f"hanging block: mean reaction_moment {moment:.6g} N m/m, the weight's moment is -6.7934 N m/m")
if any(c.startswith("reaction_force") for c in table(f"{work}/block/block-on-floor.steps.csv")[0]):
    fail("block: a reaction_force column without Dirichlet conditions")
for f in (f"{work}/block/block-on-floor.steps.csv", f"{work}/membrane/good.steps.csv"):
    if any(c.startswith("applied_load") for c in table(f)[0]):
        fail(f"{f}: an applied_load column without loads")
for f in (f"{work}/adaptive/good.steps.csv", f"{work}/adaptive/good.cycle0.steps.csv"):
    header = table(f)[0]
    if "reaction_force" not in header or "momentum" not in header:
        fail(f"{f}: an adaptive run's table has no {'reaction_force' if 'reaction_force' not in header else 'momentum'}")
slope = table(f"{work}/slope/disc-drop.steps.csv")
if len({r["dofs"] for r in slope}) < 10 or sum(int(r["active"]) > 0 for r in slope) < 10:
    fail("the disc's adaptive cycle: fewer than 10 meshes or steps in contact, the transfers were not checked")
print(f"hanging block: mean reaction {mean:.6g} N/m (weight 135.87 N/m), moment {moment:.6g} N m/m (6.7934)")
PY

$check "$work/slope/disc-drop.steps.csv" 1e-7 --free --contact 1:+1 || fail "the disc's adaptive cycle: momentum balance"
$check "$work/slope/disc-drop.cycle0.steps.csv" 1e-7 --free --contact 1:+1 || fail "the disc's cycle 0: momentum balance"
$check "$work/slope_interpolated/disc-drop.steps.csv" 1e-7 --free --contact 1:+1 > "$work/control.log" &&
  fail "control: nodal interpolation kept the disc's momentum"

# Controls: the balance of Alpha = 0.6 is not that of 1/2; a zeroed, late or halved column breaks it.
$py - "$work" <<'PY'
import sys
from step_tables import write_altered
work = sys.argv[1]
for source, column, factor, name in (("corner/good", "reaction_force", 0.0, "no_reaction"),
                                      ("membrane/good", "reaction_force", None, "late_reaction"),
                                      ("bar/bar", "momentum_y", 0.5, "half_momentum"),
                                      ("bar/bar", "applied_load_y", 0.5, "half_load"),
                                      ("bar/bar", "angular_momentum", 0.5, "half_angular"),
                                      ("clamped/block-on-floor", "reaction_moment", 0.0, "no_reaction_moment"),
                                      ("bar/bar", "applied_moment", 0.5, "half_moment")):
    write_altered(f"{work}/{source}.steps.csv", column, factor, f"{work}/{name}.csv")  # factor None: one step late
PY
for control in "$work/membrane_alpha/good.steps.csv" "$work/no_reaction.csv" "$work/late_reaction.csv" \
    "$work/half_momentum.csv"; do
  loads=()
  case $control in *half_momentum*) loads=(--load 0 "--load=-3.75e7*0.1" --contact 1:+1) ;; esac
  $check "$control" 1e-6 "${loads[@]}" > "$work/control.log" && fail "control: the checker passed $control"
  grep -q "changed by k ((1 - alpha) G(n-1) + alpha G(n))" "$work/control.log" ||
    { cat "$work/control.log"; fail "control $control: another failure"; }
done
$check "$work/half_load.csv" 1e-6 --load 0 "--load=-3.75e7*0.1" --contact 1:+1 > "$work/control.log" &&
  fail "control: the checker passed a halved applied_load_y"
grep -q "applied_load_y is .*, --load gives" "$work/control.log" || { cat "$work/control.log"; fail "control half_load: another failure"; }
$check "$work/half_load.csv" 1e-6 --contact 1:+1 > "$work/control.log" && fail "control: the balance held with a halved applied_load_y"
$py -c "import csv, sys; r = list(csv.DictReader(open(sys.argv[1]))); f = [c for c in r[0] if not c.startswith('applied_load')]
w = csv.DictWriter(open(sys.argv[2], 'w', newline=''), fieldnames=f, extrasaction='ignore'); w.writeheader(); w.writerows(r)" \
  "$work/bar/bar.steps.csv" "$work/no_load_column.csv"
$check "$work/no_load_column.csv" 1e-6 --load 0 "--load=-3.75e7*0.1" --contact 1:+1 > "$work/control.log" &&
  fail "control: the checker passed --load on a table without applied_load"
grep -q -- "--load given, but no column applied_load_x, applied_load_y" "$work/control.log" ||
  { cat "$work/control.log"; fail "control no_load_column: another failure"; }
for control in half_angular no_reaction_moment; do
  $check "$work/$control.csv" 1e-6 --contact 1:+1 > "$work/control.log" && fail "control: the checker passed $control"
  grep -q "angular_momentum changed by k ((1 - alpha) G_M(n-1) + alpha G_M(n))" "$work/control.log" ||
    { cat "$work/control.log"; fail "control $control: another failure"; }
done
$check "$work/half_moment.csv" 1e-6 --contact 1:+1 --applied-moment=-562500 > "$work/control.log" &&
  fail "control: the checker passed a halved applied_moment"
grep -q "applied_moment is .*, --applied-moment gives" "$work/control.log" ||
  { cat "$work/control.log"; fail "control half_moment: another failure"; }
echo "PASS"
