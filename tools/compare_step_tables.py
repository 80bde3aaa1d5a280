#!/usr/bin/python3
"""Compares the step tables (<base>.steps.csv and <base>.cycleN.steps.csv) of two runs value by
value, bit for bit (the doubles the text reads back to, so tables written with 17 significant
digits by earlier versions compare with today's shortest text), leaving out the wall-clock
columns time_*. Prints the first difference of every column that differs; exit status 1 if any
differs, the tables do not match in shape or no value was compared. With --common-columns, columns that only one of the
runs has (a version that added a column) are named and left out instead. With --rtol R, values
compare equal within R times the largest magnitude of their column in the two tables (runs that
need not agree bit for bit: ordinary arithmetic on other numbers of ranks, elasticity), and the
largest difference of every column is printed; the counts too (dofs, active, iterations) compare
within R of their largest value. With --atol A too, values also compare equal within A (in the
column's unit): a column that is rounding noise around 0 in both runs (a symmetric body's horizontal
reaction, 1e-5 N/m beside vertical reactions of 1e7) then does not count as a difference.
Usage: compare_step_tables.py BASE_A BASE_B [--common-columns] [--rtol R [--atol A]]"""
import argparse
import glob
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from tool_errors import ArgumentParser, InputError, fail, read_text_table  # noqa: E402

ap = ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
ap.add_argument("base_a", help="output base of one run (folder/basename)")
ap.add_argument("base_b", help="output base of the other run")
ap.add_argument("--common-columns", action="store_true", help="leave out columns that only one run has")
ap.add_argument("--rtol", type=float, help="compare within this fraction of each column's largest magnitude "
                "(default: bit for bit)")
ap.add_argument("--atol", type=float, default=0.0, help="with --rtol: also equal within this absolute difference")
args = ap.parse_args()
a, b, common, rtol, atol = args.base_a, args.base_b, args.common_columns, args.rtol, args.atol
if rtol is not None and not rtol >= 0:
    fail(f"--rtol {rtol}: not a number >= 0")
if not (atol >= 0 and math.isfinite(atol)):
    fail(f"--atol {atol}: not a finite number >= 0")
if atol > 0 and rtol is None:
    fail("--atol needs --rtol (without it the tables compare bit for bit)")


def suffixes(base):
    """The step tables' suffixes of a run: '.cycle<l>.steps.csv' in cycle order, then '.steps.csv'."""
    cycles = glob.glob(glob.escape(base) + ".cycle*.steps.csv")
    return sorted((f[len(base):] for f in cycles), key=lambda s: int(s.split(".")[1][5:])) + [".steps.csv"]


def read(path):
    """The table at path: its header, then its rows (texts); one line (fail) for a table that is
    missing, cut short, has rows of another length than the header or a cell that is not a number."""
    try:
        header, rows = read_text_table(path)
    except InputError as e:
        fail(e)
    return [header] + rows


for base in (a, b):
    if not os.path.isfile(base + ".steps.csv"):
        fail(f"{base}.steps.csv: no such file")
names = suffixes(a)
if names != suffixes(b):
    fail(f"the runs have different step tables: {a}: {', '.join(names)}; {b}: {', '.join(suffixes(b))}")
differs = False
compared = 0
tables = {suffix: (read(a + suffix), read(b + suffix)) for suffix in names}  # every table checked before output
if not any(n in tb[0] and not n.startswith("time_") for ta, tb in tables.values() for n in ta[0]):
    fail(f"{a} and {b}: no column to compare (besides time_*): nothing is shown equal")
for suffix in names:
    ta, tb = tables[suffix]
    if ta[0] != tb[0] and not common:
        only_a = [n for n in ta[0] if n not in tb[0]]
        only_b = [n for n in tb[0] if n not in ta[0]]
        what = (f"columns only in {a + suffix}: {', '.join(only_a) or 'none'}; only in {b + suffix}: "
                f"{', '.join(only_b) or 'none'} (--common-columns leaves them out)") if only_a or only_b else \
            "the same columns in another order"
        print(f"{suffix}: the headers differ: {what}")
        differs = True
        continue
    if len(ta) != len(tb):
        print(f"{suffix}: the tables differ in length ({len(ta) - 1} and {len(tb) - 1} rows)")
        differs = True
        continue
    only = [n for n in ta[0] if n not in tb[0]] + [n for n in tb[0] if n not in ta[0]]
    if only:
        print(f"{suffix}: left out, in one run only: {', '.join(only)}")
    for c, name in enumerate(ta[0]):
        if name.startswith("time_") or name not in tb[0]:
            continue
        cb = tb[0].index(name)
        compared += len(ta) - 1
        if rtol is None:
            for row in range(1, len(ta)):
                if float(ta[row][c]).hex() != float(tb[row][cb]).hex():
                    print(f"{suffix}: {name} differs first in row {row}: {ta[row][c]} against {tb[row][cb]}")
                    differs = True
                    break
            continue
        xa = [float(ta[row][c]) for row in range(1, len(ta))]
        xb = [float(tb[row][cb]) for row in range(1, len(tb))]
        scale = max([abs(x) for x in xa + xb if math.isfinite(x)], default=0.0)
        same = [x == y or (math.isfinite(x) and math.isfinite(y) and abs(x - y) <= max(rtol * scale, atol))
                or (math.isnan(x) and math.isnan(y)) for x, y in zip(xa, xb)]
        gaps = [abs(x - y) for x, y in zip(xa, xb) if math.isfinite(x) and math.isfinite(y)]
        largest = max(gaps, default=0.0) / scale if scale > 0 else 0.0
        if not all(same):
            row = same.index(False) + 1
            print(f"{suffix}: {name} differs first in row {row}: {ta[row][c]} against {tb[row][cb]} "
                  f"(largest difference {largest:.3g} of the column's largest magnitude {scale:.6g})")
            differs = True
        elif largest > 0:
            print(f"{suffix}: {name}: largest difference {largest:.3g} of the column's largest magnitude {scale:.6g}")
within = "" if rtol is None else f" within {rtol:g} of each column's largest magnitude" + (
    f" or {atol:g}" if atol > 0 else "")
print(f"{len(names)} step tables, {compared} values compared{within}: {'differences' if differs else 'all equal'}")
sys.exit(1 if differs else 0)
