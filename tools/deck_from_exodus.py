#!/usr/bin/python3
"""Prints the deck that made an Exodus file of signorini (its info records: the deck as run, with
defaults and command-line overrides), ready to run again.

  tools/deck_from_exodus.py out/membrane.e > membrane-as-run.xml

Records ending in a backslash continue on the next one (Exodus keeps 80 bytes per record; a UTF-8
character may be cut between two). The deck names the output folder and basename of the run: run
it again with --output-dir or another Output/Basename, or it replaces the results it came from.
Uses Debian's python3 with netCDF4.
"""
import os
import sys

import netCDF4

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exodus_text import record_bytes  # noqa: E402


def info_lines(path):
    with netCDF4.Dataset(path) as d:
        if "info_records" not in d.variables:
            return []
        records = [record_bytes(row) for row in d.variables["info_records"][:]]
    lines, pending = [], b""
    for r in records:  # joined as bytes, decoded whole
        if r.endswith(b"\\"):
            pending += r[:-1]
        else:
            lines.append((pending + r).decode("utf-8", errors="replace"))
            pending = b""
    return lines


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    try:
        lines = info_lines(sys.argv[1])
    except OSError as e:
        sys.exit(f"deck_from_exodus.py: error: {sys.argv[1]}: {e.strerror or e}")
    start = next((i for i, l in enumerate(lines) if l.startswith("<ParameterList")), None)
    if start is None:
        sys.exit(f"deck_from_exodus.py: error: {sys.argv[1]}: no deck in its info records")
    print("\n".join(lines[start:]))


if __name__ == "__main__":
    main()
