#!/usr/bin/python3
"""Checks the meshes of an Exodus series (<base>.e, <base>.e-s.NNNN) for mirror symmetry about the
line x2 = c (default 0.5): a mesh is symmetric when the mirror image of every cell (centre and size)
is a cell. Prints the time of the first asymmetric mesh and, over the asymmetric meshes, how many
cells have no mirror image and how far they reach from x1 = 1 (Gamma_C of the membrane decks).
For membrane runs only (cells covering [0,1]^2; others are refused), with 0 < c < 1.
Usage: check_mirror_symmetry.py BASE [c] [--require-symmetric] (exit status 1 if a mesh is not)"""
import argparse
import glob
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from tool_errors import ArgumentParser, exodus, fail, reporting, require_unit_square  # noqa: E402

parser = ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("base", help="the run's output base (folder/basename): its meshes <base>.e, <base>.e-s.NNNN")
parser.add_argument("axis", nargs="?", type=float, default=0.5,
                    help="c of the mirror line x2 = c, inside the domain: 0 < c < 1 (default 0.5)")
parser.add_argument("--require-symmetric", action="store_true", help="exit status 1 if a mesh is not symmetric")
args = parser.parse_args()
base, axis = args.base, args.axis
if not (math.isfinite(axis) and 0 < axis < 1):
    parser.error(f"argument axis: {axis:g}: not a line x2 = c inside the membrane's domain (0 < c < 1)")
files = sorted(glob.glob(glob.escape(base) + ".e") + glob.glob(glob.escape(base) + ".e-s.*"),
               key=lambda f: int(f.rsplit(".", 1)[1]) if ".e-s." in f else 0)
if not files:
    fail(f"{base}.e: no such file (no Exodus files {base}.e*)")
scale = 2.0**30  # cell centres and sizes of dyadic meshes are exact in this unit
first, counts, reach = None, [], 0.0
for f in files:
    with reporting(lambda: exodus(f)) as d:
        reporting(lambda: require_unit_square(f, d))
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
