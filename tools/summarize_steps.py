#!/usr/bin/python3
"""Summarises columns of signorini step tables (<base>.steps.csv) over a time window: for engineers'
reports (a support's mean reaction, a peak stress and when it occurs, an impact's impulse) and for
checks of a run against hand calculations.

  tools/summarize_steps.py BASE [BASE ...] [--columns PATTERN ...] [--cycle L] [--tmin T0] [--tmax T1]
                           [--csv]

For every BASE and every column that a PATTERN matches (shell-style as in plot_steps.py: 'reaction*',
'probe:tip:*y'; ',' joins patterns; default: the force, moment, stress and energy columns the table
has), over the steps with T0 <= t <= T1 (the bounds hold to 1e-9 of the run's duration, as a step's t
is the double n k):
  mean      the time mean, integral / (t_last - t_first) (the value itself for a window of one step)
  integral  int x dt by the trapezoidal rule over the window's steps: for a force its impulse
            [N s/m]; with the paper's scheme (Alpha 1/2) the momentum changes by exactly the
            trapezoidal integral of the force resultant (applied_load + contact + reaction)
  min, max  the smallest and the largest value and the (first) time of each; for a column with
            place columns (max_von_mises with max_von_mises_at_x, _at_y) also the place of the max
  last      the value at the window's last step
(place columns are not summarised themselves; steps without a value, nan, are left out and
counted: the integral takes the intervals between two steps with values) and, where the table has
the contact columns, a contact summary: the steps with an active contact segment, the first and the
last of them (first contact, last step in contact), the number of separate contact intervals, the most active segments, the
largest |contact_force| and its time, and the contact force's impulse. Peaks are those of the
discrete run: with the paper's contact force the contact chatters, and its peak force and time
change with the time step and the mesh (by 20% and several milliseconds on a clamped beam) where
the mean and the impulse hardly do; a peak stress at a clamped corner grows with refinement
(singular). --csv prints one CSV row per run and column (run, column, steps, t_first, t_last, mean,
integral, min, t_min, max, t_max, x_at_max, y_at_max (empty without place columns), last, missing)
instead, and no contact summary. --cycle L
takes cycle L's tables of adaptive runs. A pattern that matches no column, a window without a step,
a missing or cut-short table stop the script with one line naming it.
Uses Debian's python3 (no extra modules).
"""
import argparse
import csv
import fnmatch
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from step_selection import matching, read_steps, table_path, window  # noqa: E402
from tool_errors import ArgumentParser, InputError, reporting  # noqa: E402

# The default columns: the physical quantities an engineer reads first (those the table has).
DEFAULT_PATTERNS = ["energy", "contact_force", "contact_moment", "reaction*", "applied*", "max_von_mises"]


def is_place(column, table):
    """Whether column is the x or y place column of another column of the table (max_von_mises_at_x)."""
    for suffix in ("_at_x", "_at_y"):
        if column.endswith(suffix) and column[:-len(suffix)] in table:
            return True
    return False


def place_of_max(table, column, n):
    """The place (x, y) the table gives for column's value at step n, or None."""
    if n is not None and column + "_at_x" in table and column + "_at_y" in table:
        return table[column + "_at_x"][n], table[column + "_at_y"][n]
    return None


def summary(t, x):
    """{mean, integral, min, t_min, max, t_max, n_max, last, missing} of the values x at the times t;
    steps without a value (NaN) are left out: the integral takes the intervals between two steps
    with values, the mean divides it by their length, min and max the steps with values, and
    missing counts the others (all NaN where no step has a value)."""
    nan = float("nan")
    finite = [n for n in range(len(x)) if math.isfinite(x[n])]
    pairs = [n for n in range(1, len(t)) if math.isfinite(x[n]) and math.isfinite(x[n - 1])]
    integral = sum(0.5 * (t[n] - t[n - 1]) * (x[n] + x[n - 1]) for n in pairs)
    span = sum(t[n] - t[n - 1] for n in pairs)
    if not finite:
        return {"mean": nan, "integral": nan, "min": nan, "t_min": nan, "max": nan, "t_max": nan, "n_max": None,
                "last": x[-1], "missing": len(x)}
    low = min(finite, key=lambda n: (x[n], n))
    high = min(finite, key=lambda n: (-x[n], n))
    return {"mean": integral / span if span > 0 else x[finite[0]], "integral": integral, "min": x[low],
            "t_min": t[low], "max": x[high], "t_max": t[high], "n_max": high, "last": x[-1],
            "missing": len(x) - len(finite)}


def contact_summary(table):
    """Lines on the contact of a table with the columns active and contact_force (empty without them)."""
    if "active" not in table or "contact_force" not in table:
        return []
    t, active, force = table["t"], table["active"], table["contact_force"]
    touching = [n for n in range(len(t)) if active[n] > 0]
    if not touching:
        return [f"  contact: none in the window ({len(t)} steps, no active segment)"]
    intervals = 1 + sum(1 for a, b in zip(touching, touching[1:]) if b != a + 1)
    peak = min(range(len(t)), key=lambda n: (-abs(force[n]), n))
    impulse = summary(t, force)["integral"]
    return [f"  contact: {len(touching)} of {len(t)} steps with an active segment, from t = {t[touching[0]]:.6g} "
            f"to t = {t[touching[-1]]:.6g} in {intervals} interval(s); at most {max(active):.0f} active segments",
            f"  contact_force: largest |value| {force[peak]:.6g} at t = {t[peak]:.6g}; impulse {impulse:.6g}"]


def main():
    ap = ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("bases", nargs="+", metavar="BASE", help="output base of a run (folder/basename)")
    ap.add_argument("--columns", nargs="+", metavar="PATTERN",
                    help="the columns to summarise (shell-style; ',' joins patterns; default: forces, moments, "
                         "stress, energy)")
    ap.add_argument("--cycle", type=int, help="cycle L of adaptive runs (<base>.cycle<L>.steps.csv)")
    ap.add_argument("--tmin", type=float, default=-float("inf"), help="the steps with t >= T0")
    ap.add_argument("--tmax", type=float, default=float("inf"), help="the steps with t <= T1")
    ap.add_argument("--csv", action="store_true", help="one CSV row per run and column, no contact summary")
    a = ap.parse_args()
    for name in ("tmin", "tmax"):
        if math.isnan(getattr(a, name)):
            raise InputError(f"--{name} nan: not a time")
    if not a.tmin <= a.tmax:
        raise InputError(f"--tmin {a.tmin} is after --tmax {a.tmax}")
    runs = []  # (base, table, columns): every input read and checked before anything is printed
    for base in a.bases:
        path = table_path(base, a.cycle)
        table = window(read_steps(path), a.tmin, a.tmax, path)
        if a.columns:
            columns = []
            for p in a.columns:
                found = matching(table, p, path)
                if all(is_place(c, table) for c in found):
                    raise InputError(f"{path}: '{p}' matches only place columns ({', '.join(found)}): their "
                                     f"quantity's summary gives the place of its largest value")
                columns += found
        else:
            columns = [c for p in DEFAULT_PATTERNS for c in table if fnmatch.fnmatchcase(c, p)]
        # a place column (x_at_x, x_at_y) belongs to its quantity x: its max's place, not summarised
        columns = [c for c in dict.fromkeys(columns) if not is_place(c, table)]
        runs.append((base, table, columns))
    if a.csv:
        w = csv.writer(sys.stdout, lineterminator="\n")
        w.writerow(["run", "column", "steps", "t_first", "t_last", "mean", "integral", "min", "t_min", "max", "t_max",
                    "x_at_max", "y_at_max", "last", "missing"])
        for base, table, columns in runs:
            t = table["t"]
            for c in columns:
                s = summary(t, table[c])
                place = place_of_max(table, c, s["n_max"])
                w.writerow([base, c, len(t), repr(t[0]), repr(t[-1])] +
                           [repr(s[k]) for k in ("mean", "integral", "min", "t_min", "max", "t_max")] +
                           ([repr(place[0]), repr(place[1])] if place else ["", ""]) + [repr(s["last"]), s["missing"]])
        return
    for base, table, columns in runs:
        t = table["t"]
        print(f"{base}: {len(t)} step(s), t = {t[0]:.6g} to {t[-1]:.6g}")
        width = max([len(c) for c in columns] + [6])
        print(f"  {'column':<{width}} {'mean':>13} {'integral':>13} {'min':>13} {'at t':>10} {'max':>13} "
              f"{'at t':>10} {'last':>13}")
        summaries = {c: summary(t, table[c]) for c in columns}
        for c, s in summaries.items():
            print(f"  {c:<{width}} {s['mean']:>13.6g} {s['integral']:>13.6g} {s['min']:>13.6g} {s['t_min']:>10.4g} "
                  f"{s['max']:>13.6g} {s['t_max']:>10.4g} {s['last']:>13.6g}")
        for c, s in summaries.items():  # steps without a value (a Stress Region that holds no cell of a later mesh)
            if s["missing"]:
                print(f"  {c}: no value (nan) in {s['missing']} of {len(t)} steps, left out")
        for c, s in summaries.items():  # where the largest value of a column with place columns was
            place = place_of_max(table, c, s["n_max"])
            if place:
                print(f"  {c}: the largest, {s['max']:.6g} at t = {s['t_max']:.6g}, at ({place[0]:.6g}, {place[1]:.6g})")
        for line in contact_summary(table):
            print(line)


if __name__ == "__main__":
    reporting(main)
