"""Text of Exodus II character records (variable names, info lines) read with netCDF4.

A record holds its text up to the first NUL. The bytes after it are undefined: the Exodus library
writes a name and its NUL only, into a file created without fill values, so they may hold whatever
the buffer held (pieces of the deck were seen). Everything from the first NUL on is cut off.
"""
import numpy as np


def record_bytes(row):
    """The bytes of one character record up to its first NUL."""
    out = bytearray()
    for c in np.ma.getdata(row):
        b = bytes(c)
        if b in (b"", b"\x00"):
            break
        out += b
    return bytes(out)


def names(var):
    """The names in a name variable (name_elem_var, name_nod_var, ...), blanks stripped."""
    return [record_bytes(row).decode().strip() for row in var[:]]
