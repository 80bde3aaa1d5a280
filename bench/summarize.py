#!/usr/bin/python3
"""Summarises a benchmark run: per-step phase split and the contact overhead ratio
R = time_contact / time_unconstrained over the steps with contact (needs Output/Measure Contact
Overhead = true). Usage: bench/summarize.py RUN.steps.csv [driver-log]"""
import os
import re
import sys
import time

import numpy as np

if len(sys.argv) not in (2, 3):
    sys.exit(__doc__)
try:
    steps = np.atleast_1d(np.genfromtxt(sys.argv[1], delimiter=",", names=True))
except OSError as e:
    sys.exit(f"{sys.argv[1]}: {e.strerror or e}")
names = steps.dtype.names or ()
if "time_unconstrained" not in names or len(steps) < 2 or not (steps["time_unconstrained"][1:] > 0).all():
    sys.exit(f"{sys.argv[1]}: no unconstrained solve timed in every step: run the deck with "
             "Output/Measure Contact Overhead = true")
print(f"{sys.argv[1]}, written {time.strftime('%Y-%m-%d %H:%M', time.localtime(os.path.getmtime(sys.argv[1])))}")
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
if len(sys.argv) > 2:
    text = open(sys.argv[2]).read()
    m = re.search(r"phase seconds:(.*)", text)
    if not m:
        sys.exit(f"{sys.argv[2]}: no 'phase seconds' line (did the run finish?)")
    parts = m.group(1).split()
    phases = dict(zip(parts[0::2], map(float, parts[1::2])))
    print("whole-run phase totals [s] (exclusive; with the set-up on the deck's mesh): "
          + ", ".join(f"{k} {v:.2f}" for k, v in phases.items()))
    if "preconditioner" in phases:
        print(f"solver set-up (once, with the contact Schur preconditioner): {phases['preconditioner']:.3f} s")
