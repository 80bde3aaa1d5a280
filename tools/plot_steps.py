#!/usr/bin/python3
"""Plots columns of signorini step tables (<base>.steps.csv) against time, for any run: probes,
energies and work, contact force, KKT columns, iterations.

  tools/plot_steps.py BASE [BASE ...] --columns PATTERN [PATTERN ...] --out FILE.png [--rate]
                      [--cycle L] [--tmin T0] [--tmax T1]

Each PATTERN is one panel and draws every column it matches (shell-style: 'probe:tip*' gives the
tip's u, v and a, 'probe:tip:*y' an elastic body's y components; 'energy' only the column energy;
several patterns in one panel joined by ',' as in 'energy,kinetic_energy'), for every BASE (runs
compared in one figure; a legend names a run by its basename, or by its path where two runs share
a basename). --rate draws the
step differences (x^n - x^{n-1}) / k instead of the values: the motion of a probe's u, which in
contact differs from Newmark's own v^n (README, Outputs). --cycle L takes the tables of cycle L of
adaptive runs (<base>.cycle<L>.steps.csv; the last cycle is <base>.steps.csv; a cycle the run does
not have is refused). --tmin, --tmax draw the steps with T0 <= t <= T1 (a window without a step is
refused; the bounds hold to 1e-9 of the run's duration, as a step's t is the double n k). A column
keeps its colour in every run of a panel, and each run has its own line style (solid, dashed,
dotted, dash-dotted; from the fifth run on with markers); the legend stands beside the panel. A
pattern that
matches no column of a run, a missing or cut-short table stop the script with one line naming
it, before anything is written. Uses Debian's python3 with matplotlib.
"""
import argparse
import csv
import fnmatch
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from tool_errors import (ArgumentParser, InputError, read_text_table, reporting, require_complete,  # noqa: E402
                         require_file)


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
    """The step table of cycle \p cycle of the adaptive run at base (the last cycle's is <base>.steps.csv);
    InputError for a cycle the run does not have (its cycles.csv counts them)."""
    cycles = base + ".cycles.csv"
    require_file(cycles)
    require_complete(cycles)
    with open(cycles, newline="") as f:
        count = len(list(csv.reader(f))) - 1
    if not 0 <= cycle < count:
        raise InputError(f"--cycle {cycle}: {cycles} has cycles 0 to {count - 1}")
    return base + (".steps.csv" if cycle == count - 1 else f".cycle{cycle}.steps.csv")


def main():
    ap = ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("bases", nargs="+", metavar="BASE", help="output base of a run (folder/basename)")
    ap.add_argument("--columns", nargs="+", required=True, metavar="PATTERN",
                    help="one panel per pattern: the columns it matches (shell-style; ',' joins patterns)")
    ap.add_argument("--rate", action="store_true", help="draw (x^n - x^{n-1}) / k instead of x^n")
    ap.add_argument("--cycle", type=int, help="cycle L of adaptive runs (<base>.cycle<L>.steps.csv)")
    ap.add_argument("--tmin", type=float, default=-float("inf"), help="draw the steps with t >= T0")
    ap.add_argument("--tmax", type=float, default=float("inf"), help="draw the steps with t <= T1")
    ap.add_argument("--out", required=True, help="the PNG file to write")
    a = ap.parse_args()
    for name in ("tmin", "tmax"):
        if math.isnan(getattr(a, name)):
            raise InputError(f"--{name} nan: not a time")
    if not a.tmin <= a.tmax:
        raise InputError(f"--tmin {a.tmin} is after --tmax {a.tmax}")
    suffix = ".steps.csv" if a.cycle is None else f".cycle{a.cycle}.steps.csv"
    names = [os.path.basename(b) for b in a.bases]
    runs = []  # (label, table, [[columns] per panel]): every input read and checked before drawing
    for base in a.bases:
        path = base + suffix
        if a.cycle is not None:
            path = cycle_table(base, a.cycle)
        table = read_steps(path)
        # t is the double n k (3 x 1e-5 > 3e-5): the bounds hold to 1e-9 of the run's duration
        slack = 1e-9 * ((table["t"][-1] - table["t"][0]) or 1.0)
        window = [n for n, t in enumerate(table["t"]) if a.tmin - slack <= t <= a.tmax + slack]
        if not window:
            raise InputError(f"{path}: no step with {a.tmin:g} <= t <= {a.tmax:g} (it has t = {table['t'][0]:g} to "
                             f"{table['t'][-1]:g})")
        # with --rate, the step before the window too: the difference into its first step
        first = max(window[0] - 1, 0) if a.rate else window[0]
        table = {name: values[first:window[-1] + 1] for name, values in table.items()}
        if a.rate and len(table["t"]) < 2:
            raise InputError(f"{path}: one step: no difference to draw (--rate)")
        label = os.path.basename(base) if names.count(os.path.basename(base)) == 1 else base
        runs.append((label, table, [matching(table, p, path) for p in a.columns]))
    if os.path.isdir(a.out):
        raise InputError(f"--out {a.out}: a folder, not a file")
    folder = os.path.dirname(os.path.abspath(a.out))
    if not os.path.isdir(folder):
        raise InputError(f"--out {a.out}: no folder {folder}")

    styles = ["-", "--", ":", "-."]
    fig, axes = plt.subplots(len(a.columns), 1, figsize=(11, 2.8 * len(a.columns)), sharex=True, squeeze=False)
    for panel, pattern in enumerate(a.columns):
        ax = axes[panel][0]
        colours = {}  # column -> colour, the same in every run
        for r, (label, table, columns) in enumerate(runs):
            t = table["t"]
            for name in columns[panel]:
                colour = colours.setdefault(name, f"C{len(colours) % 10}")
                x = table[name]
                # a fifth run and later: the line styles again, with markers
                marker = [None, "o", "s", "^", "v"][(r // len(styles)) % 5]
                style = dict(lw=1, color=colour, ls=styles[r % len(styles)], marker=marker, markersize=3,
                             markevery=max(1, len(t) // 12))
                if a.rate:
                    y = [(x[n] - x[n - 1]) / (t[n] - t[n - 1]) for n in range(1, len(t))]
                    ax.plot(t[1:], y, label=f"{label}: d({name})/dt", **style)
                else:
                    ax.plot(t, x, label=f"{label}: {name}", **style)
        ax.set_ylabel(("rate of " if a.rate else "") + pattern, fontsize=8)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    axes[-1][0].set_xlabel("t")
    fig.tight_layout()
    fig.savefig(a.out, dpi=130)
    plt.close(fig)
    drawn = sum(len(c) for _, _, panels in runs for c in panels)
    window = ""
    if a.tmin > -float("inf") or a.tmax < float("inf"):  # the first run's steps drawn
        t = runs[0][1]["t"][1:] if a.rate else runs[0][1]["t"]
        window = f", {len(t)} step(s) of t in [{t[0]:g}, {t[-1]:g}] in {runs[0][0]}"
    print(f"wrote {a.out}: {drawn} curve(s) in {len(a.columns)} panel(s){window}")


if __name__ == "__main__":
    reporting(main)
