"""One-line errors for the scripts in tools/: a missing or unusable input (no such file, a table cut
short or without the columns a script needs, an Exodus file that cannot be read, a run of the wrong
kind) and bad arguments end a script with one line '<script>: error: <message naming the file or
argument>' on stderr and a non-zero exit status (1; 2 for arguments argparse refuses), never a
traceback. So does output that cannot be written (a full disk, /dev/full: '<script>: error: cannot
write output: <reason>', exit status 1), wherever the script prints; output into a pipe closed early
(`| head -1`) ends the script quietly, killed by SIGPIPE, as Unix tools end (both set up on import).

  InputError          raised by the readers below and by the scripts' own checks
  fail(message)       exits with the one line, status 1
  reporting(main)     runs main(); an InputError ends it with the one line
  ArgumentParser      argparse, its usage errors in one line (message, then the usage)
  read_table(path)    a CSV table of signorini (numpy structured array), checked complete
  read_text_table(path)  a step table as (header, rows of texts), every cell a number, names as written
  require_complete_exodus(path)  an Exodus file as long as its header says (not cut short)
  exodus(path)        an Exodus file opened with netCDF4, checked complete
  require_unit_square(path, d)   the cells of an open Exodus file cover [0,1]^2 (a membrane run)
"""
import argparse
import atexit
import csv
import errno
import os
import signal
import sys
import warnings

import numpy as np


# A write into a closed pipe kills the script without a word (Python ignores SIGPIPE and raises
# BrokenPipeError instead, a traceback).
signal.signal(signal.SIGPIPE, signal.SIG_DFL)

# errno values of a write that failed for lack of room (or of a reader): not the script's fault.
WRITE_ERRORS = {errno.ENOSPC, errno.EDQUOT, errno.EFBIG, errno.EPIPE}


def _cannot_write(e):
    """Ends the script at once: '<script>: error: cannot write output: <reason>', exit status 1;
    what stdout still holds is dropped (flushing it would fail again)."""
    where = f": {e.filename}" if getattr(e, "filename", None) else ""
    try:
        sys.stderr.write(f"{os.path.basename(sys.argv[0])}: error: cannot write output: "
                         f"{e.strerror or e}{where}\n")
        sys.stderr.flush()
    finally:
        os._exit(1)


def _excepthook(kind, value, tb, previous=sys.excepthook):
    """A write failure (WRITE_ERRORS) anywhere, also at a script's top level: one line, no traceback."""
    if isinstance(value, OSError) and value.errno in WRITE_ERRORS:
        _cannot_write(value)
    previous(kind, value, tb)


def _flush_stdout():
    """At exit: what is left of stdout written now, so that a failure is reported in one line (the
    interpreter's own last flush would print 'Exception ignored' and exit with status 120)."""
    try:
        if sys.stdout is not None:  # None: started with stdout closed
            sys.stdout.flush()
    except OSError as e:
        _cannot_write(e)


sys.excepthook = _excepthook
atexit.register(_flush_stdout)


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
    """InputError unless path is a file (a directory is named as such)."""
    if os.path.isdir(path):
        raise InputError(f"{path}: a directory, not a file")
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


def read_text_table(path):
    """(header, rows) of the CSV table at path, the cells as written ('probe:tip:v:y' keeps its
    colons); InputError for a table that is missing, cut short, has a header and no rows, rows of
    another length than the header or a cell that is not a number."""
    try:
        require_file(path)
        require_complete(path)  # also: empty
        with open(path, newline="") as f:
            table = list(csv.reader(f))
    except OSError as e:
        raise InputError(f"{path}: {e.strerror}") from None
    header, rows = table[0], table[1:]
    if not rows:
        raise InputError(f"{path}: a header and no rows (a run writes at least step 0)")
    for r, row in enumerate(rows, start=1):
        if len(row) != len(header):
            raise InputError(f"{path}: row {r} has {len(row)} values, the header {len(header)} columns")
        for name, value in zip(header, row):
            try:
                float(value)
            except ValueError:
                raise InputError(f"{path}: row {r}, column {name}: '{value}' is not a number") from None
    return header, rows


def read_table(path, columns=(), min_rows=1):
    """The CSV table at path (numpy structured array, as np.genfromtxt with names=True gives it);
    InputError if it is missing, cut short, empty, has fewer than min_rows rows or lacks one of
    the columns (names as genfromtxt makes them: 'probe:corner' is 'probecorner')."""
    require_file(path)
    if os.path.getsize(path) == 0:  # numpy raises IndexError for a file without a single line
        raise InputError(f"{path}: empty")
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # an empty file: reported below
            data = np.genfromtxt(path, delimiter=",", names=True)
    except IndexError:  # no line with a value (e.g. only line ends)
        raise InputError(f"{path}: empty") from None
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


def classic_netcdf_size(path):
    """The bytes a netCDF classic file (CDF-1, CDF-2 or CDF-5, as Exodus writes it) needs by its
    header: the end of its last variable's data for the number of records the header declares; None
    for other formats (netCDF-4/HDF5) or a header that cannot be parsed (netCDF4 then decides)."""
    import struct

    with open(path, "rb") as f:
        head = f.read(1 << 20)
    if head[:3] != b"CDF" or head[3] not in (1, 2, 5):
        return None
    version, pos = head[3], 4
    wide = version == 5  # 8-byte counts and dimension lengths

    def take(fmt):
        nonlocal pos
        value = struct.unpack_from(">" + fmt, head, pos)
        pos += struct.calcsize(">" + fmt)
        return value[0]

    def count():
        return take("q" if wide else "i")

    def name():
        nonlocal pos
        n = count()
        pos += (n + 3) // 4 * 4

    type_size = {1: 1, 2: 1, 3: 2, 4: 4, 5: 4, 6: 8, 7: 1, 8: 2, 9: 4, 10: 8, 11: 8}

    def attributes():
        nonlocal pos
        take("i")  # NC_ATTRIBUTE or ABSENT
        for _ in range(count()):
            name()
            size = type_size[take("i")] * count()
            pos += (size + 3) // 4 * 4

    try:
        records = count()
        take("i")  # NC_DIMENSION or ABSENT
        lengths = []
        for _ in range(count()):
            name()
            lengths.append(count())
        attributes()
        take("i")  # NC_VARIABLE or ABSENT
        fixed_end, record_vars = 0, []
        for _ in range(count()):
            name()
            dims = [count() for _ in range(count())]
            attributes()
            nc_type = take("i")
            vsize = count() if wide else take("I")
            begin = take("q" if version != 1 else "i")
            if dims and lengths[dims[0]] == 0:  # the unlimited dimension: a record variable
                values = 1
                for d in dims[1:]:
                    values *= lengths[d]
                record_vars.append((begin, vsize, values * type_size[nc_type]))
            else:
                fixed_end = max(fixed_end, begin + vsize)
    except (struct.error, KeyError, IndexError):
        return None
    if records in (-1, 0xFFFFFFFF) or not record_vars:
        return fixed_end
    # A lone record variable's records are not padded to 4 bytes (netCDF classic format).
    record_size = sum(v for _, v, _ in record_vars) if len(record_vars) > 1 else record_vars[0][2]
    return max(fixed_end, max(b + (records - 1) * record_size + unpadded for b, _, unpadded in record_vars))


def require_complete_exodus(path):
    """InputError unless path is a file at least as long as its netCDF header says (netCDF reads
    zeros for the part of a file cut short)."""
    require_file(path)
    needed = classic_netcdf_size(path)
    if needed is not None and os.path.getsize(path) < needed:  # (needed counts no padding after the last value)
        raise InputError(f"{path}: cut short: {os.path.getsize(path)} bytes, its header needs {needed}")


def exodus(path):
    """The Exodus file at path opened with netCDF4 (a context manager); InputError if it is
    missing, not readable as netCDF or shorter than its header says (a file cut short: netCDF
    would read zeros for the missing part)."""
    import netCDF4

    require_complete_exodus(path)
    try:
        return netCDF4.Dataset(path)
    except OSError as e:
        raise InputError(f"{path}: not readable as an Exodus file: {e.strerror or e}") from None


def require_unit_square(path, d):
    """InputError unless the cells of the Exodus file d (open, read from path) cover the unit square
    [0,1]^2 exactly, the domain of the membrane decks (inputs/membrane*.xml): the scripts written for
    those runs refuse others (the bar's [0,0.2]x[0,0.05], an Exodus mesh of another shape)."""
    x, y = np.asarray(d["coordx"][:], dtype=float), np.asarray(d["coordy"][:], dtype=float)
    blocks = [v for v in d.variables if v.startswith("connect")]
    area = 0.0
    for b in blocks:  # the shoelace formula over every cell (corners in order, either orientation)
        conn = np.asarray(d[b][:]) - 1
        cx, cy = x[conn], y[conn]
        area += np.abs(np.sum(cx * np.roll(cy, -1, 1) - np.roll(cx, -1, 1) * cy, axis=1)).sum() / 2
    box = (x.min(), x.max(), y.min(), y.max()) if x.size else (np.nan,) * 4
    if not blocks or not np.allclose(box, (0, 1, 0, 1), rtol=0, atol=1e-12) or abs(area - 1) > 1e-9:
        raise InputError(f"{path}: not a membrane run: the cells do not cover [0,1]^2 (they lie in "
                         f"[{box[0]:g},{box[1]:g}]x[{box[2]:g},{box[3]:g}], area {area:g})")
