"""What the dynamics test scripts' Python checks share (run_helpers.sh puts this folder on
PYTHONPATH): reading a step table, failing a test, and writing a control table with one column
altered."""
import csv
import sys


def table(path):
    """The rows of a step table (CSV) as dicts of strings."""
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def fail(message):
    """Prints FAIL: message and ends the check with status 1."""
    print("FAIL:", message)
    sys.exit(1)


def write_altered(source, column, factor, target):
    """Writes step table source to target with column scaled by factor, or one step late when factor is None
    (a control the checkers must fail)."""
    rows = table(source)
    if factor is None:
        for n in range(len(rows) - 1, 0, -1):
            rows[n][column] = rows[n - 1][column]
    else:
        for r in rows:
            r[column] = repr(factor * float(r[column]))
    with open(target, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
