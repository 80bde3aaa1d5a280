#!/usr/bin/python3
"""Summarises a benchmark run: per-step phase split and the contact overhead ratio
R = time_contact / time_unconstrained over the steps with contact (needs Output/Measure Contact
Overhead = true). Usage: bench/summarize.py RUN.steps.csv [driver-log]"""
import re
import sys

import numpy as np

steps = np.genfromtxt(sys.argv[1], delimiter=",", names=True)
s = steps[1:]
contact = s["active"] > 0
print(f"steps: {len(s)}, unknowns per step: {int(s['dofs'][0])}, steps with contact: {int(contact.sum())}")
print("mean seconds per step (all steps): assembly %.4f  contact solve %.4f  output %.4f  unconstrained solve %.4f"
      % (s["time_assembly"].mean(), s["time_contact"].mean(), s["time_output"].mean(), s["time_unconstrained"].mean()))
if contact.any():
    c = s[contact]
    R = c["time_contact"].sum() / c["time_unconstrained"].sum()
    print("steps with contact: active-set iterations %.2f (max %d), CG iterations on Q %.2f (max %d), "
          "A-solves %.2f, Krylov iterations %.1f" % (c["qp_iterations"].mean(), c["qp_iterations"].max(),
                                                     c["cg_iterations"].mean(), c["cg_iterations"].max(),
                                                     c["linear_solves"].mean(), c["linear_iterations"].mean()))
    print(f"R = time(contact solve) / time(unconstrained solve, same A and preconditioner) = {R:.2f} (target <= 4)")
if len(sys.argv) > 2:
    text = open(sys.argv[2]).read()
    m = re.search(r"phase seconds:(.*)", text)
    if m:
        parts = m.group(1).split()
        phases = dict(zip(parts[0::2], map(float, parts[1::2])))
        print("whole-run phase totals [s]: " + ", ".join(f"{k} {v:.2f}" for k, v in phases.items()))
        if "preconditioner" in phases:
            print(f"preconditioner setup per step (set up once, uniform mesh): {phases['preconditioner'] / len(s):.4f} s")
