#!/usr/bin/python3
"""Prints the deck that made an Exodus file of signorini (its info records: the deck as run, with
defaults and command-line overrides), ready to run again.

  tools/deck_from_exodus.py out/membrane.e > membrane-as-run.xml

Records ending in a backslash continue on the next one (Exodus keeps 80 bytes per record; a UTF-8
character may be cut between two). The deck names the output folder and basename of the run: run
it again with --output-dir or another Output/Basename, or it replaces the results it came from.
Uses Debian's python3 with netCDF4.
"""
import argparse
import os
import sys


sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exodus_text import record_bytes  # noqa: E402
from tool_errors import ArgumentParser, InputError, exodus, fail  # noqa: E402


def info_lines(path):
    with exodus(path) as d:
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
    ap = ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("exodus_file", help="an Exodus file written by signorini (e.g. out/membrane.e)")
    path = ap.parse_args().exodus_file
    try:
        lines = info_lines(path)
    except InputError as e:
        fail(e)
    except OSError as e:
        fail(f"{path}: {e.strerror or e}")
    start = next((i for i, l in enumerate(lines) if l.startswith("<ParameterList")), None)
    if start is None:
        fail(f"{path}: no deck in its info records")
    print("\n".join(lines[start:]))


if __name__ == "__main__":
    main()
