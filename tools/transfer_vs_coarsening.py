#!/usr/bin/python3
"""Where the transfer between meshes changes the energy: for every step n of a run written in every
step (Output/Exodus Interval = 1, the rectangle [0,1]^2 of the membrane decks), the share of the
domain where T^n is coarser than T^{n-1} and the transfer's change of the energy,
|energy_transferred(n) - energy(n-1)| / energy(0) (Adaptivity/Report Transfer Energy). The L2
projection is exact where the new mesh only refines the old one, so a step without coarsened
area must not change the energy beyond rounding. Prints the largest change among those steps and
the median change per coarsened area in three equal parts of the steps that coarsen.
With --check the script fails (exit status 1) if such a step changes the energy by more than
1e-12 E(0) or if the run has no such step.
Usage: transfer_vs_coarsening.py [--check] OUT/BASENAME (e.g. out/transfer/membrane)"""
import argparse
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exodus_text import names as exodus_names  # noqa: E402
from tool_errors import ArgumentParser, InputError, exodus, read_table, reporting  # noqa: E402

PIXELS = 1024  # the level map's resolution: finer than any cell of the decks' meshes


def level_maps(base):
    """{step: PIXELS x PIXELS array of the cell level covering each pixel} over the Exodus series."""
    files = sorted(glob.glob(base + ".e") + glob.glob(base + ".e-s.*"), key=lambda f: (len(f), f))
    if not files:
        raise InputError(f"{base}.e: no such file (the run wrote no Exodus output? Output/Write Exodus)")
    maps = {}
    for f in files:
        with exodus(f) as d:
            names = exodus_names(d["name_elem_var"]) if "name_elem_var" in d.variables else []
            if "level" not in names:
                raise InputError(f"{f}: no element variable level")
            x, y, conn = d["coordx"][:], d["coordy"][:], d["connect1"][:] - 1
            lo = np.rint(np.c_[x[conn].min(1), y[conn].min(1)] * PIXELS).astype(int)
            hi = np.rint(np.c_[x[conn].max(1), y[conn].max(1)] * PIXELS).astype(int)
            levels = d["vals_elem_var%deb1" % (names.index("level") + 1)][:]
            for k, t in enumerate(d["time_whole"][:]):
                m = np.full((PIXELS, PIXELS), -1, dtype=np.int8)
                for (i0, j0), (i1, j1), level in zip(lo, hi, levels[k]):
                    m[j0:j1, i0:i1] = level
                if (m < 0).any():
                    raise InputError(f"{f}: the cells do not cover [0,1]^2 (not a membrane deck?)")
                maps[float(t)] = m
    return maps


def main():
    ap = ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("base", help="output base of the run (folder/basename)")
    ap.add_argument("--check", action="store_true",
                    help="fail unless the steps that only refine keep the energy to 1e-12 E(0)")
    args = ap.parse_args()
    base = args.base
    steps = read_table(base + ".steps.csv", ["step", "t", "energy", "energy_transferred"], min_rows=3)
    maps = level_maps(base)
    rows = []
    for n in range(1, len(steps)):
        before, after = maps.get(float(steps["t"][n - 1])), maps.get(float(steps["t"][n]))
        if before is None or after is None:
            raise InputError(f"{base}: no mesh written at t = {steps['t'][n - 1]:g} or {steps['t'][n]:g} "
                             "(run with Output/Exodus Interval = 1)")
        change = abs(steps["energy_transferred"][n] - steps["energy"][n - 1]) / steps["energy"][0]
        rows.append((n, (after < before).mean(), change, (after > before).mean()))
    rows = np.array(rows)
    exact, coarsened = rows[(rows[:, 1] == 0) & (rows[:, 3] > 0)], rows[rows[:, 1] > 0]
    print(f"{len(exact)} of {len(rows)} steps only refine the previous mesh (and {len(rows) - len(exact) - len(coarsened)} "
          f"keep it): largest energy change {exact[:, 2].max() if len(exact) else 0:.2e} E(0)")
    print(f"{len(coarsened)} steps coarsen part of it: energy change per coarsened share of the domain "
          "(median) and the coarsened share (median), in three groups of these steps:")
    for part in np.array_split(coarsened, 3):
        if len(part):
            print(f"  steps {int(part[0, 0])}-{int(part[-1, 0])}: {np.median(part[:, 2] / part[:, 1]):.2e} E(0), "
                  f"share {np.median(part[:, 1]):.3f}")
    if args.check and (len(exact) == 0 or exact[:, 2].max() > 1e-12):
        sys.exit(f"{base}: " + ("no step only refines its predecessor's mesh" if len(exact) == 0 else
                                "a step that only refines changes the energy by more than 1e-12 E(0)"))


reporting(main)
