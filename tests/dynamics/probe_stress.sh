#!/usr/bin/env bash
# Output/Probe Fields with sigma: the stress at the probes (elasticity).
#  - an elastic block in a uniform strain state at t = 0 (u0 linear, which the initial projection
#    reproduces): every probe, inside a cell, on a cell edge, at a node where four cells meet and at
#    the body's corners, reads the exact stress sigma = lambda tr(eps) I + 2 mu eps, sigma_zz =
#    lambda tr(eps) and von Mises, to 1e-9;
#  - after the block has started to vibrate, a probe at a cell's centre reads the Exodus file's cell
#    stress of that cell (the same quantity, two outputs) in every written step;
#  - the Exodus cell strains eps_xx, eps_yy, eps_xy are the uniform strain at t = 0 in every cell, and
#    cell by cell the cell stresses in every written step (Hooke's law, to 1e-9);
#  - with Output/Stress Region, max_von_mises is the largest cell stress among the cells whose centre
#    lies in the region, with the same place rule (2 ranks), and differs from the whole body's;
#  - 2 ranks give the same probe stresses as 1 rank to 1e-9 in every step (the node probe lies on the
#    ranks' boundary: its mean takes cells of both ranks);
#  - the list may come in any order and spacing ("sigma,v , u" gives u, v and the stress);
#  - a probe outside the body by less than the locator's tolerance stays found on refined meshes;
#  - the step tables' max_von_mises (every elasticity run) is the uniform strain's von Mises stress at
#    step 0, the largest cell von_mises of the Exodus file in every written step, and its place
#    (max_von_mises_at_x, _y) the centre with the smallest x, then y, of the cells within 1e-6 of it (at
#    step 0 every cell's, the first cell's centre); 2 ranks give the same value to 1e-9 and the same place
#    (mirror cells tie to rounding that differs between rank counts).
# Usage: probe_stress.sh SIGNORINI MPIEXEC SOURCE_DIR WORK_DIR
# (MPIEXEC: the launcher of cmake/SignoriniTesting.cmake; run_helpers.sh reads the arguments.)
source "$(dirname "$0")/run_helpers.sh" "$@"
# The block of block-on-floor.xml: 0.1 m x 0.05 m, 16 x 8 cells of 6.25 mm; E = 73 GPa, nu = 0.33.
block=(--set "Problem/Initial Displacement=1e-4*x + 2e-5*y, -3e-5*y" --set "Problem/Initial Velocity=0, 0"
       --set "Time Integration/Final Time=2e-4" --set "Output/Write Exodus=true"
       --set "Output/Probes/inside=0.03, 0.02" --set "Output/Probes/centre=0.028125, 0.021875"
       --set "Output/Probes/edge=0.05, 0.02" --set "Output/Probes/node=0.05, 0.025"
       --set "Output/Probes/corner=0, 0" --set "Output/Probes/far=0.1, 0.05" "$decks/block-on-floor.xml")
run one 1 --set "Output/Probe Fields=sigma,v , u" "${block[@]}"
run two 2 --set "Output/Probe Fields=u, sigma" "${block[@]}"
# max_von_mises looks only where Output/Stress Region is not 0 (here away from the block's sides), on 2 ranks.
run region 2 --set "Output/Stress Region=(x > 0.02) * (0.08 > x) * (y > 0.01)" "${block[@]}"
# A probe outside the block by 5e-13 m, within the locator's tolerance on the deck's mesh but not on
# finer ones: it is moved onto the boundary at set-up, so uniformly refined cycles still find it.
run edge 1 --set "Time Integration/Final Time=3e-5" --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Cycles=3" \
  --set "Output/Probe Fields=u, sigma" --set "Output/Probes/p=0.1 + 5e-13, 0.025" "$decks/block-on-floor.xml"
for t in "$work"/edge/block-on-floor.steps.csv "$work"/edge/block-on-floor.cycle[01].steps.csv; do
  [ -f "$t" ] || fail "edge: no table $t"
  ! grep -qi nan "$t" || fail "edge: a probe of $t is nan: the point was lost on a finer mesh"
done

$py - "$work" <<'PY' || exit 1
import glob, math, sys
import netCDF4
from step_tables import fail, table
work = sys.argv[1]
E, nu = 73e9, 0.33
lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
exx, eyy, exy = 1e-4, -3e-5, 1e-5  # u0 = (1e-4 x + 2e-5 y, -3e-5 y): gamma_xy = 2e-5
sxx, syy, sxy = lam * (exx + eyy) + 2 * mu * exx, lam * (exx + eyy) + 2 * mu * eyy, 2 * mu * exy
szz = lam * (exx + eyy)
vm = math.sqrt(0.5 * ((sxx - syy) ** 2 + (syy - szz) ** 2 + (szz - sxx) ** 2) + 3 * sxy ** 2)
exact = {"sigma_xx": sxx, "sigma_yy": syy, "sigma_xy": sxy, "sigma_zz": szz, "von_mises": vm}
one, two = table(f"{work}/one/block-on-floor.steps.csv"), table(f"{work}/two/block-on-floor.steps.csv")
probes = ("inside", "centre", "edge", "node", "corner", "far")
stress = [f"probe:{p}:{q}" for p in probes for q in exact]
missing = [c for c in stress + [f"probe:{p}:{s}" for p in probes for s in ("x", "y", "v:x", "v:y")] if c not in one[0]]
if missing or any(c.startswith("probe:") and c.split(":")[2] == "a" for c in one[0]):
    fail(f"the columns of 'sigma,v , u': missing {missing}, or an acceleration column")
for c in stress:
    value, want = float(one[0][c]), exact[c.split(":")[2]]
    if not abs(value - want) <= 1e-9 * abs(sxx):
        fail(f"step 0: {c} = {value!r}, the uniform strain's stress is {want!r}")
# The block vibrates: its stress is no longer uniform.
last = one[-1]
spread = max(abs(float(last[f"probe:{p}:sigma_xx"]) - float(last["probe:inside:sigma_xx"])) for p in probes)
if not spread > 1e-3 * abs(sxx):
    fail(f"the stress is still uniform at the end (spread {spread:.3g}): the run checked nothing after step 0")
for a, b in zip(one, two):
    for c in stress:
        if not abs(float(a[c]) - float(b[c])) <= 1e-9 * abs(sxx):
            fail(f"step {a['step']}: {c} is {a[c]} on 1 rank, {b[c]} on 2")
if len(one) != len(two):
    fail(f"{len(one)} steps on 1 rank, {len(two)} on 2")
# The centre probe against the Exodus cell stress of the cell whose centre it is.
files = glob.glob(f"{work}/one/block-on-floor.e*")
if len(files) != 1:
    fail(f"one Exodus file expected on 1 rank, found {files}")
with netCDF4.Dataset(files[0]) as d:
    x, y = d.variables["coordx"][:], d.variables["coordy"][:]
    connect = d.variables["connect1"][:] - 1
    centres = [(x[c].mean(), y[c].mean()) for c in connect]
    cell = min(range(len(centres)), key=lambda e: (centres[e][0] - 0.028125) ** 2 + (centres[e][1] - 0.021875) ** 2)
    names = [bytes(r).rstrip(b"\0").decode() for r in d.variables["name_elem_var"][:].data]
    times = list(d.variables["time_whole"][:])
    checked = 0
    for i, t in enumerate(times):
        row = next(r for r in one if abs(float(r["t"]) - t) <= 1e-12)
        for q in exact:
            value = d.variables[f"vals_elem_var{names.index(q) + 1}eb1"][i][cell]
            if not abs(value - float(row[f"probe:centre:{q}"])) <= 1e-12 * abs(sxx):
                fail(f"t = {t}: probe:centre:{q} = {row[f'probe:centre:{q}']}, the Exodus cell's {q} = {value!r}")
            checked += 1
# max_von_mises: the uniform value at step 0, the Exodus cells' largest and its centre later, 2 ranks alike.
if not abs(float(one[0]["max_von_mises"]) - vm) <= 1e-9 * vm:
    fail(f"step 0: max_von_mises {one[0]['max_von_mises']}, the uniform strain's von Mises stress is {vm!r}")
if (one[0]["max_von_mises_at_x"], one[0]["max_von_mises_at_y"]) != ("0.003125", "0.003125"):
    fail(f"step 0: max_von_mises at ({one[0]['max_von_mises_at_x']}, {one[0]['max_von_mises_at_y']}): every cell ties "
         "in a uniform strain, so the first cell's centre (0.003125, 0.003125)")
for a, b in zip(one, two):
    if not abs(float(a["max_von_mises"]) - float(b["max_von_mises"])) <= 1e-9 * vm:
        fail(f"step {a['step']}: max_von_mises {a['max_von_mises']} on 1 rank, {b['max_von_mises']} on 2")
    for c in ("max_von_mises_at_x", "max_von_mises_at_y"):
        if a[c] != b[c]:
            fail(f"step {a['step']}: {c} {a[c]} on 1 rank, {b[c]} on 2")
with netCDF4.Dataset(files[0]) as d:
    vm_cells = d.variables[f"vals_elem_var{names.index('von_mises') + 1}eb1"]
    located = 0
    for i, t in enumerate(times):
        row = next(r for r in one if abs(float(r["t"]) - t) <= 1e-12)
        values = vm_cells[i][:]
        top = max(range(len(values)), key=lambda e: values[e])
        if not abs(float(row["max_von_mises"]) - values[top]) <= 1e-12 * vm:
            fail(f"t = {t}: max_von_mises {row['max_von_mises']}, the Exodus cells' largest von_mises {values[top]!r}")
        # Its place: of the cells within 1e-6 of the largest, the centre with the smallest x, then y.
        at = (float(row["max_von_mises_at_x"]), float(row["max_von_mises_at_y"]))
        want = min(tuple(centres[e]) for e in range(len(values)) if values[e] >= values[top] * (1 - 1e-6))
        if not (abs(at[0] - want[0]) <= 1e-12 and abs(at[1] - want[1]) <= 1e-12):
            fail(f"t = {t}: max_von_mises at {at}, the Exodus cells put it at {want}")
        located += values[top] - min(values) > 1e-3 * vm  # not uniform: the place tells something
    if located < len(times) // 2:
        fail(f"the cell stresses are uniform in {len(times) - located} of {len(times)} steps: the place was hardly checked")
# The Exodus cell strains: the uniform strain (eps_xy the tensor's, half of gamma_xy) in every cell at
# t = 0, and Hooke's law sigma = lambda tr(eps) I + 2 mu eps cell by cell in every written step.
with netCDF4.Dataset(files[0]) as d:
    cells = {q: d.variables[f"vals_elem_var{names.index(q) + 1}eb1"][:] for q in
             ("eps_xx", "eps_yy", "eps_xy", "sigma_xx", "sigma_yy", "sigma_xy")}
for q, want in (("eps_xx", exx), ("eps_yy", eyy), ("eps_xy", exy)):
    if not abs(cells[q][0] - want).max() <= 1e-9 * exx:
        fail(f"t = 0: the Exodus cells' {q} is not the uniform strain's {want}")
tr = cells["eps_xx"] + cells["eps_yy"]
hooke = max(abs(cells["sigma_xx"] - lam * tr - 2 * mu * cells["eps_xx"]).max(),
            abs(cells["sigma_yy"] - lam * tr - 2 * mu * cells["eps_yy"]).max(),
            abs(cells["sigma_xy"] - 2 * mu * cells["eps_xy"]).max())
if not hooke <= 1e-9 * abs(sxx):
    fail(f"the Exodus cells' stress and strain break Hooke's law by {hooke:.3g} Pa")
# Output/Stress Region: the largest cell von Mises stress among the cells whose centre lies in it,
# and its place by the same rule; in some step it differs from the unrestricted one.
region_rows = table(f"{work}/region/block-on-floor.steps.csv")
region_files = sorted(glob.glob(f"{work}/region/block-on-floor.e*"))
inside = lambda c: c[0] > 0.02 and 0.08 > c[0] and c[1] > 0.01
differs = 0
for path in region_files:  # the series (one file: one mesh)
    with netCDF4.Dataset(path) as d:
        rx, ry = d.variables["coordx"][:], d.variables["coordy"][:]
        rconnect = d.variables["connect1"][:] - 1
        rcentres = [(rx[c].mean(), ry[c].mean()) for c in rconnect]
        rnames = [bytes(r).rstrip(b"\0").decode() for r in d.variables["name_elem_var"][:].data]
        rvm = d.variables[f"vals_elem_var{rnames.index('von_mises') + 1}eb1"]
        for i, t in enumerate(d.variables["time_whole"][:]):
            row = next(r for r in region_rows if abs(float(r["t"]) - t) <= 1e-12)
            values = rvm[i][:]
            cells = [e for e in range(len(values)) if inside(rcentres[e])]
            top = max(values[e] for e in cells)
            if not abs(float(row["max_von_mises"]) - top) <= 1e-9 * vm:
                fail(f"region, t = {t}: max_von_mises {row['max_von_mises']}, the region's cells' largest {top!r}")
            want = min(tuple(rcentres[e]) for e in cells if values[e] >= top * (1 - 1e-6))
            at = (float(row["max_von_mises_at_x"]), float(row["max_von_mises_at_y"]))
            if not (abs(at[0] - want[0]) <= 1e-12 and abs(at[1] - want[1]) <= 1e-12):
                fail(f"region, t = {t}: max_von_mises at {at}, the region's cells put it at {want}")
            differs += max(values) > top * (1 + 1e-6)
if not differs:
    fail("region: the largest stress lies in the region in every step: the restriction was not checked")
print(f"Stress Region: the region's largest cell stress in every written step ({differs} differ from the whole body's)")
if checked == 0:
    fail("no Exodus value was compared with the centre probe")
print(f"max_von_mises: the Exodus cells' largest and its place in {len(times)} steps")
print(f"step 0 exact at {len(probes)} probes; 1 and 2 ranks agree in {len(one)} steps; "
      f"the centre probe equals its cell's Exodus stress in {checked} values")
PY
echo "PASS"
