#!/usr/bin/python3
"""Summarises an adaptive run: phase split per cycle (cycles.csv) and, for the last cycle, the cost
of a whole adaptive step (remesh + transfer, assembly, contact, estimate + mark, output) in units of
one unconstrained solve of the same size (time_unconstrained). Usage: summarize_adaptive.py BASE"""
import sys

import numpy as np

base = sys.argv[1]
c = np.atleast_1d(np.genfromtxt(base + ".cycles.csv", delimiter=",", names=True))
phases = ["time_remesh_transfer", "time_assembly", "time_preconditioner", "time_contact", "time_estimate_mark",
          "time_output", "time_regularise"]
print(f"total wall time over {len(c)} cycles: {c['wall_seconds'].sum():.1f} s")
for row in c:
    split = ", ".join(f"{p[5:]} {row[p]:.2f}" for p in phases)
    print(f"cycle {int(row['cycle'])}: {int(row['total_dofs'])} unknowns, eta {row['eta']:.4g}, "
          f"{row['wall_seconds']:.1f} s ({split})")


def step_cost(name, label):
    s = np.genfromtxt(name, delimiter=",", names=True)[1:]
    step = s["time_remesh"] + s["time_assembly"] + s["time_contact"] + s["time_estimate"] + s["time_output"]
    free = s["time_unconstrained"]
    ok = free > 0
    ratio = step[ok].sum() / free[ok].sum()
    print(f"{label}: mean unknowns per step {s['dofs'].mean():.0f}; per step: remesh+transfer "
          f"{s['time_remesh'].mean() * 1e3:.2f} ms, assembly {s['time_assembly'].mean() * 1e3:.2f} ms, contact "
          f"{s['time_contact'].mean() * 1e3:.2f} ms, estimate+mark {s['time_estimate'].mean() * 1e3:.2f} ms, output "
          f"{s['time_output'].mean() * 1e3:.2f} ms; unconstrained solve {free[ok].mean() * 1e3:.2f} ms")
    return ratio


# The last cycle only estimates (it marks and refines nothing); the one before it also marks, refines
# and balances the next cycle's meshes.
if len(c) > 1:
    before = step_cost(f"{base}.cycle{len(c) - 2}.steps.csv", f"cycle {len(c) - 2}")
    print(f"  a step of cycle {len(c) - 2} (with marking and refinement) costs {before:.1f} unconstrained solves")
ratio = step_cost(base + ".steps.csv", "last cycle")
print(f"a whole adaptive step costs {ratio:.1f} unconstrained solves of the same size (target <= 6)")
