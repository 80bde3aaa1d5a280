"""Checks a step table's energy balance (PassOptions::reportWork).

With Newmark's alpha = 1/2 and any beta, (3.1)-(3.2) and the step equation M a^n + K u^n = f^n
(loads and contact forces, -B lambda^n / (beta k^2)) give, step by step,
    newmark_energy(n) - newmark_energy(n-1) = (u^n - u^{n-1}) . (f^{n-1} + f^n) / 2,
so newmark_energy(n) = newmark_energy(0) + external_work(n) + contact_work(n) up to the solves'
tolerance. (With alpha > 1/2 the difference gains (alpha - 1/2) (k^2/2 da.M abar + k vbar.M da) per
step, of either sign.) Usage: check_energy_balance.py STEPS_CSV TOL, TOL relative to the largest
|newmark_energy|, |external_work| or |contact_work| of the run. Exit 0 when every step satisfies the
balance to TOL, 1 otherwise (also without the columns, with fewer than two steps, or with a value
that is not a finite number)."""
import csv
import math
import sys

path, tol = sys.argv[1], float(sys.argv[2])
names = ("newmark_energy", "external_work", "contact_work")
with open(path, newline="") as f:
    rows = list(csv.DictReader(f))
if len(rows) < 2 or any(n not in rows[0] for n in names):
    print(f"FAIL: {path}: not a step table with {', '.join(names)} and at least two steps")
    sys.exit(1)
values = {n: [float(r[n]) for r in rows] for n in names}
if not all(math.isfinite(x) for column in values.values() for x in column):
    print(f"FAIL: {path}: a value that is not a finite number")
    sys.exit(1)
scale = max(abs(x) for column in values.values() for x in column) or 1.0  # a body at rest: absolute
e, w_ext, w_c = values["newmark_energy"], values["external_work"], values["contact_work"]
residual = [(e[n] - e[0] - w_ext[n] - w_c[n]) / scale for n in range(len(rows))]
worst = max(range(len(rows)), key=lambda n: abs(residual[n]))
if not abs(residual[worst]) <= tol:
    print(f"FAIL: {path}: step {rows[worst]['step']}: newmark_energy - newmark_energy(0) - external_work - "
          f"contact_work = {residual[worst]:.3g} of the energy scale {scale:.6g} (tolerance {tol:g})")
    sys.exit(1)
print(f"{path}: largest |newmark_energy(n) - newmark_energy(0) - external_work - contact_work| "
      f"{abs(residual[worst]):.2g} of {scale:.6g} (step {rows[worst]['step']}); at the end "
      f"external_work {w_ext[-1]:.6g}, contact_work {w_c[-1]:.6g}")
