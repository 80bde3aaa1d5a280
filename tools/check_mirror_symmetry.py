#!/usr/bin/python3
"""Checks the meshes of an Exodus series (<base>.e, <base>.e-s.NNNN) for mirror symmetry about the
line x2 = c (default 0.5): a mesh is symmetric when the mirror image of every cell (centre and size)
is a cell. Prints the time of the first asymmetric mesh and, over the asymmetric meshes, how many
cells have no mirror image and how far they reach from x1 = 1 (Gamma_C of the membrane decks).
Usage: check_mirror_symmetry.py BASE [c] [--require-symmetric] (exit status 1 if a mesh is not)"""
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from tool_errors import ArgumentParser, exodus, fail, reporting  # noqa: E402

parser = ArgumentParser()
parser.add_argument("base")
parser.add_argument("axis", nargs="?", type=float, default=0.5)
parser.add_argument("--require-symmetric", action="store_true")
args = parser.parse_args()
base, axis = args.base, args.axis
files = sorted(glob.glob(base + ".e") + glob.glob(base + ".e-s.*"),
               key=lambda f: int(f.rsplit(".", 1)[1]) if ".e-s." in f else 0)
if not files:
    fail(f"{base}.e: no such file (no Exodus files {base}.e*)")
scale = 2.0**30  # cell centres and sizes of dyadic meshes are exact in this unit
first, counts, reach = None, [], 0.0
for f in files:
    with reporting(lambda: exodus(f)) as d:
        x, y, conn = d["coordx"][:], d["coordy"][:], d["connect1"][:] - 1
        t = float(d["time_whole"][0])
    cx, cy = x[conn].mean(1), y[conn].mean(1)
    h = x[conn].max(1) - x[conn].min(1)

    def cells(yy):
        return set(zip(*(np.round(v * scale).astype(np.int64) for v in (cx, yy, h))))

    alone = cells(cy) - cells(2 * axis - cy)
    if alone:
        first = t if first is None else first
        counts.append(len(alone))
        reach = max(reach, max(1.0 - c[0] / scale for c in alone))
print(f"{len(files)} meshes, {len(counts)} asymmetric about x2 = {axis}", end="")
if counts:
    print(f"; the first at t = {first:.4g}; cells without a mirror image: {min(counts)}-{max(counts)}, "
          f"median {int(np.median(counts))}; they reach {reach:.3f} from x1 = 1")
else:
    print()
if counts and args.require_symmetric:
    sys.exit(1)
