#!/usr/bin/python3
"""Compares the step tables of run-rank-sensitivity.sh: for each scheme, 2 ranks against 1 rank and a
1e-12 perturbation of the initial velocity against the unperturbed run (1 rank), in cycles 0 and 1
(the two-cycle runs write both): the energy relative to its initial value, the probe u(1, 0.5) and
eta^n relative to its maximum ("reproducible": the paper's scheme under Parallel/Reproducible
Arithmetic). Usage: compare_sensitivity.py DIR"""
import argparse
import functools
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from tool_errors import ArgumentParser, InputError, read_table, reporting  # noqa: E402

ap = ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
ap.add_argument("dir", help="the output folder of run-rank-sensitivity.sh")
out = ap.parse_args().dir
steps = [25, 50, 100, 150, 200, 250, 300, 350, 400]
rows = {}  # rows of the first table read: every table must have as many (the same steps)


@functools.cache
def table(base, cycle=1):
    path = f"{out}/{base}{'.cycle0' if cycle == 0 else ''}.steps.csv"

    def read():
        t = read_table(path, ["dofs", "energy", "probecorner", "eta"], steps[-1] + 1)
        if rows.setdefault("n", t.size) != t.size:
            raise InputError(f"{path}: {t.size} rows, the tables read before {rows['n']}: not runs of the same steps")
        return t

    return reporting(read)


schemes = ["paper", "stabilised", "reproducible"]
for scheme in schemes:  # every table first: a missing or cut-short one stops before any output
    for run in ("np1", "np2", "perturbed"):
        for cycle in (1, 0):
            table(f"{scheme}.{run}", cycle)


for scheme in schemes:
    ref = table(f"{scheme}.np1")
    print(f"{scheme} scheme, cycle 1: relative difference of the energy at steps " + " ".join(map(str, steps)))
    for other, label in [("np2", "2 ranks against 1      "), ("perturbed", "v0 * (1 + 1e-12), 1 rank")]:
        t = table(f"{scheme}.{other}")
        same = np.array_equal(ref["dofs"], t["dofs"])
        energy = np.abs(ref["energy"] - t["energy"]) / ref["energy"][0]
        probe = np.abs(ref["probecorner"] - t["probecorner"])
        eta = np.abs(ref["eta"] - t["eta"]) / ref["eta"].max()
        print(f"  {label}: " + " ".join(f"{energy[n]:.0e}" for n in steps)
              + f"   largest: energy {energy.max():.0e}, probe u(1, 0.5) {probe.max():.0e}, eta^n {eta.max():.0e} of max eta"
              + ("" if same else "   (unknowns differ!)"))
        r0, t0 = table(f"{scheme}.np1", 0), table(f"{scheme}.{other}", 0)
        print(f"  {'':24}  cycle 0 (uniform h = 1/16): largest: energy "
              f"{(np.abs(r0['energy'] - t0['energy']) / r0['energy'][0]).max():.0e}, probe u(1, 0.5) "
              f"{np.abs(r0['probecorner'] - t0['probecorner']).max():.0e}")
