#!/usr/bin/python3
"""Compares an adaptive run with its uniform comparison from their <base>.cycles.csv files:
the total unknowns the adaptive run needs to reach the estimate of the finest uniform cycle
(log-log interpolation between adaptive cycles) and the ratio of wall times.
Usage: tools/compare_runs.py ADAPTIVE_BASE UNIFORM_BASE"""
import sys

import numpy as np

ad = np.atleast_1d(np.genfromtxt(sys.argv[1] + ".cycles.csv", delimiter=",", names=True))
un = np.atleast_1d(np.genfromtxt(sys.argv[2] + ".cycles.csv", delimiter=",", names=True))
target, n_uniform, t_uniform = un["eta"][-1], un["total_dofs"][-1], un["wall_seconds"].sum()
print("adaptive cycles: " + "; ".join(f"{int(d)} unknowns, eta {e:.4g}" for d, e in zip(ad["total_dofs"], ad["eta"])))
print("uniform cycles:  " + "; ".join(f"{int(d)} unknowns, eta {e:.4g}" for d, e in zip(un["total_dofs"], un["eta"])))
reached = np.nonzero(ad["eta"] <= target)[0]
if len(reached) == 0:
    print(f"the adaptive run does not reach the finest uniform estimate {target:.4g}")
    sys.exit(0)
i = reached[0]
if i == 0:
    n_needed, t_needed = ad["total_dofs"][0], ad["wall_seconds"][0]
else:  # log-log interpolation between cycles i-1 and i
    x0, x1 = np.log(ad["total_dofs"][i - 1]), np.log(ad["total_dofs"][i])
    y0, y1 = np.log(ad["eta"][i - 1]), np.log(ad["eta"][i])
    n_needed = float(np.exp(x0 + (np.log(target) - y0) * (x1 - x0) / (y1 - y0)))
    t_needed = ad["wall_seconds"][: i + 1].sum()
print(f"finest uniform estimate {target:.4g} with {int(n_uniform)} total unknowns ({t_uniform:.1f} s over all cycles)")
print(f"adaptive reaches it with about {int(n_needed)} total unknowns: factor {n_uniform / n_needed:.2f} fewer unknowns")
print(f"wall time to reach it (all cycles up to that one): {t_needed:.1f} s: factor {t_uniform / t_needed:.2f}")
