#!/usr/bin/env bash
# The step tables' energy balance (external_work, contact_work; runs on one mesh):
#  - with Alpha = 1/2, newmark_energy(n) = newmark_energy(0) + external_work(n) + contact_work(n) in
#    every step (check_energy_balance.py): an aluminium block dropped onto a floor at the deck's
#    Time Step and at a tenth of it, the bar of paper Example 6.2 under its load on 2 ranks (loads
#    and contact both do work), the membrane through contact with Beta = 1/2 and 1/4 and under a
#    body force that varies in time and space, a block lifted by a floor that moves (no warning:
#    the obstacle's own work);
#  - the block's impact at a Time Step longer than the wave's transit gains more than 30% of the
#    initial energy from the contact, and the run warns; at a tenth of the step under 5%, no warning;
#  - Contact Force = implicit (with Beta = 1/4): the balance holds, and the contact never does positive
#    work (contact_work never rises beyond the tolerance) and dissipates at the block's impact (the
#    floor 0.53 mm below, reached inside a step; 2 ranks); the membrane gains nothing either, also
#    with the predictor projection (Deuflhard, Krause and Ertel's contact-stabilised step);
#  - the block resting on the floor under its weight: over 600 steps the mean contact_force is its
#    weight (momentum balance) with either contact force and with the implicit one and the predictor
#    projection, which checks the implicit one's physical scale (alpha times the step equation's);
#  - controls: Alpha = 0.6 breaks the balance (the relation is that of alpha = 1/2), and so do a
#    table whose contact_work is zeroed, one whose external_work is halved and one whose
#    contact_work lags a step;
#  - adaptive runs (a mesh per step) have no such columns.
# Usage: energy_balance.sh SIGNORINI MPIEXEC SOURCE_DIR WORK_DIR
# (MPIEXEC: the launcher of cmake/SignoriniTesting.cmake; run_helpers.sh reads the arguments.)
source "$(dirname "$0")/run_helpers.sh" "$@"
check="$py $src/tests/dynamics/check_energy_balance.py"
membrane=(--set "Time Integration/Final Time=1.2" --set "Output/Write Exodus=false" "$decks/good.xml")
run block 1 "$decks/block-on-floor.xml"
run block_fine 1 --set "Time Integration/Time Step=1e-6" "$decks/block-on-floor.xml"
run bar 2 --set "Adaptivity/Strategy=none" --set "Time Integration/Final Time=1e-3" --set "Output/Write Exodus=false" \
  "$src/inputs/bar.xml"
run membrane 1 "${membrane[@]}"
run membrane_quarter 1 --set "Time Integration/Beta=0.25" "${membrane[@]}"
run membrane_alpha 1 --set "Time Integration/Alpha=0.6" --set "Time Integration/Beta=0.4" "${membrane[@]}"
run adaptive 1 --set "Adaptivity/Strategy=fixed fraction" --set "Adaptivity/Cycles=2" "${membrane[@]}"
implicit=(--set "Time Integration/Contact Force=implicit" --set "Time Integration/Beta=0.25")
projection=(--set "Time Integration/Contact Stabilisation=predictor projection")
run block_implicit 2 "${implicit[@]}" --set "Problem/Obstacle=-0.00053" "$decks/block-on-floor.xml"
run membrane_implicit 1 "${implicit[@]}" "${membrane[@]}"
run membrane_implicit_projected 1 "${implicit[@]}" "${projection[@]}" "${membrane[@]}"
resting=(--set "Problem/Initial Velocity=0, 0" --set "Problem/Obstacle=0" --set "Problem/Body Force=0, -27173.7"
         --set "Time Integration/Final Time=6e-3" "$decks/block-on-floor.xml")  # rho g = 2770 kg/m^3 x 9.81 m/s^2: 135.87 N/m
run resting 1 "${resting[@]}"
run resting_implicit 1 "${implicit[@]}" "${resting[@]}"
run resting_implicit_projected 1 "${implicit[@]}" "${projection[@]}" "${resting[@]}"
run membrane_load 1 --set "Problem/Body Force=-2*sin(3*t)*x" "${membrane[@]}"
run lifted 1 --set "Problem/Initial Velocity=0, 0" --set "Problem/Obstacle=-0.0005 + 2*t" "$decks/block-on-floor.xml"

$check "$work/block/block-on-floor.steps.csv" 1e-7 || fail "block: energy balance"
$check "$work/block_fine/block-on-floor.steps.csv" 1e-7 || fail "block, Time Step 1e-6: energy balance"
$check "$work/bar/bar.steps.csv" 1e-7 || fail "bar on 2 ranks: energy balance"
$check "$work/membrane/good.steps.csv" 1e-6 || fail "membrane: energy balance"
$check "$work/membrane_quarter/good.steps.csv" 1e-6 || fail "membrane, Beta = 1/4: energy balance"
$check "$work/block_implicit/block-on-floor.steps.csv" 1e-7 || fail "block, implicit contact force: energy balance"
$check "$work/membrane_implicit/good.steps.csv" 1e-6 || fail "membrane, implicit contact force: energy balance"
$check "$work/resting/block-on-floor.steps.csv" 1e-7 || fail "resting block: energy balance"
$check "$work/resting_implicit/block-on-floor.steps.csv" 1e-7 || fail "resting block, implicit contact force: energy balance"
$check "$work/membrane_load/good.steps.csv" 1e-6 || fail "membrane under a body force varying in time: energy balance"
$check "$work/lifted/block-on-floor.steps.csv" 1e-7 || fail "block lifted by a moving floor: energy balance"

$py - "$work" <<'PY' || exit 1
import sys
from step_tables import fail, table
work = sys.argv[1]
def gain(name):
    t = table(f"{work}/{name}/block-on-floor.steps.csv")
    return float(t[-1]["contact_work"]) / float(t[0]["newmark_energy"])
def warned(name):
    return "the contact did work" in open(f"{work}/{name}.log").read()
coarse, fine = gain("block"), gain("block_fine")
if not (coarse > 0.3 and warned("block")):
    fail(f"block: the contact's work is {coarse:.3g} of the initial energy (more than 0.3 expected), warned: {warned('block')}")
if not (0 < fine < 0.05 and not warned("block_fine")):
    fail(f"block, Time Step 1e-6: the contact's work is {fine:.3g} of the initial energy (0 to 0.05 expected), "
         f"warned: {warned('block_fine')}")
bar = table(f"{work}/bar/bar.steps.csv")
e0, w_ext, w_c = (float(bar[0]["newmark_energy"]), float(bar[-1]["external_work"]), float(bar[-1]["contact_work"]))
load = table(f"{work}/membrane_load/good.steps.csv")
if not (float(load[-1]["external_work"]) != 0 and any(int(r["active"]) > 0 for r in load)):
    fail("membrane_load: no external work or no contact")
lifted = table(f"{work}/lifted/block-on-floor.steps.csv")
if not (float(lifted[-1]["contact_work"]) > 0.05 * float(lifted[-1]["newmark_energy"]) and not warned("lifted")):
    fail(f"lifted: contact_work {lifted[-1]['contact_work']} (the floor's work: most of the energy), warned: {warned('lifted')}")
if not (abs(w_ext) > 10 * e0 and w_c != 0 and any(int(r["active"]) > 0 for r in bar)):
    fail(f"bar: external_work {w_ext}, contact_work {w_c}, newmark_energy(0) {e0}: loads and contact were to do work")
membrane = table(f"{work}/membrane/good.steps.csv")
if not any(int(r["active"]) > 0 for r in membrane) or float(membrane[-1]["contact_work"]) == 0:
    fail("the membrane run has no contact work: the balance was not checked through contact")
for f in (f"{work}/adaptive/good.steps.csv", f"{work}/adaptive/good.cycle0.steps.csv"):
    header = table(f)[0]
    if "external_work" in header or "contact_work" in header:
        fail(f"{f}: work columns in an adaptive run")
for name, base, lost in (("block_implicit", "block-on-floor", 0.1), ("membrane_implicit", "good", 0.0)):
    t = table(f"{work}/{name}/{base}.steps.csv")
    e = [float(r["newmark_energy"]) for r in t]
    w = [float(r["contact_work"]) for r in t]
    rise = max(w[n] - w[n - 1] for n in range(1, len(w))) / max(e)
    if not (rise <= 1e-9 and w[-1] < -lost * e[0] and w[-1] < 0 and e[-1] <= e[0] * (1 + 1e-7)
            and any(int(r["active"]) > 0 for r in t)):
        fail(f"{name}: with the implicit contact force the contact's work rises by {rise:.3g} of the energy in a "
             f"step and ends at {w[-1]:.6g}; newmark_energy {e[0]:.6g} -> {e[-1]:.6g}")
    if warned(name):
        fail(f"{name}: a warning about the contact's work with the implicit contact force")
t = table(f"{work}/membrane_implicit_projected/good.steps.csv")
e = [float(r["newmark_energy"]) for r in t]
if not max(e) <= e[0] * (1 + 1e-7):
    fail(f"membrane_implicit_projected: newmark_energy rises from {e[0]:.6g} to {max(e):.6g}")
for name in ("resting", "resting_implicit", "resting_implicit_projected"):
    force = [float(r["contact_force"]) for r in table(f"{work}/{name}/block-on-floor.steps.csv")[1:]]
    mean = sum(force) / len(force)
    if not abs(mean / 135.87 - 1) <= 0.01:
        fail(f"{name}: mean contact_force {mean:.6g} N/m over {len(force)} steps, the weight is 135.87 N/m")
print(f"block: contact work {coarse:.3g} of the initial energy (warned), {fine:.3g} at a tenth of the step; "
      f"bar: external work {w_ext:.6g}, contact work {w_c:.6g}; implicit contact force: no energy gained")
PY

# Controls: Alpha = 0.6, a zeroed contact_work and a halved external_work break the balance.
$py - "$work" <<'PY'
import sys
from step_tables import write_altered
work = sys.argv[1]
for source, column, factor, name in (("block/block-on-floor", "contact_work", 0.0, "no_contact_work"),
                                      ("bar/bar", "external_work", 0.5, "half_external_work"),
                                      ("block/block-on-floor", "contact_work", None, "late_contact_work")):
    write_altered(f"{work}/{source}.steps.csv", column, factor, f"{work}/{name}.csv")  # factor None: one step late
PY
for table in "$work/membrane_alpha/good.steps.csv" "$work/no_contact_work.csv" "$work/half_external_work.csv" \
    "$work/late_contact_work.csv"; do
  $check "$table" 1e-6 > "$work/control.log" && fail "control: the checker passed $table"
  grep -q "newmark_energy - newmark_energy(0) - external_work - contact_work = " "$work/control.log" ||
    { cat "$work/control.log"; fail "control $table: another failure"; }
done
echo "PASS"
