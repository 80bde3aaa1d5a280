"""One-line errors for the scripts in tools/: a missing or unusable input (no such file, a table cut
short or without the columns a script needs, an Exodus file that cannot be read, a run of the wrong
kind) and bad arguments end a script with one line '<script>: error: <message naming the file or
argument>' on stderr and a non-zero exit status (1; 2 for arguments argparse refuses), never a
traceback.

  InputError          raised by the readers below and by the scripts' own checks
  fail(message)       exits with the one line, status 1
  reporting(main)     runs main(); an InputError ends it with the one line
  ArgumentParser      argparse, its usage errors in one line (message, then the usage)
  read_table(path)    a CSV table of signorini (numpy structured array), checked complete
  exodus(path)        an Exodus file opened with netCDF4
"""
import argparse
import os
import sys
import warnings

import numpy as np


class InputError(Exception):
    """A missing or unusable input: reported in one line before anything is written."""


def fail(message):
    """Ends the script: '<script>: error: message' on stderr, exit status 1."""
    sys.exit(f"{os.path.basename(sys.argv[0])}: error: {message}")


def reporting(main):
    """Runs main(); an InputError ends the script in one line (fail)."""
    try:
        return main()
    except InputError as e:
        fail(e)


class ArgumentParser(argparse.ArgumentParser):
    """argparse.ArgumentParser whose usage errors are one line: the message, then the usage."""

    def error(self, message):
        usage = " ".join(self.format_usage().split())
        self.exit(2, f"{self.prog}: error: {message} ({usage})\n")


def require_file(path):
    """InputError unless path is a file."""
    if not os.path.isfile(path):
        raise InputError(f"{path}: no such file")


def require_complete(path):
    """InputError unless the text at path ends with a line end (signorini ends every row with one;
    a table without it was cut short, possibly inside its last number)."""
    with open(path, "rb") as f:
        f.seek(0, os.SEEK_END)
        if f.tell() == 0:
            raise InputError(f"{path}: empty")
        f.seek(-1, os.SEEK_END)
        if f.read(1) != b"\n":
            raise InputError(f"{path}: not a complete table: its last line has no line end (cut short)")


def read_table(path, columns=(), min_rows=1):
    """The CSV table at path (numpy structured array, as np.genfromtxt with names=True gives it);
    InputError if it is missing, cut short, empty, has fewer than min_rows rows or lacks one of
    the columns (names as genfromtxt makes them: 'probe:corner' is 'probecorner')."""
    require_file(path)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # an empty file: reported below
            data = np.genfromtxt(path, delimiter=",", names=True)
    except ValueError as e:  # rows of different lengths
        raise InputError(f"{path}: not a complete table: {str(e).strip().splitlines()[-1].strip()}") from None
    if data.dtype.names is None or data.size == 0:
        raise InputError(f"{path}: no rows")
    require_complete(path)
    missing = [c for c in columns if c not in data.dtype.names]
    if missing:
        raise InputError(f"{path}: no column {', '.join(missing)}")
    if data.size < min_rows:
        raise InputError(f"{path}: {data.size} rows, at least {min_rows} needed")
    return data


def exodus(path):
    """The Exodus file at path opened with netCDF4 (a context manager); InputError if it is
    missing or not readable as netCDF."""
    import netCDF4

    require_file(path)
    try:
        return netCDF4.Dataset(path)
    except OSError as e:
        raise InputError(f"{path}: not readable as an Exodus file: {e.strerror or e}") from None
