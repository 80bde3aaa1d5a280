#!/usr/bin/env bash
# With two or more Dirichlet segments the step table gives each support's reaction,
# reaction:<segment> (elasticity reaction:<segment>:x, :y, :moment, the moment about the support's
# centre, the mean of its edges' points): the rows of the Dirichlet unknowns it holds, an unknown held by two supports (a corner) counted with the first of them in
# Mesh/Boundary Segments.
#  - the supports' columns add up to the total reaction (reaction_force, and reaction_moment about the
#    Moment Point: each support's moment about its centre c plus (c - p) x its force) in every step,
#    to rounding; --check names the centres, (0, 0.025) and (0.1, 0.025): a block clamped at both sides pressed onto the floor under a body force varying in
#    time, with lumped boundary mass, on 2 ranks (both end contact segments end at clamped corners, whose
#    contact share goes to that side's support); the same block with a roller (u_y held) on its right
#    side; the membrane clamped along two sides through contact, on one mesh and adaptive (2 cycles, a
#    new mesh per step);
#  - mirror symmetry of the clamped block about x = 0.05: reaction:left:y = reaction:right:y,
#    reaction:left:x = -reaction:right:x and, each about its centre, reaction:left:moment =
#    -reaction:right:moment (to 1e-8 of the largest value: the solves' rounding);
#  - a roller carries no force along itself: reaction:right:x is 0 in every step;
#  - one Dirichlet segment: no per-support columns (the total is its reaction);
#  - controls: a support's column halved fails the sum check; the roller run (not symmetric) fails the
#    mirror check.
# Usage: support_reactions.sh SIGNORINI MPIEXEC SOURCE_DIR WORK_DIR
source "$(dirname "$0")/run_helpers.sh" "$@"
block=(--set "Mesh/Boundary Segments/left=left" --set "Mesh/Boundary Segments/right=right"
       --set "Problem/Initial Velocity=0, 0" --set "Problem/Obstacle=0" --set "Contact/Boundary Mass=lumped"
       --set "Problem/Body Force=0, -3e6*(1 + sin(2e4*t))" --set "Output/Moment Point=0.02, 0.1"
       --set "Time Integration/Final Time=3e-4")
membrane=(--set "Mesh/Boundary Segments/bottom=bottom" --set "Problem/Dirichlet Segments=clamped, bottom"
          --set "Time Integration/Final Time=1.2" --set "Output/Write Exodus=false" "$decks/good.xml")
run clamped 2 "${block[@]}" --set "Problem/Dirichlet Segments=left, right" "$decks/block-on-floor.xml"
run roller 1 "${block[@]}" --set "Problem/Dirichlet Segments=left" --set "Problem/Dirichlet Y Segments=right" \
  "$decks/block-on-floor.xml"
run membrane 1 "${membrane[@]}"
run adaptive 1 --set "Adaptivity/Strategy=fixed fraction" --set "Adaptivity/Cycles=2" "${membrane[@]}"
run single 1 "${block[@]}" --set "Problem/Dirichlet Segments=left" "$decks/block-on-floor.xml"
"$signorini" --check --output-dir "$work/plan" "${block[@]}" --set "Problem/Dirichlet Segments=left, right" \
  "$decks/block-on-floor.xml" > "$work/plan.log" 2>&1 || { cat "$work/plan.log"; fail "--check"; }
grep -q "supports (reaction:<segment>; each moment about the support's centre): left at (" "$work/plan.log" ||
  { cat "$work/plan.log"; fail "--check does not name the supports' centres"; }

$py - "$work" <<'PY'
import re, sys
from step_tables import fail, table
work = sys.argv[1]


def values(rows, column):
    if column not in rows[0]:
        fail(f"no column {column}")
    return [float(r[column]) for r in rows]


POINT = (0.02, 0.1)  # Output/Moment Point of the block runs
# The centres as --check names them (every digit): the mean of the sides' edge midpoints, (0, 0.025)
# and (0.1, 0.025) to rounding.
line = next(l for l in open(f"{work}/plan.log") if "supports (reaction:<segment>" in l)
CENTRES = {m[0]: (float(m[1]), float(m[2])) for m in re.findall(r"(\w+) at \(([^,]+), ([^)]+)\)", line)}
for name, want in (("left", (0.0, 0.025)), ("right", (0.1, 0.025))):
    if not all(abs(a - b) <= 1e-12 for a, b in zip(CENTRES.get(name, (9, 9)), want)):
        fail(f"--check names {name}'s centre {CENTRES.get(name)}, the side's centre is {want}")


def shifted_moments(rows, support):
    """reaction:<support>:moment about its centre c, moved to the Moment Point p: + (c - p) x F."""
    (cx, cy), (px, py) = CENTRES[support], POINT
    m, fx, fy = (values(rows, f"reaction:{support}{s}") for s in (":moment", ":x", ":y"))
    return [m[n] + (cx - px) * fy[n] - (cy - py) * fx[n] for n in range(len(rows))]


def sum_error(rows, supports, suffixes):
    """The largest |sum over the supports - total| of each quantity, relative to the largest value of
    its columns (moments moved to the Moment Point)."""
    worst = 0.0
    for suffix, total in suffixes:
        whole = values(rows, total)
        parts = [shifted_moments(rows, s) if suffix == ":moment" else values(rows, f"reaction:{s}{suffix}")
                 for s in supports]
        scale = max(abs(x) for column in parts + [whole] for x in column) or 1.0
        worst = max(worst, max(abs(sum(p[n] for p in parts) - whole[n]) for n in range(len(rows))) / scale)
    return worst


def mirror_error(rows):
    """The largest asymmetry of the clamped block's two supports, relative to the largest value."""
    worst = 0.0
    for suffix, sign in ((":x", -1.0), (":y", 1.0), (":moment", -1.0)):
        left, right = values(rows, f"reaction:left{suffix}"), values(rows, f"reaction:right{suffix}")
        scale = max(abs(x) for x in left + right) or 1.0
        worst = max(worst, max(abs(l - sign * r) for l, r in zip(left, right)) / scale)
    return worst


elastic = [(":x", "reaction_force_x"), (":y", "reaction_force_y"), (":moment", "reaction_moment")]
scalar = [("", "reaction_force")]
checks = [("clamped/block-on-floor", ["left", "right"], elastic), ("roller/block-on-floor", ["left", "right"], elastic),
          ("membrane/good", ["clamped", "bottom"], scalar), ("adaptive/good", ["clamped", "bottom"], scalar),
          ("adaptive/good.cycle0", ["clamped", "bottom"], scalar)]
for name, supports, suffixes in checks:
    rows = table(f"{work}/{name}.steps.csv")
    error = sum_error(rows, supports, suffixes)
    if not error <= 1e-12:
        fail(f"{name}: the supports' reactions miss the total by {error:.3g} of their largest value")
    if max(abs(float(r[f"reaction:{s}{suffix}"])) for r in rows for s in supports[1:] for suffix, _ in suffixes) == 0:
        fail(f"{name}: the second support carries nothing: nothing was split")
    print(f"{name}: the supports' reactions add up to the total to {error:.2g} of their largest value")
clamped = table(f"{work}/clamped/block-on-floor.steps.csv")
if max(int(r["active"]) for r in clamped) != 8:
    fail("clamped block: not every contact segment is pressed (the end segments end at the supports)")
error = mirror_error(clamped)
if not error <= 1e-8:
    fail(f"clamped block: the supports' reactions are not mirror images ({error:.3g} of the largest value)")
print(f"clamped block: mirror images to {error:.2g}")
roller = table(f"{work}/roller/block-on-floor.steps.csv")
if any(float(r["reaction:right:x"]) != 0 for r in roller) or max(abs(float(r["reaction:right:y"])) for r in roller) < 1e3:
    fail("roller: a force along the roller, or none across it")
if any(c.startswith("reaction:") for c in table(f"{work}/single/block-on-floor.steps.csv")[0]):
    fail("one Dirichlet segment: per-support columns")

# Controls: a halved support column breaks the sum; the roller run's supports swapped are no mirror images.
halved = [dict(r, **{"reaction:right:y": repr(0.5 * float(r["reaction:right:y"]))}) for r in clamped]
if sum_error(halved, ["left", "right"], elastic) <= 1e-12:
    fail("control: the sum check passed a halved reaction:right:y")
if mirror_error(roller) <= 1e-8:
    fail("control: the mirror check passed the roller run, which is not symmetric")
PY
[ $? -eq 0 ] || exit 1
echo "PASS"
