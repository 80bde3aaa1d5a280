#!/usr/bin/python3
"""Levels of the cells along Gamma_C (x = 1) near y = 0.5, where the membrane first touches the
obstacle, in the written Exodus series of a membrane run from t = 0.0375 to one output after the
first contact (first step with active > 0 in <base>.steps.csv); the step mesh's finest level for
comparison. Usage: contact_zone_levels.py OUT/BASENAME (e.g. out/membrane)"""
import argparse
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exodus_text import names as exodus_names  # noqa: E402
from tool_errors import (ArgumentParser, InputError, exodus, read_table, reporting,  # noqa: E402
                         require_unit_square)


def main():
    ap=ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('base', help='output base of the run (folder/basename)')
    base=ap.parse_args().base
    steps=np.atleast_1d(read_table(base+'.steps.csv', ['t', 'active']))
    if not np.any(steps['active']>0):
        raise InputError(f'{base}.steps.csv: no step with active > 0 (no contact in the run)')
    first=steps['t'][np.argmax(steps['active']>0)]
    files=sorted(glob.glob(glob.escape(base)+'.e*'), key=lambda f: (len(f), f))
    if not files:
        raise InputError(f'{base}.e: no such file (the run wrote no Exodus output? Output/Write Exodus)')
    with exodus(files[0]) as d:  # a run of another kind refused before any output
        require_unit_square(files[0], d)
    print(base, 'first contact t =', first)
    for f in files:
        with exodus(f) as d:
            t=d['time_whole'][:]
            x=d['coordx'][:]; y=d['coordy'][:]
            conn=d['connect1'][:]-1
            names=exodus_names(d['name_elem_var']) if 'name_elem_var' in d.variables else []
            if 'level' not in names:
                raise InputError(f'{f}: no element variable level')
            li=names.index('level')
            for k,tt in enumerate(t):
                if tt>first+0.0126: return
                if tt<0.0374: continue
                lev=d['vals_elem_var%deb1'%(li+1)][k]
                cy=y[conn].mean(1)
                onC=(x[conn].max(1)>1-1e-12)
                mid=onC&(np.abs(cy-0.5)<0.15)
                print(f't={tt:.4f} max level {lev.max():.0f}; Gamma_C cells near y=0.5 levels {np.unique(lev[mid]).astype(int)}')


reporting(main)
