#!/usr/bin/python3
"""Compares the step tables (<base>.steps.csv and <base>.cycleN.steps.csv) of two runs value by
value as written (17 significant digits, so equal text is equal bits), leaving out the wall-clock
columns time_*. Prints the first difference of every column that differs; exit status 1 if any
differs or the tables do not match in shape.
Usage: compare_step_tables.py BASE_A BASE_B"""
import csv
import glob
import os
import sys

a, b = sys.argv[1], sys.argv[2]
names = sorted(os.path.basename(f)[len(os.path.basename(a)):] for f in glob.glob(a + ".cycle*.steps.csv")) + [".steps.csv"]
differs = False
compared = 0
for suffix in names:
    ta = list(csv.reader(open(a + suffix)))
    tb = list(csv.reader(open(b + suffix)))
    if ta[0] != tb[0] or len(ta) != len(tb):
        print(f"{suffix}: the tables differ in shape ({len(ta)} and {len(tb)} rows)")
        differs = True
        continue
    for c, name in enumerate(ta[0]):
        if name.startswith("time_"):
            continue
        compared += len(ta) - 1
        for row in range(1, len(ta)):
            if ta[row][c] != tb[row][c]:
                print(f"{suffix}: {name} differs first in row {row}: {ta[row][c]} against {tb[row][c]}")
                differs = True
                break
print(f"{len(names)} step tables, {compared} values compared: {'differences' if differs else 'all equal'}")
sys.exit(1 if differs else 0)
