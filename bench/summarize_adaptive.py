#!/usr/bin/python3
"""Summarises an adaptive run: phase split per cycle (cycles.csv) and, for the last cycle, the cost
of a whole adaptive step (new mesh and transfer, assembly, contact, estimate + mark, output) in units
of one unconstrained solve of the same size (time_unconstrained: the step's own solver on its
matrix, right-hand side and start, timed right after the contact solve; needs Output/Measure Contact
Overhead = true). Usage: summarize_adaptive.py BASE, or summarize_adaptive.py --ratios BASE... (the
last cycle's cost of each run, their median and range, and the whole runs' wall times)"""
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
from tool_errors import InputError, fail, read_table  # noqa: E402

if len(sys.argv) >= 2 and sys.argv[1] in ("-h", "--help"):
    print(__doc__)
    sys.exit(0)
if len(sys.argv) < 2 or (sys.argv[1] != "--ratios" and len(sys.argv) != 2) or sys.argv[1:] == ["--ratios"]:
    sys.exit(__doc__)
base = sys.argv[1]


def table(name):
    """The CSV table name; one line (tool_errors.fail) if it is missing, empty or cut short."""
    try:
        return np.atleast_1d(read_table(name))
    except InputError as e:
        fail(e)


def steps_and_units(name):
    """The step table's rows after step 0, each step's cost and its unconstrained solve [s]."""
    s = table(name)[1:]
    if "time_unconstrained" not in (s.dtype.names or ()) or not (s["time_unconstrained"] > 0).all():
        fail(f"{name}: no unconstrained solve timed in every step: run with Output/Measure Contact Overhead = true")
    step = s["time_remesh"] + s["time_assembly"] + s["time_contact"] + s["time_estimate"] + s["time_output"]
    return s, step, s["time_unconstrained"]


def last_cycle_ratio(base):
    _, step, free = steps_and_units(base + ".steps.csv")
    return step.sum() / free.sum()


if sys.argv[1] == "--ratios":
    ratios = [last_cycle_ratio(b) for b in sys.argv[2:]]
    walls = [table(b + ".cycles.csv")["wall_seconds"].sum() for b in sys.argv[2:]]
    print(f"a whole adaptive step costs {np.median(ratios):.1f} unconstrained solves (median of {len(ratios)} runs; "
          f"{min(ratios):.1f}-{max(ratios):.1f}: " + ", ".join(f"{r:.1f}" for r in ratios) + f"); whole run "
          f"{np.median(walls):.1f} s ({min(walls):.1f}-{max(walls):.1f} s)")
    sys.exit(0)

c = table(base + ".cycles.csv")
# Every input before anything is printed: refuses a run without the measurement or a table missing.
steps_and_units(base + ".steps.csv")
if len(c) > 1:
    steps_and_units(f"{base}.cycle{len(c) - 2}.steps.csv")
# The phases are exclusive; "other" is what none covers (predictors, the Newmark update, the
# transfer energies, a later cycle's initial state). "unconstrained" is the measurement itself.
phases = ["time_remesh_transfer", "time_assembly", "time_preconditioner", "time_contact", "time_estimate_mark",
          "time_output", "time_regularise", "time_unconstrained", "time_other"]
missing = [p for p in phases if p not in (c.dtype.names or ())]
if missing:
    fail(f"{base}.cycles.csv: no column {', '.join(missing)} (written by an older signorini?)")
print(f"{base}.cycles.csv, written {time.strftime('%Y-%m-%d %H:%M', time.localtime(os.path.getmtime(base + '.cycles.csv')))}")
print(f"total wall time over {len(c)} cycles: {c['wall_seconds'].sum():.1f} s "
      "(phases: remesh_transfer = the Q1 numbering and the transfer; assembly = matrices, loads, B; preconditioner ="
      " the solver and contact Schur preconditioner set-up; estimate_mark = estimator, marking, refinement)")
for row in c:
    split = ", ".join(f"{p[5:]} {row[p]:.2f}" for p in phases)
    print(f"cycle {int(row['cycle'])}: {int(row['total_dofs'])} unknowns, eta {row['eta']:.4g}, "
          f"{row['wall_seconds']:.1f} s ({split})")


def step_cost(name, label):
    s, step, free = steps_and_units(name)
    ratio = step.sum() / free.sum()
    spread = np.percentile(free, 90) / np.median(free)
    print(f"{label}: mean unknowns per step {s['dofs'].mean():.0f}; mean per step: new mesh (numbering, matrices, "
          f"solver set-up) + transfer {s['time_remesh'].mean() * 1e3:.2f} ms, loads {s['time_assembly'].mean() * 1e3:.2f}"
          f" ms, contact {s['time_contact'].mean() * 1e3:.2f} ms, estimate+mark {s['time_estimate'].mean() * 1e3:.2f} ms,"
          f" output {s['time_output'].mean() * 1e3:.2f} ms; unconstrained solve {free.mean() * 1e3:.2f} ms (median "
          f"{np.median(free) * 1e3:.2f} ms, 90th percentile {spread:.2f} times the median"
          + ("; a busy machine? the ratio is less reliable" if spread > 1.3 else "") + ")"
          + (f"; its Krylov iterations: median {np.median(s['unconstrained_iterations']):.0f}"
             f" ({s['unconstrained_iterations'].min():.0f}-{s['unconstrained_iterations'].max():.0f})"
             if "unconstrained_iterations" in s.dtype.names else ""))
    print(f"  median over the steps of step / unconstrained solve: {np.median(step / free):.1f}")
    return ratio


# The last cycle only estimates (it marks and refines nothing); the one before it also marks, refines
# and balances the next cycle's meshes.
if len(c) > 1:
    before = step_cost(f"{base}.cycle{len(c) - 2}.steps.csv", f"cycle {len(c) - 2}")
    print(f"  a step of cycle {len(c) - 2} (with marking and refinement) costs {before:.1f} unconstrained solves")
ratio = step_cost(base + ".steps.csv", "last cycle")
whole = (c["wall_seconds"] - c["time_unconstrained"]).sum() / table(base + ".steps.csv")[1:]["time_unconstrained"].sum()
print(f"a whole adaptive step costs {ratio:.1f} unconstrained solves of the same size (target <= 6); "
      f"the whole run (every cycle) costs {whole:.1f} unconstrained solves of the last cycle per step of it")
