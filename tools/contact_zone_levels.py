#!/usr/bin/python3
"""Levels of the cells along Gamma_C (x = 1) near y = 0.5, where the membrane first touches the
obstacle, in the written Exodus series of a membrane run from t = 0.0375 to one output after the
first contact (first step with active > 0 in <base>.steps.csv); the step mesh's finest level for
comparison. Usage: contact_zone_levels.py OUT/BASENAME (e.g. out/membrane)"""
import glob
import os
import sys

import netCDF4
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exodus_text import names as exodus_names  # noqa: E402

base=sys.argv[1]
steps=np.genfromtxt(base+'.steps.csv',delimiter=',',names=True)
first=steps['t'][np.argmax(steps['active']>0)]
files=sorted(glob.glob(base+'.e*'), key=lambda f: (len(f), f))
print(base, 'first contact t =', first)
for f in files:
    d=netCDF4.Dataset(f)
    t=d['time_whole'][:]
    x=d['coordx'][:]; y=d['coordy'][:]
    conn=d['connect1'][:]-1
    names=exodus_names(d['name_elem_var']) if 'name_elem_var' in d.variables else []
    li=names.index('level')
    for k,tt in enumerate(t):
        if tt>first+0.0126: d.close(); sys.exit()
        if tt<0.0374: continue
        lev=d['vals_elem_var%deb1'%(li+1)][k]
        cx=x[conn].mean(1); cy=y[conn].mean(1)
        onC=(x[conn].max(1)>1-1e-12)
        mid=onC&(np.abs(cy-0.5)<0.15)
        print(f't={tt:.4f} max level {lev.max():.0f}; Gamma_C cells near y=0.5 levels {np.unique(lev[mid]).astype(int)}')
    d.close()
