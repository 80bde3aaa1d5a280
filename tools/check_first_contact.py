#!/usr/bin/python3
"""Checks that an adaptive membrane run (paper Example 6.1, inputs/membrane.xml and its variants)
resolves the contact zone before the first contact, the property the paper's Section 7 finds
missing in strategies that compare indicators over all time steps ("the contact zone is not
resolved, before the first contact takes place. Thus, the algorithm is not able to detect the
moment of the first contact exactly").

The reference is independent of the program: until the first contact the membrane moves as the
obstacle-free solution u = -(2/pi) sin(pi t/2) sin(pi x/2), so the point (1, 1/2), where the
obstacle sin(pi y) - 1.05 is highest, touches it first, at t* = (2/pi) arcsin(0.05 pi/2). The first
time step at or after t* is the step of first contact a resolved discretisation must find.

Asserted, from the step tables and the last cycle's Exodus series (written every step):
  1. the last cycle's first step with active segments is that step;
  2. in the step before it and in it, every cell along Gamma_C (x = 1) under the first active
     segments is at the finest level of that step's mesh, and finer than the initial mesh;
  3. the first active segments lie around y = 1/2 (within 0.05 of it);
  4. control, the behaviour the paper warns of: cycle 0 (the uniform initial mesh, whose
     multiplier segments average the obstacle over 1/8 of Gamma_C) finds the contact later.
Prints what it finds; exit status 1 on any violation.
Usage: check_first_contact.py BASE [INITIAL_LEVEL] (the run's output base, e.g. out/membrane; the
level of the initial mesh's cells, 0 unless the deck sets Mesh/Refinement Level)"""
import argparse
import glob
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exodus_text import names as exodus_names  # noqa: E402
from tool_errors import (ArgumentParser, InputError, exodus, fail, read_table, reporting,  # noqa: E402
                         require_unit_square)

ap = ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
ap.add_argument("base", help="the run's output base (folder/basename)")
ap.add_argument("initial_level", nargs="?", type=int, default=0,
                help="the level of the initial mesh's cells (0 or more; default 0)")
args = ap.parse_args()
if args.initial_level < 0:
    ap.error(f"argument initial_level: {args.initial_level}: not a level (0 or more)")
base = args.base
initial = args.initial_level
failures = []


def steps_table(path, min_rows=1):
    return np.atleast_1d(reporting(lambda: read_table(path, ["step", "t", "active"], min_rows)))


def first_contact_step(table):
    active = np.flatnonzero(table["active"] > 0)
    return int(table["step"][active[0]]) if active.size else None


def written_steps():
    """(time, file, index in the file) of every written step of the last cycle's series."""
    files = sorted(glob.glob(glob.escape(base) + ".e") + glob.glob(glob.escape(base) + ".e-s.*"),
                   key=lambda f: int(f.rsplit(".", 1)[1]) if ".e-s." in f else 0)
    if not files:
        raise InputError(f"{base}.e: no such file (no Exodus files {base}.e*; run with Output/Exodus Interval = 1)")
    out = []
    for f in files:
        with exodus(f) as d:
            require_unit_square(f, d)
            for var, name in (("name_elem_var", "level"), ("name_sset_var", "lambda")):
                if var not in d.variables or name not in exodus_names(d[var]):
                    raise InputError(f"{f}: no variable {name} (not the output of a membrane run with contact?)")
            out += [(float(t), f, i) for i, t in enumerate(np.asarray(d["time_whole"][:]))]
    return out


last = steps_table(base + ".steps.csv", 2)
times = reporting(written_steps)  # a run of another kind (not the membrane's [0,1]^2) refused before any output
k = float(last["t"][1] - last["t"][0])
t_star = 2 / math.pi * math.asin(0.05 * math.pi / 2)
expected = math.ceil(t_star / k - 1e-9)
found = first_contact_step(last)
t_of = {round(t / k): (f, i) for t, f, i in times}
if found is not None and (found not in t_of or found - 1 not in t_of):  # an input problem, not a failed check
    fail(f"{base}: steps {found - 1} and {found} (the first contact) are not both in the Exodus series: run "
         "with Output/Exodus Interval = 1")
print(f"{base}: exact first contact t* = {t_star:.6f}, step {expected} (k = {k}); last cycle: step {found}")
if found != expected:
    failures.append(f"the last cycle finds the first contact in step {found}, not {expected}")

cycle0 = glob.glob(glob.escape(base) + ".cycle0.steps.csv")
if not cycle0:
    failures.append(f"no {base}.cycle0.steps.csv (the control needs the initial cycle's table)")
else:
    found0 = first_contact_step(steps_table(cycle0[0]))
    print(f"  cycle 0 (uniform initial mesh): step {found0}")
    if found0 is None or found0 <= expected:
        failures.append(f"control: cycle 0 finds the contact in step {found0}, expected later than {expected}")


def gamma_c_cells(f, i):
    """Levels of the mesh, and (y-range, level, lambda) of the cells along the side set, sorted in y."""
    with exodus(f) as d:
        names = exodus_names(d["name_elem_var"])
        level = np.asarray(d[f"vals_elem_var{names.index('level') + 1}eb1"][i])
        side_names = exodus_names(d["name_sset_var"])
        lam = np.asarray(d[f"vals_sset_var{side_names.index('lambda') + 1}ss1"][i])
        y = np.asarray(d["coordy"][:])
        conn = np.asarray(d["connect1"][:]) - 1
        cells = np.asarray(d["elem_ss1"][:]) - 1
    lo, hi = y[conn[cells]].min(1), y[conn[cells]].max(1)
    order = np.argsort(lo)
    return level, lo[order], hi[order], level[cells][order], lam[order]


if found is None:
    failures.append("the last cycle has no step with contact")
else:
    level, lo, hi, cell_level, lam = gamma_c_cells(*t_of[found])
    active = lam < 0
    zone = (lo[active].min(), hi[active].max())
    print(f"  first active segments cover y in [{zone[0]:.4f}, {zone[1]:.4f}]")
    if zone[0] < 0.45 or zone[1] > 0.55 or not zone[0] < 0.5 < zone[1]:
        failures.append(f"the first active segments cover [{zone[0]}, {zone[1]}]: not within 0.05 of y = 1/2 on both sides")
    for step in (found - 1, found):
        level, lo, hi, cell_level, _ = gamma_c_cells(*t_of[step])
        under = (hi > zone[0]) & (lo < zone[1])
        levels = sorted(set(cell_level[under].astype(int)))
        finest = int(level.max())
        print(f"  step {step}: cells of Gamma_C under them at levels {levels}; mesh levels "
              f"{int(level.min())}..{finest} (median {np.median(level):.0f}), initial mesh {initial}")
        if min(levels) < finest or finest <= initial:
            failures.append(f"step {step}: the contact zone is at levels {levels}, the mesh's finest is {finest} "
                            f"(initial {initial})")

for f in failures:
    print("FAILED:", f)
sys.exit(1 if failures else 0)
