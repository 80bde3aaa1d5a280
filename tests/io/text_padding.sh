#!/usr/bin/env bash
# Every text row of every Exodus file of a run (variable, block and set names, QA and info
# records) is text (UTF-8 without control bytes) up to its first NUL and holds nothing behind it:
# Exodus 6 writes names from a buffer it does not clear, and a user review found pieces of the deck
# there ('gap\0ame="Final Time" type="double' in 13 files of tests/driver/decks/tilted-membrane.xml's
# cycle 1).
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
                end = text.find(b"\0")
                head = text if end < 0 else text[:end]
                try:  # what comes before the NUL (a whole row without one) is text: UTF-8, no control bytes
                    readable = not any(ord(c) < 32 for c in head.decode("utf-8"))
                except UnicodeDecodeError:
                    readable = False
                if not readable or (end >= 0 and text[end:].strip(b"\0")):
                    bad.append(f"{f.split('/')[-1]} {name}: {text[:48]!r}")
if len(files) < 10:
    bad.append(f"only {len(files)} Exodus files: the test cannot see what it checks")
print("\n".join(bad) or f"{rows} text rows in {len(files)} files, each text up to its NUL and NULs after it")
sys.exit(1 if bad else 0)
PY
