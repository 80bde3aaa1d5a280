#!/usr/bin/env bash
# Every text row of every Exodus file of a run (variable, block and set names, QA and info
# records) holds nothing behind its first NUL: Exodus 6 writes names from a buffer it does not
# clear, and a user review found pieces of the deck there ('gap\0ame="Final Time" type="double'
# in 13 files of tests/driver/decks/tilted-membrane.xml's cycle 1).
# Usage: text_padding.sh SIGNORINI SOURCE_DIR WORK_DIR
set -uo pipefail
signorini=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
"$signorini" --output-dir "$work" "$src/tests/driver/decks/tilted-membrane.xml" > "$work/run.log" 2>&1 ||
  { cat "$work/run.log"; echo "FAIL: the run"; exit 1; }
/usr/bin/python3 - "$work" <<'PY'
import glob, sys
import netCDF4
import numpy as np
files = sorted(glob.glob(f"{sys.argv[1]}/*.e*"))
bad, rows = [], 0
for f in files:
    with netCDF4.Dataset(f) as d:
        for name, v in d.variables.items():
            if v.dtype != "S1" or v.ndim == 0 or v.size == 0:
                continue
            v.set_auto_chartostring(False)
            v.set_auto_mask(False)
            for row in np.asarray(v[:]).reshape(-1, v.shape[-1]):
                text = row.tobytes()
                rows += 1
                if text.find(b"\0") >= 0 and text[text.find(b"\0"):].strip(b"\0"):
                    bad.append(f"{f.split('/')[-1]} {name}: {text[:48]!r}")
if len(files) < 10:
    bad.append(f"only {len(files)} Exodus files: the test cannot see what it checks")
print("\n".join(bad) or f"{rows} text rows in {len(files)} files, each ends in NULs")
sys.exit(1 if bad else 0)
PY
