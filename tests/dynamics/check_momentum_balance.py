"""Checks a step table's momentum balance (runs on one mesh: the momentum columns; the reaction_force
columns of a problem with Dirichlet conditions).

Summing the rows of the full system M a^n + K u^n = f^n - B lambda^n + r^n over all unknowns of
component c (the partition of unity: the column sums of M are m_j = int rho phi_j and those of K
vanish, constants and translations being in its kernel) gives
    sum_j m_j a_j^n = F_c(t_n) + contact_c^n + reaction_c^n,
where reaction^n is the sum of the rows the Dirichlet elimination drops (reaction_force), contact
the contact force's resultant (contact_force along the contact direction) and F the applied loads'
resultant (applied_load, in a table of a problem with loads). Newmark's (3.2), v^n = v^{n-1} + k ((1 - alpha) a^{n-1} + alpha a^n), then gives, step by
step and up to the solves' tolerance,
    momentum(n) - momentum(n-1) = k ((1 - alpha) G(n-1) + alpha G(n)),  G = F + contact + reaction.
Elasticity's tables also balance the angular momentum about Output/Moment Point: the rigid rotation
r(x) = (-(y - p_y), x - p_x) lies in the Q1 space and in the kernel of K, so r^T (M a + K u) = (M r) . a
and, with angular_momentum = (M r) . v,
    angular_momentum(n) - angular_momentum(n-1) = k ((1 - alpha) G_M(n-1) + alpha G_M(n)),
    G_M = applied_moment + contact_moment + reaction_moment (each 0 where the table has no column).
(Both hold step by step with the paper's contact force; with Contact Force = implicit over a contact only.)

Usage: check_momentum_balance.py STEPS_CSV TOL [--alpha A] [--load EXPR ...] [--applied-moment EXPR]
                                 [--contact C:S] [--free]
  --load EXPR: the applied loads' resultant of each component as a Python expression of t (math's
    names allowed), one per component: the table's applied_load columns must equal it (to 1e-9 of its
    largest magnitude), and a table without them fails (default: the columns, or 0 without them);
  --applied-moment EXPR: the loads' moment about the moment point as a Python expression of t: the
    table's applied_moment column must equal it (to 1e-9 of its largest magnitude);
  --contact C:S: the contact force acts on component C (0 or 1) with sign S (+1 or -1; default 0:+1);
  --free: a body without Dirichlet conditions, whose table has no reaction_force columns (they are 0);
  TOL: relative to the largest |k G| of the run (for the angular momentum, |k G_M|); absolute where
    every force (moment) is 0, as for a free body, whose momentum may be rounding noise alone.
Exit 0 when every step balances to TOL, 1 otherwise (also without the columns, with fewer than two
steps, or with a value that is not a finite number)."""
import argparse
import csv
import math
import sys

parser = argparse.ArgumentParser()
parser.add_argument("table")
parser.add_argument("tol", type=float)
parser.add_argument("--alpha", type=float, default=0.5)
parser.add_argument("--load", action="append", default=[])
parser.add_argument("--applied-moment")
parser.add_argument("--contact", default="0:+1")
parser.add_argument("--free", action="store_true")
args = parser.parse_args()
with open(args.table, newline="") as f:
    rows = list(csv.DictReader(f))
if len(rows) < 2:
    print(f"FAIL: {args.table}: fewer than two steps")
    sys.exit(1)
header = rows[0].keys()
suffixes = ["_x", "_y"] if "momentum_x" in header else [""]
nc = len(suffixes)
reactions = [f"reaction_force{s}" for s in suffixes]
needed = ["t", "contact_force"] + [f"momentum{s}" for s in suffixes] + ([] if args.free else reactions)
if nc == 2:  # the angular momentum balance; the moments of the contact and of the loads where they act
    needed += ["angular_momentum"] + ([] if args.free else ["reaction_moment"])
    needed += [n for n in ("contact_moment", "applied_moment") if n in header]
    if args.applied_moment is not None and "applied_moment" not in header:
        print(f"FAIL: {args.table}: --applied-moment given, but no column applied_moment")
        sys.exit(1)
missing = [n for n in needed if n not in header]
if missing:
    print(f"FAIL: {args.table}: no column {', '.join(missing)}")
    sys.exit(1)
if args.free and any(n in header for n in reactions):
    print(f"FAIL: {args.table}: --free, but the table has reaction_force columns")
    sys.exit(1)
try:
    values = {n: [float(r[n]) for r in rows] for n in needed}
except ValueError as e:
    print(f"FAIL: {args.table}: {e}")
    sys.exit(1)
if not all(math.isfinite(x) for column in values.values() for x in column):
    print(f"FAIL: {args.table}: a value that is not a finite number")
    sys.exit(1)
loads = args.load + ["0"] * (nc - len(args.load))
if len(loads) != nc:
    print(f"FAIL: {len(args.load)} --load expressions for {nc} component(s)")
    sys.exit(1)
applied = [f"applied_load{s}" for s in suffixes]
has_applied = all(n in header for n in applied)
if args.load and not has_applied:
    print(f"FAIL: {args.table}: --load given, but no column {', '.join(applied)}")
    sys.exit(1)
if has_applied:
    try:
        applied_values = {n: [float(r[n]) for r in rows] for n in applied}
    except ValueError as e:
        print(f"FAIL: {args.table}: {e}")
        sys.exit(1)
component, sign = args.contact.split(":")
component, sign = int(component), float(sign)
t = values["t"]
k = t[1] - t[0]
alpha = args.alpha
worst = (0.0, None)
scale = 0.0
residuals = []
for c, s in enumerate(suffixes):
    load = [eval(loads[c], vars(math), {"t": tn}) for tn in t]
    if has_applied:
        column = applied_values[f"applied_load{suffixes[c]}"]
        if args.load:
            size = max(abs(x) for x in load) or 1.0
            n = max(range(len(rows)), key=lambda n: abs(column[n] - load[n]))
            if not abs(column[n] - load[n]) <= 1e-9 * size:
                print(f"FAIL: {args.table}: step {rows[n]['step']}: applied_load{suffixes[c]} is {column[n]!r}, "
                      f"--load gives {load[n]!r}")
                sys.exit(1)
        load = column
    reaction = [0.0] * len(rows) if args.free else values[f"reaction_force{s}"]
    G = [load[n] + reaction[n] + (sign * values["contact_force"][n] if c == component else 0.0)
         for n in range(len(rows))]
    scale = max(scale, max(abs(k * g) for g in G))
    P = values[f"momentum{s}"]
    for n in range(1, len(rows)):
        residuals.append((P[n] - P[n - 1] - k * ((1 - alpha) * G[n - 1] + alpha * G[n]), rows[n]["step"], f"momentum{s}"))
# Without any force (a free body) the momentum is constant: then TOL is absolute (its noise may be
# all the momentum a body at rest has, no scale).
balances = [(residuals, scale or 1.0, "G", "|k G|" if scale else "(absolute: every force is 0)")]
if nc == 2:
    column = lambda name: values[name] if name in values else [0.0] * len(rows)
    if args.applied_moment is not None:
        moment = [eval(args.applied_moment, vars(math), {"t": tn}) for tn in t]
        size = max(abs(x) for x in moment) or 1.0
        n = max(range(len(rows)), key=lambda n: abs(values["applied_moment"][n] - moment[n]))
        if not abs(values["applied_moment"][n] - moment[n]) <= 1e-9 * size:
            print(f"FAIL: {args.table}: step {rows[n]['step']}: applied_moment is {values['applied_moment'][n]!r}, "
                  f"--applied-moment gives {moment[n]!r}")
            sys.exit(1)
    GM = [a + c + r for a, c, r in zip(column("applied_moment"), column("contact_moment"), column("reaction_moment"))]
    L = values["angular_momentum"]
    angular = [(L[n] - L[n - 1] - k * ((1 - alpha) * GM[n - 1] + alpha * GM[n]), rows[n]["step"], "angular_momentum")
               for n in range(1, len(rows))]
    scale_M = max(abs(k * g) for g in GM)
    balances.append((angular, scale_M or 1.0, "G_M", "|k G_M|" if scale_M else "(absolute: every moment is 0)"))
failed = False
for residuals, scale, force, unit in balances:
    r, step, name = max(residuals, key=lambda x: abs(x[0]))
    if not abs(r) / scale <= args.tol:
        print(f"FAIL: {args.table}: step {step}: {name} changed by k ((1 - alpha) {force}(n-1) + alpha {force}(n)) "
              f"{'+' if r >= 0 else '-'} {abs(r):.3g}, {abs(r) / scale:.3g} {f'of the largest {unit} {scale:.6g}' if unit[0] == '|' else unit} "
              f"(tolerance {args.tol:g})")
        failed = True
    else:
        print(f"{args.table}: largest {name.split('_')[0]} imbalance {abs(r) / scale:.2g} "
              f"{f'of the largest {unit} {scale:.6g}' if unit[0] == '|' else unit} (step {step}, {name})")
sys.exit(1 if failed else 0)
