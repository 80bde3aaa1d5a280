"""What plot_steps.py and summarize_steps.py share: reading a step table of signorini, the table of
one cycle of an adaptive run, the columns a shell-style pattern matches, and the steps of a time
window.

  read_steps(path)                 {column: [float]}, names as written
  cycle_table(base, cycle)         the path of cycle L's table of an adaptive run
  table_path(base, cycle)          <base>.steps.csv, or cycle L's table
  matching(table, pattern, path)   the columns the pattern matches (',' joins patterns)
  window(table, tmin, tmax, path, before=False)  the table cut to tmin <= t <= tmax
"""
import csv
import fnmatch

from tool_errors import InputError, read_text_table, require_complete, require_file


def read_steps(path):
    """{column: [float]} of a step table, names as written ('probe:tip:v:y'); InputError for a
    table that is missing, cut short, has no rows, a value that is not a number or no column t."""
    header, rows = read_text_table(path)
    if "t" not in header:
        raise InputError(f"{path}: no column t: not a step table of signorini")
    return {name: [float(row[c]) for row in rows] for c, name in enumerate(header)}


def matching(table, pattern, path):
    """The columns of table that the panel pattern matches (its ','-separated parts in order)."""
    names = []
    for part in pattern.split(","):
        found = [n for n in table if fnmatch.fnmatchcase(n, part.strip())]
        if not found:
            shown = ", ".join(n for n in table if not n.startswith("time_"))
            raise InputError(f"{path}: no column matches '{part.strip()}' (its columns: {shown})")
        names += [n for n in found if n not in names]
    return names


def cycle_table(base, cycle):
    """The step table of cycle \\p cycle of the adaptive run at base (the last cycle's is <base>.steps.csv);
    InputError for a cycle the run does not have (its cycles.csv counts them)."""
    cycles = base + ".cycles.csv"
    require_file(cycles)
    require_complete(cycles)
    with open(cycles, newline="") as f:
        count = len(list(csv.reader(f))) - 1
    if not 0 <= cycle < count:
        raise InputError(f"--cycle {cycle}: {cycles} has cycles 0 to {count - 1}")
    return base + (".steps.csv" if cycle == count - 1 else f".cycle{cycle}.steps.csv")


def table_path(base, cycle):
    """The step table of the run at base: <base>.steps.csv, or with a cycle that cycle's (cycle_table)."""
    return base + ".steps.csv" if cycle is None else cycle_table(base, cycle)


def window(table, tmin, tmax, path, before=False):
    """The table's steps with tmin <= t <= tmax (and with before, the step before the first of
    them too, where there is one); InputError for a window without a step. t is the double n k
    (3 x 1e-5 > 3e-5): the bounds hold to 1e-9 of the run's duration."""
    slack = 1e-9 * ((table["t"][-1] - table["t"][0]) or 1.0)
    steps = [n for n, t in enumerate(table["t"]) if tmin - slack <= t <= tmax + slack]
    if not steps:
        raise InputError(f"{path}: no step with {tmin:g} <= t <= {tmax:g} (it has t = {table['t'][0]:g} to "
                         f"{table['t'][-1]:g})")
    first = max(steps[0] - 1, 0) if before else steps[0]
    return {name: values[first:steps[-1] + 1] for name, values in table.items()}
