"""Checks the side sets of an Exodus result series against straight boundary pieces.

Usage: check_segment_side_sets.py RESULTS.e --sets NAME,NAME,... [--piece NAME=x0,y0,x1,y1 ...]
                                   [--within NAME=x0,y0,x1,y1 ...] [--empty-in-some NAME ...]
                                   [--same NAME=NAME ...]
In every file of the series (RESULTS.e and RESULTS.e-s.NNNN):
  - the side sets are exactly --sets, in this order (side set 1 first);
  - for each --piece, every side of set NAME has both end points on the segment from (x0, y0) to
    (x1, y1), no side appears twice, and their lengths add up to the segment's length: the set covers
    the piece exactly, on whatever mesh the file holds (hanging nodes included);
  - for each --within, the same but for the lengths (the set lies on the piece, maybe empty);
  - for each --empty-in-some NAME, set NAME is empty in some files and not in others;
  - for each --same A=B, sets A and B hold the same sides.
Exits 1 with a message naming the file and the set on the first violation.
"""
import argparse
import glob
import math
import re
import sys

import netCDF4
import numpy as np


def names(ds, var):
    return [b"".join(row).decode().rstrip("\x00") for row in np.asarray(ds.variables[var][:])] if var in ds.variables else []


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def series(first):
    rest = sorted(glob.glob(glob.escape(first) + "-s.*"), key=lambda p: int(re.search(r"-s\.(\d+)$", p).group(1)))
    return [first] + rest


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("results")
    parser.add_argument("--sets", required=True)
    parser.add_argument("--piece", action="append", default=[])
    parser.add_argument("--within", action="append", default=[])
    parser.add_argument("--empty-in-some", action="append", default=[])
    parser.add_argument("--same", action="append", default=[])
    args = parser.parse_args()
    expected_sets = args.sets.split(",")
    pieces = {}
    for p in args.piece + args.within:
        name, coords = p.split("=")
        pieces[name] = np.array([float(c) for c in coords.split(",")]).reshape(2, 2)
    partial = {p.split("=")[0] for p in args.within}
    emptiness = {name: set() for name in args.empty_in_some}
    files = series(args.results)
    for path in files:
        ds = netCDF4.Dataset(path)
        ds.set_auto_mask(False)
        sets = names(ds, "ss_names")
        if sets != expected_sets:
            fail(f"{path}: side sets {sets}, expected {expected_sets}")
        x, y = np.asarray(ds["coordx"][:], float), np.asarray(ds["coordy"][:], float)
        conn = np.asarray(ds["connect1"][:], np.int64) - 1
        sides = {}
        for i, name in enumerate(sets):
            present = f"elem_ss{i + 1}" in ds.variables  # an empty set has no entries
            elems = np.asarray(ds[f"elem_ss{i + 1}"][:] if present else [], np.int64) - 1
            local = np.asarray(ds[f"side_ss{i + 1}"][:] if present else [], np.int64) - 1
            sides[name] = list(zip(elems.tolist(), local.tolist()))
            if len(set(sides[name])) != len(sides[name]):
                fail(f"{path}: side set '{name}' holds a side twice")
        for name, (p0, p1) in ((n, pieces[n]) for n in pieces):
            direction = p1 - p0
            length = float(np.hypot(*direction))
            tol = 1e-12 * max(length, 1.0)
            total = 0.0
            for e, s in sides[name]:
                a, b = conn[e, s], conn[e, (s + 1) % 4]
                for v in (a, b):
                    q = np.array([x[v], y[v]]) - p0
                    along = float(q @ direction) / length
                    off = abs(float(q[0] * direction[1] - q[1] * direction[0])) / length
                    if off > tol or along < -tol or along > length + tol:
                        fail(f"{path}: side set '{name}': side {s + 1} of element {e + 1} has the end point "
                             f"({x[v]}, {y[v]}) off the piece {p0.tolist()}-{p1.tolist()}")
                total += math.hypot(x[b] - x[a], y[b] - y[a])
            if name not in partial and abs(total - length) > 1e-12 * length * max(1, len(sides[name])):
                fail(f"{path}: side set '{name}': its sides' lengths add up to {total!r}, the piece's length is {length!r}")
        for name in emptiness:
            emptiness[name].add(len(sides[name]) == 0)
        for pair in args.same:
            a, b = pair.split("=")
            if sorted(sides[a]) != sorted(sides[b]):
                fail(f"{path}: side sets '{a}' and '{b}' differ")
        ds.close()
    for name, seen in emptiness.items():
        if seen != {True, False}:
            fail(f"side set '{name}' is {'empty' if True in seen else 'not empty'} in every file")
    print(f"ok: {len(files)} file(s), side sets {expected_sets}")


if __name__ == "__main__":
    main()
