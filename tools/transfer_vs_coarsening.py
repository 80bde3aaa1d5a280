#!/usr/bin/python3
"""Where the transfer between meshes changes the energy: for every step n of a run written in every
step (Output/Exodus Interval = 1, the rectangle [0,1]^2 of the membrane decks), the share of the
domain where T^n is coarser than T^{n-1} and the transfer's change of the energy,
|energy_transferred(n) - energy(n-1)| / energy(0) (Adaptivity/Report Transfer Energy; for a run
starting at rest, energy(0) = 0, relative to the largest energy of the run, max E, instead). The L2
projection is exact where the new mesh only refines the old one, so a step without coarsened
area must not change the energy beyond rounding. Prints the largest change among those steps and
the median change per coarsened area in three equal parts of the steps that coarsen.
With --check the script fails (exit status 1) if such a step changes the energy by more than
1e-12 E(0) (max E), by an amount that is not a number, or if the run has no such step.
Usage: transfer_vs_coarsening.py [--check] OUT/BASENAME (e.g. out/transfer/membrane)"""
import argparse
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exodus_text import names as exodus_names  # noqa: E402
from tool_errors import ArgumentParser, InputError, exodus, read_table, reporting  # noqa: E402

PIXELS = 1024  # the level map's least resolution; finer where a series has cells below 1/PIXELS


def level_frames(base):
    """({time: (lower left pixels, upper right pixels, levels) of the cells}, pixels per side) over
    the Exodus series: the pixels (a power of two, at least PIXELS) as fine as the series' finest
    cell, so that every cell covers whole pixels (inputs/membrane-fraction10.xml reaches 1/2048)."""
    files = sorted(glob.glob(glob.escape(base) + ".e") + glob.glob(glob.escape(base) + ".e-s.*"),
                   key=lambda f: (len(f), f))
    if not files:
        raise InputError(f"{base}.e: no such file (the run wrote no Exodus output? Output/Write Exodus)")
    meshes = []
    for f in files:
        with exodus(f) as d:
            names = exodus_names(d["name_elem_var"]) if "name_elem_var" in d.variables else []
            if "level" not in names:
                raise InputError(f"{f}: no element variable level")
            x, y, conn = np.asarray(d["coordx"][:]), np.asarray(d["coordy"][:]), np.asarray(d["connect1"][:]) - 1
            lo, hi = np.c_[x[conn].min(1), y[conn].min(1)], np.c_[x[conn].max(1), y[conn].max(1)]
            levels = np.asarray(d["vals_elem_var%deb1" % (names.index("level") + 1)][:])
            meshes.append((f, lo, hi, [(float(t), levels[k]) for k, t in enumerate(d["time_whole"][:])]))
    smallest = min((hi - lo).min() for _, lo, hi, _ in meshes)
    pixels = PIXELS
    while smallest * pixels < 1 - 1e-9:
        pixels *= 2
    frames = {}
    for f, lo, hi, times in meshes:
        cells = (f, np.rint(lo * pixels).astype(int), np.rint(hi * pixels).astype(int))
        for t, levels in times:
            frames[t] = cells + (levels,)
    return frames, pixels


def level_map(frame, pixels):
    """pixels x pixels array of the cell level covering each pixel of one frame of level_frames."""
    f, lo, hi, levels = frame
    m = np.full((pixels, pixels), -1, dtype=np.int8)
    for (i0, j0), (i1, j1), level in zip(lo, hi, levels):
        m[j0:j1, i0:i1] = level
    if (m < 0).any():
        raise InputError(f"{f}: the cells do not cover [0,1]^2 (not a membrane deck?)")
    return m


def main():
    ap = ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("base", help="output base of the run (folder/basename)")
    ap.add_argument("--check", action="store_true",
                    help="fail unless the steps that only refine keep the energy to 1e-12 E(0) (max E for a run at rest)")
    args = ap.parse_args()
    base = args.base
    steps = read_table(base + ".steps.csv", ["step", "t", "energy", "energy_transferred"], min_rows=3)
    frames, pixels = level_frames(base)
    # The reference energy: E(0), or for a run starting at rest (E(0) = 0) the largest energy of the run.
    energy = np.asarray(steps["energy"], dtype=float)
    reference, ref_name = energy[0], "E(0)"
    if not reference > 0:
        reference, ref_name = np.abs(energy).max(), "max E"
    if not (np.isfinite(reference) and reference > 0):
        raise InputError(f"{base}.steps.csv: the energy is 0 (or not a number) in every step: no reference "
                         "for the relative energy change")
    rows, cache = [], {}
    for n in range(1, len(steps)):
        t0, t1 = float(steps["t"][n - 1]), float(steps["t"][n])
        if t0 not in frames or t1 not in frames:
            raise InputError(f"{base}: no mesh written at t = {steps['t'][n - 1]:g} or {steps['t'][n]:g} "
                             "(run with Output/Exodus Interval = 1)")
        cache = {t: cache[t] if t in cache else level_map(frames[t], pixels) for t in (t0, t1)}  # two maps kept
        before, after = cache[t0], cache[t1]
        change = abs(steps["energy_transferred"][n] - steps["energy"][n - 1]) / reference
        rows.append((n, (after < before).mean(), change, (after > before).mean()))
    rows = np.array(rows)
    exact, coarsened = rows[(rows[:, 1] == 0) & (rows[:, 3] > 0)], rows[rows[:, 1] > 0]
    print(f"{len(exact)} of {len(rows)} steps only refine the previous mesh (and {len(rows) - len(exact) - len(coarsened)} "
          f"keep it): largest energy change {exact[:, 2].max() if len(exact) else 0:.2e} {ref_name}")
    print(f"{len(coarsened)} steps coarsen part of it: energy change per coarsened share of the domain "
          "(median) and the coarsened share (median), in three groups of these steps:")
    for part in np.array_split(coarsened, 3):
        if len(part):
            print(f"  steps {int(part[0, 0])}-{int(part[-1, 0])}: {np.median(part[:, 2] / part[:, 1]):.2e} {ref_name}, "
                  f"share {np.median(part[:, 1]):.3f}")
    if ref_name != "E(0)":
        print(f"E(0) = {energy[0]:g} (the run starts at rest): the energy changes are relative to the largest "
              f"energy of the run, max E = {reference:.6g}")
    if args.check and (len(exact) == 0 or not (exact[:, 2] <= 1e-12).all()):  # NaN fails too
        sys.exit(f"{base}: " + ("no step only refines its predecessor's mesh" if len(exact) == 0 else
                                f"a step that only refines changes the energy by more than 1e-12 {ref_name}"))


reporting(main)
