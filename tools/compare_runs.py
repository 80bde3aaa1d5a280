#!/usr/bin/python3
"""Compares an adaptive run with its uniform comparison from their <base>.cycles.csv files:
the total unknowns the adaptive run needs to reach the estimate of the finest uniform cycle
(log-log interpolation between the adaptive cycles around the first one at or below it; also the
unknowns of that cycle itself, with no interpolation) and the ratio of wall times; then the same factor
for the estimate of every uniform cycle, to show how it changes with the level of the comparison;
then both runs cycle by cycle: with no coarsening the adaptive cycle c refines no cell beyond level c,
so its meshes lie inside the uniform cycle c's; while its estimate stays above that cycle's, the
factor against uniform cycle c cannot exceed the ratio of the two cycles' unknowns.
The runs must be comparable: their step tables (<base>.steps.csv, the last cycle's) end at the same
step and time, and not be given the other way round (an adaptive run whose last cycle has the same
unknowns in every step against a uniform run whose does not); otherwise, or for a missing or
cut-short table, one line and exit status 1.
Usage: tools/compare_runs.py ADAPTIVE_BASE UNIFORM_BASE [--require-factor F]
With --require-factor the exit status is 1 unless the interpolated factor is at least F."""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from tool_errors import ArgumentParser, InputError, read_table, reporting  # noqa: E402

ap = ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
ap.add_argument("adaptive", help="output base of the adaptive run (folder/basename)")
ap.add_argument("uniform", help="output base of the uniform run")
ap.add_argument("--require-factor", type=float, default=0.0, help="fail unless the factor in unknowns reaches this")
a = ap.parse_args()
if not (np.isfinite(a.require_factor) and a.require_factor >= 0):
    ap.error(f"argument --require-factor: {a.require_factor:g}: not a factor (a number, 0 or more)")


def read_runs():
    """Both runs' cycle tables; InputError if one is missing or cut short, or if the runs are not
    comparable: their (last cycles') step tables must end at the same step and time; or if the
    arguments are swapped (the adaptive run's last cycle keeps one mesh, the uniform run's does not)."""
    cycles = [np.atleast_1d(read_table(base + ".cycles.csv", ["total_dofs", "eta", "wall_seconds"]))
              for base in (a.adaptive, a.uniform)]
    ends, fixed = [], []
    for base in (a.adaptive, a.uniform):
        steps = np.atleast_1d(read_table(base + ".steps.csv", ["step", "t", "dofs"]))
        ends.append((int(steps["step"][-1]), float(steps["t"][-1])))
        fixed.append(bool((steps["dofs"] == steps["dofs"][0]).all()))  # one mesh in every step: uniform
    if fixed[0] and not fixed[1]:
        raise InputError(f"{a.adaptive}.steps.csv has the same unknowns in every step and {a.uniform}.steps.csv "
                         "does not: the arguments swapped? (ADAPTIVE_BASE first, then UNIFORM_BASE)")
    (n_a, t_a), (n_u, t_u) = ends
    if n_a != n_u or abs(t_a - t_u) > 1e-9 * max(abs(t_a), abs(t_u)):
        raise InputError(f"the runs are not comparable: {a.adaptive}.steps.csv ends at step {n_a}, t = {t_a:.6g}, "
                         f"{a.uniform}.steps.csv at step {n_u}, t = {t_u:.6g} (another final time or time step)")
    return cycles


ad, un = reporting(read_runs)
target, n_uniform, t_uniform = un["eta"][-1], un["total_dofs"][-1], un["wall_seconds"].sum()
print(f"{a.adaptive} against {a.uniform}")
print("adaptive cycles: " + "; ".join(f"{int(d)} unknowns, eta {e:.4g}" for d, e in zip(ad["total_dofs"], ad["eta"])))
print("uniform cycles:  " + "; ".join(f"{int(d)} unknowns, eta {e:.4g}" for d, e in zip(un["total_dofs"], un["eta"])))


def adaptive_unknowns_for(eta):
    """(interpolated total unknowns, first cycle at or below eta) of the adaptive run, or None."""
    below = np.nonzero(ad["eta"] <= eta)[0]
    if len(below) == 0:
        return None
    j = below[0]
    if j == 0:
        return float(ad["total_dofs"][0]), 0
    x0, x1 = np.log(ad["total_dofs"][j - 1]), np.log(ad["total_dofs"][j])
    y0, y1 = np.log(ad["eta"][j - 1]), np.log(ad["eta"][j])
    return float(np.exp(x0 + (np.log(eta) - y0) * (x1 - x0) / (y1 - y0))), j


for j in range(1, len(un)):
    found = adaptive_unknowns_for(un["eta"][j])
    head = f"uniform cycle {j} (eta {un['eta'][j]:.4g}, {int(un['total_dofs'][j])} unknowns): "
    print(head + ("not reached by the adaptive run" if found is None else
                  f"adaptive about {int(found[0])} (cycle {found[1]}): factor {un['total_dofs'][j] / found[0]:.2f}"))
# Cycle by cycle (the cycles both runs have): the factor an adaptive run keeping pace with uniform
# refinement would reach, and whether it does keep pace.
for c in range(1, min(len(ad), len(un))):
    ratio, lead = un["total_dofs"][c] / ad["total_dofs"][c], ad["eta"][c] / un["eta"][c]
    print(f"cycle {c}: uniform/adaptive unknowns {ratio:.2f}, adaptive/uniform estimate {lead:.2f} "
          + ("(adaptive ahead: the factor can exceed the ratio)" if lead < 1 else
             f"(adaptive behind: factor against uniform cycle {c} at most {ratio:.2f})"))
if adaptive_unknowns_for(target) is None:
    print(f"the adaptive run does not reach the finest uniform estimate {target:.4g}")
    # The other way round: the unknowns the uniform run needs for the adaptive run's last estimate
    # (log-log interpolation between the two uniform cycles around it).
    last, n_last, t_last = ad["eta"][-1], ad["total_dofs"][-1], ad["wall_seconds"].sum()
    above = np.nonzero(un["eta"] <= last)[0]
    if len(above) and above[0] > 0:
        i = above[0]
        x0, x1 = np.log(un["total_dofs"][i - 1]), np.log(un["total_dofs"][i])
        y0, y1 = np.log(un["eta"][i - 1]), np.log(un["eta"][i])
        n_uniform_needed = float(np.exp(x0 + (np.log(last) - y0) * (x1 - x0) / (y1 - y0)))
        t_uniform_needed = un["wall_seconds"][: i + 1].sum()
        print(f"uniform refinement reaches the adaptive run's last estimate {last:.4g} with about "
              f"{int(n_uniform_needed)} total unknowns (interpolated) against the adaptive {int(n_last)}: "
              f"factor {n_uniform_needed / n_last:.2f} fewer unknowns adaptively")
        print(f"wall time: adaptive {t_last:.1f} s (all cycles), uniform {t_uniform_needed:.1f} s (all cycles up "
              f"to the one that reaches it): factor {t_uniform_needed / t_last:.2f}")
    sys.exit(1 if a.require_factor > 0 else 0)
n_needed, i = adaptive_unknowns_for(target)
n_cycle, t_needed = ad["total_dofs"][i], ad["wall_seconds"][: i + 1].sum()
factor = n_uniform / n_needed
print(f"finest uniform estimate {target:.4g} with {int(n_uniform)} total unknowns ({t_uniform:.1f} s over all cycles)")
print(f"adaptive reaches it with about {int(n_needed)} total unknowns (interpolated): factor {factor:.2f} fewer unknowns")
print(f"first adaptive cycle at or below it: cycle {i}, {int(n_cycle)} unknowns: factor {n_uniform / n_cycle:.2f}")
print(f"wall time to reach it (all cycles up to that one): {t_needed:.1f} s: factor {t_uniform / t_needed:.2f}")
if factor < a.require_factor:
    print(f"FAILED: factor {factor:.2f} < required {a.require_factor:g}")
    sys.exit(1)
