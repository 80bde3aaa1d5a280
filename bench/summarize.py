#!/usr/bin/python3
"""Summarises a benchmark run: per-step phase split and the contact overhead ratio
R = time_contact / time_unconstrained over the steps with contact (needs Output/Measure Contact
Overhead = true); with the driver's log of the same run (the one that wrote the table), its
whole-run phase totals and the solver set-up.
Usage: bench/summarize.py RUN.steps.csv [driver-log]"""
import argparse
import os
import re
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
from tool_errors import ArgumentParser, InputError, fail, read_table, require_file  # noqa: E402

ap = ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
ap.add_argument("table", help="the run's step table, RUN.steps.csv")
ap.add_argument("log", nargs="?", help="the driver's output of the same run (signorini's stdout)")
args = ap.parse_args()


def log_phases(log, table, steps):
    """The 'phase seconds:' of the run in the log that wrote table ('wrote .../RUN.steps.csv' after
    it), checked against the table's steps and unknowns ('done: N steps, M unknowns per step')."""
    try:
        require_file(log)
        with open(log, errors="replace") as f:
            lines = f.read().splitlines()
    except OSError as e:
        raise InputError(f"{log}: {e.strerror or e}") from None
    wrote = [i for i, line in enumerate(lines)
             if line.strip().startswith("wrote ") and os.path.basename(line.split()[-1]) == os.path.basename(table)]
    if not wrote:
        raise InputError(f"{log}: not the log of the run that wrote {table} (no line 'wrote ...{os.path.basename(table)}')")
    before = lines[:wrote[-1]]
    done = [line for line in before if " done: " in line]
    phases = [line for line in before if "phase seconds:" in line]
    if not done or not phases:
        raise InputError(f"{log}: no 'done:' or 'phase seconds:' line before 'wrote ...{os.path.basename(table)}' "
                         "(did the run finish?)")
    m = re.search(r"done: (\d+) steps, (\d+) unknowns per step", done[-1])
    if not m or int(m.group(1)) != len(steps) - 1 or int(m.group(2)) != int(steps["dofs"][-1]):
        raise InputError(f"{log}: its run ('{done[-1].split('done: ', 1)[-1]}') is not the one of {table} "
                         f"({len(steps) - 1} steps, {int(steps['dofs'][-1])} unknowns per step)")
    parts = phases[-1].split("phase seconds:", 1)[1].split()
    return dict(zip(parts[0::2], map(float, parts[1::2])))


try:  # every input first: nothing printed for a run without the measurement or a log of another run
    steps = np.atleast_1d(read_table(args.table, ["dofs", "active"]))
    names = steps.dtype.names
    if "time_unconstrained" not in names or len(steps) < 2 or not (steps["time_unconstrained"][1:] > 0).all():
        raise InputError(f"{args.table}: no unconstrained solve timed in every step: run the deck with "
                         "Output/Measure Contact Overhead = true")
    phases = log_phases(args.log, args.table, steps) if args.log else None
except InputError as e:
    fail(e)
print(f"{args.table}, written {time.strftime('%Y-%m-%d %H:%M', time.localtime(os.path.getmtime(args.table)))}")
s = steps[1:]
contact = s["active"] > 0
print(f"steps: {len(s)}, mean unknowns per step: {s['dofs'].mean():.0f}, steps with contact: {int(contact.sum())}")
print("mean seconds per step (all steps): assembly %.4f  contact solve %.4f  output %.4f  unconstrained solve %.4f"
      % (s["time_assembly"].mean(), s["time_contact"].mean(), s["time_output"].mean(), s["time_unconstrained"].mean()))
free = s["time_unconstrained"]
spread = np.percentile(free, 90) / np.median(free)
print(f"unconstrained solve: median {np.median(free):.4f} s, 90th percentile {spread:.2f} times the median"
      + (" (a busy machine? the ratios below are less reliable)" if spread > 1.3 else "")
      + (f"; Krylov iterations: median {np.median(s['unconstrained_iterations']):.0f}"
         if "unconstrained_iterations" in names else ""))
if contact.any():
    c = s[contact]
    R = c["time_contact"].sum() / c["time_unconstrained"].sum()
    print("steps with contact: mean seconds per step: contact solve %.4f, unconstrained solve %.4f" %
          (c["time_contact"].mean(), c["time_unconstrained"].mean()))
    print("steps with contact: active-set iterations %.2f (max %d), CG iterations on Q %.2f (max %d), "
          "A-solves %.2f, Krylov iterations %.1f" % (c["qp_iterations"].mean(), c["qp_iterations"].max(),
                                                     c["cg_iterations"].mean(), c["cg_iterations"].max(),
                                                     c["linear_solves"].mean(), c["linear_iterations"].mean()))
    print(f"R = time(contact solve) / time(unconstrained solve, same A and preconditioner) = {R:.2f} (target <= 4); "
          f"median over the steps with contact {np.median(c['time_contact'] / c['time_unconstrained']):.2f}")
if phases is not None:
    print("whole-run phase totals [s] (exclusive; with the set-up on the deck's mesh): "
          + ", ".join(f"{k} {v:.2f}" for k, v in phases.items()))
    if "preconditioner" in phases:
        print(f"solver set-up (once, with the contact Schur preconditioner): {phases['preconditioner']:.3f} s")
