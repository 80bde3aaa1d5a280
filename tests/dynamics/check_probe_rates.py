"""Checks that a run's probes of v and a are the Newmark velocity and acceleration at the probe.

Newmark's update (3.1)-(3.2) is linear in the nodal values, and a probe interpolates the nodal
values of one fixed point linearly, so on a fixed mesh (no adaptivity, no contact stabilisation)
every probe satisfies, for each step n >= 1,
    u_n = u_{n-1} + k v_{n-1} + k^2/2 ((1 - 2 beta) a_{n-1} + 2 beta a_n),
    v_n = v_{n-1} + k ((1 - alpha) a_{n-1} + alpha a_n)
to rounding. Usage: check_probe_rates.py STEPS_CSV ALPHA BETA K
Exit 0 when every probe's columns probe:<name>[...], probe:<name>:v[...], probe:<name>:a[...]
satisfy both relations to 1e-10 of their terms' size, 1 otherwise (also when there is no such
probe, when a column of v lacks its u or a column, and when a probe value is not a finite number)."""
import csv
import math
import sys

path, alpha, beta, k = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
with open(path, newline="") as f:
    rows = list(csv.DictReader(f))
columns = rows[0].keys() if rows else []
checked, worst = 0, 0.0
for v_col in [c for c in columns if c.startswith("probe:") and c.endswith((":v", ":v:x", ":v:y"))]:
    if v_col.endswith(":v"):
        u_col, a_col = v_col[: -len(":v")], v_col[: -len(":v")] + ":a"
    else:  # elasticity: probe:<name>:v:x
        u_col, a_col = v_col[: -len(":v:x")] + v_col[-2:], v_col[: -len(":v:x")] + ":a" + v_col[-2:]
    if u_col not in columns or a_col not in columns:
        print(f"FAIL: {path}: {v_col} without {u_col if u_col not in columns else a_col}")
        sys.exit(1)
    u = [float(r[u_col]) for r in rows]
    v = [float(r[v_col]) for r in rows]
    a = [float(r[a_col]) for r in rows]
    for name, values in ((u_col, u), (v_col, v), (a_col, a)):
        bad = next((n for n, x in enumerate(values) if not math.isfinite(x)), None)
        if bad is not None:
            print(f"FAIL: {path}: {name} step {rows[bad]['step']} is {values[bad]}, not a finite number")
            sys.exit(1)
    for n in range(1, len(rows)):
        terms_u = [u[n], u[n - 1], k * v[n - 1], k * k / 2 * (1 - 2 * beta) * a[n - 1], k * k * beta * a[n]]
        res_u = terms_u[0] - sum(terms_u[1:])
        terms_v = [v[n], v[n - 1], k * (1 - alpha) * a[n - 1], k * alpha * a[n]]
        res_v = terms_v[0] - sum(terms_v[1:])
        for name, res, terms in (("u", res_u, terms_u), ("v", res_v, terms_v)):
            size = max(abs(t) for t in terms)
            rel = abs(res) / size if size > 0 else 0.0
            worst = max(worst, rel)
            if not rel <= 1e-10:
                print(f"FAIL: {path}: {v_col} step {rows[n]['step']}: the Newmark relation for {name} is off "
                      f"by {rel:.3g} of its terms' size")
                sys.exit(1)
    checked += 1
if checked == 0:
    print(f"FAIL: {path}: no probe with the columns of u, v and a")
    sys.exit(1)
print(f"{path}: {checked} probe component(s), Newmark relations hold to {worst:.2g} of their terms' size")
