#!/usr/bin/python3
"""Plots columns of signorini step tables (<base>.steps.csv) against time, for any run: probes,
energies and work, contact force, KKT columns, iterations.

  tools/plot_steps.py BASE [BASE ...] --columns PATTERN [PATTERN ...] --out FILE.png [--rate]
                      [--cycle L] [--tmin T0] [--tmax T1] [--scale PATTERN=FACTOR ...]
                      [--hline PANEL:VALUE[:LABEL] ...]

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
dotted, dash-dotted; from the fifth run on with markers); the legend stands beside the panel.
--scale 'probe:*=1000' draws the columns the pattern matches times the factor (m as mm; the legend
says "x 1000"; the first --scale that matches a column applies). --hline 2:135.87:weight draws a
reference line at 135.87 in the second panel (panels are numbered from 1 in the order of
--columns; the value in the units drawn, after --scale), named in the legend by its label or its
value. A
pattern that
matches no column of a run, a missing or cut-short table stop the script with one line naming
it, before anything is written. Uses Debian's python3 with matplotlib.
"""
import argparse
import fnmatch
import math
import os
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from step_selection import matching, read_steps, table_path, window  # noqa: E402
from tool_errors import ArgumentParser, InputError, reporting  # noqa: E402


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
    ap.add_argument("--scale", action="append", default=[], metavar="PATTERN=FACTOR",
                    help="draw the columns the pattern matches times the factor")
    ap.add_argument("--hline", action="append", default=[], metavar="PANEL:VALUE[:LABEL]",
                    help="a reference line at VALUE in panel PANEL (1 = the first pattern of --columns)")
    a = ap.parse_args()
    scales = []  # (pattern, factor)
    for item in a.scale:
        pattern, _, factor = item.rpartition("=")
        try:
            value = float(factor)
        except ValueError:
            value = math.nan
        if not pattern or not math.isfinite(value) or value == 0:
            raise InputError(f"--scale {item}: expected PATTERN=FACTOR with a finite factor other than 0")
        scales.append((pattern, value))
    lines = []  # (panel index, value, label)
    for item in a.hline:
        parts = item.split(":", 2)
        try:
            panel, value = int(parts[0]), float(parts[1])
        except (ValueError, IndexError):
            panel, value = 0, math.nan
        if not 1 <= panel <= len(a.columns) or not math.isfinite(value):
            raise InputError(f"--hline {item}: expected PANEL:VALUE[:LABEL] with PANEL 1 to {len(a.columns)} "
                             f"(one per --columns pattern) and a finite VALUE")
        lines.append((panel - 1, value, parts[2] if len(parts) > 2 and parts[2] else f"{value:g}"))
    for name in ("tmin", "tmax"):
        if math.isnan(getattr(a, name)):
            raise InputError(f"--{name} nan: not a time")
    if not a.tmin <= a.tmax:
        raise InputError(f"--tmin {a.tmin} is after --tmax {a.tmax}")
    names = [os.path.basename(b) for b in a.bases]
    runs = []  # (label, table, [[columns] per panel]): every input read and checked before drawing
    for base in a.bases:
        path = table_path(base, a.cycle)
        # with --rate, the step before the window too: the difference into its first step
        table = window(read_steps(path), a.tmin, a.tmax, path, before=a.rate)
        if a.rate and len(table["t"]) < 2:
            raise InputError(f"{path}: one step: no difference to draw (--rate)")
        label = os.path.basename(base) if names.count(os.path.basename(base)) == 1 else base
        runs.append((label, table, [matching(table, p, path) for p in a.columns]))
        for pattern, _ in scales:
            if not any(fnmatch.fnmatchcase(n, pattern) for panel in runs[-1][2] for n in panel):
                raise InputError(f"--scale {pattern}: matches no column drawn from {path}")
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
                factor = next((f for p, f in scales if fnmatch.fnmatchcase(name, p)), None)
                x = [factor * value for value in table[name]] if factor is not None else table[name]
                shown = f"{name} x {factor:g}" if factor is not None else name
                # a fifth run and later: the line styles again, with markers
                marker = [None, "o", "s", "^", "v"][(r // len(styles)) % 5]
                style = dict(lw=1, color=colour, ls=styles[r % len(styles)], marker=marker, markersize=3,
                             markevery=max(1, len(t) // 12))
                if a.rate:
                    y = [(x[n] - x[n - 1]) / (t[n] - t[n - 1]) for n in range(1, len(t))]
                    ax.plot(t[1:], y, label=f"{label}: d({shown})/dt", **style)
                else:
                    ax.plot(t, x, label=f"{label}: {shown}", **style)
        for index, value, text in lines:
            if index == panel:
                ax.axhline(value, color="0.4", lw=0.8, ls=(0, (6, 3)), label=text)
        # a long pattern wraps (the figure's height per panel holds about three lines of 30 characters)
        ax.set_ylabel(textwrap.fill(("rate of " if a.rate else "") + pattern.replace(",", ", "), 30), fontsize=8)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    axes[-1][0].set_xlabel("t")
    fig.tight_layout()
    fig.savefig(a.out, dpi=130)
    plt.close(fig)
    drawn = sum(len(c) for _, _, panels in runs for c in panels)
    span = ""
    if a.tmin > -float("inf") or a.tmax < float("inf"):  # the first run's steps drawn
        t = runs[0][1]["t"][1:] if a.rate else runs[0][1]["t"]
        span = f", {len(t)} step(s) of t in [{t[0]:g}, {t[-1]:g}] in {runs[0][0]}"
    references = f", {len(lines)} reference line(s)" if lines else ""
    print(f"wrote {a.out}: {drawn} curve(s) in {len(a.columns)} panel(s){span}{references}")


if __name__ == "__main__":
    reporting(main)
