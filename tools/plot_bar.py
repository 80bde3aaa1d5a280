#!/usr/bin/python3
"""Plots and numbers of paper Example 6.2 (the bar) from signorini's CSV and Exodus output.

  tools/plot_bar.py --adaptive out/bar --uniform out/bar-uniform [--more-adaptive BASE:LABEL]
                    [--steps auto | 16,20,38,...] --out out/plots-bar

Writes (PNG): bar_eta_vs_unknowns.png (paper Fig. 6.5), bar_meshes.png (Fig. 6.4: meshes of the final
adaptive cycle at nine steps, displacement scaled by 5, the foundation drawn: the deck's Problem/Obstacle
below Gamma_C; --steps auto
chooses them from the run's contact intervals as in the paper: (a)-(c) before, during and after the
first contact, (d)-(f) the same for another contact, (g)-(i) three steps inside one contact, growing,
largest and shrinking), bar_contact_zone.png (the length of the active contact zone against the
length of Gamma_C in cells of the run's finest level and the mean level of the cells along Gamma_C,
per written step). Prints the contact intervals of the adaptive run, the chosen steps and the
correlations of refined zone and contact zone, over the run and per contact. Uses Debian's python3
with numpy, matplotlib and netCDF4.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_results import (adaptive_setting, deck_file, deck_parameter, exodus_frames, multiplier_frame,  # noqa: E402
                          names, nearest_frame, output_folder, parse_steps, plot_eta, read_csv, read_cycles,
                          require_exodus, run_deck, time_step)
from tool_errors import ArgumentParser, InputError, exodus, fail  # noqa: E402


def contact_intervals(steps_csv):
    """[(t_first, t_last)] of the runs of consecutive steps with active contact segments."""
    s = read_csv(steps_csv)
    intervals, start, last = [], None, None
    for t, active in zip(s["t"], s["active"]):
        if active > 0:
            start = t if start is None else start
            last = t
        elif start is not None:
            intervals.append((start, last))
            start = None
    if start is not None:
        intervals.append((start, last))
    return intervals


def contact_step_intervals(s, k):
    """[(first step, last step, step with the most active segments)] of the runs of consecutive steps
    with active contact segments in a step table."""
    steps = np.rint(s["t"] / k).astype(int)
    out, run = [], []
    for n, active in zip(steps, s["active"]):
        if active > 0:
            run.append((n, active))
        elif run:
            out.append(run)
            run = []
    if run:
        out.append(run)
    return [(r[0][0], r[-1][0], max(r, key=lambda na: na[1])[0]) for r in out]


def choose_mesh_steps(s, k, written):
    """The nine steps of Fig. 6.4 from the contact intervals, among the written steps: (a)-(c) the
    last written step at least 3 steps before the first contact, its written step with the most
    active segments, the first written step at least 3 steps after it; (d)-(f) the same for another
    contact; (g)-(i) the contact (other than the first) with the most written steps in contact: its
    first written step in contact, the one with the most active segments and its last. Returns
    [(step, caption)]; fewer panels when the run has fewer contacts."""
    active = dict(zip(np.rint(s["t"] / k).astype(int), s["active"]))
    written = sorted(set(written))
    intervals = contact_step_intervals(s, k)
    inside = [[n for n in written if a <= n <= b and active.get(n, 0) > 0] for a, b, _ in intervals]
    peak = [max(w, key=lambda n: active[n]) if w else None for w in inside]

    def when(i):
        a, b, _ = intervals[i]
        return f"contact {i + 1} ({a * k * 1e3:.2f}-{b * k * 1e3:.2f} ms)"

    def around(i):
        a, b, _ = intervals[i]
        before = [n for n in written if n <= a - 3] or [written[0]]
        after = [n for n in written if n >= b + 3] or [written[-1]]
        chosen = [(before[-1], f"before {when(i)}")]
        if peak[i] is not None:
            chosen.append((peak[i], f"in {when(i)}, most active segments"))
        return chosen + [(after[0], f"after {when(i)}")]

    panels = []
    if not intervals:
        return panels
    usable = [i for i in range(1, len(intervals)) if len(inside[i]) >= 3]
    during = max(usable, key=lambda i: (len(inside[i]), -i)) if usable else None
    panels += around(0)
    other = [i for i in range(1, len(intervals)) if i != during]
    if other:
        panels += around(other[0])
    if during is not None:
        w = inside[during]
        panels += [(w[0], f"in {when(during)}, first written step"),
                   (peak[during], f"in {when(during)}, most active segments"),
                   (w[-1], f"in {when(during)}, last written step")]
    return panels


def require_bar_variables(base):
    """InputError unless the Exodus output of base has the variables the pictures read: the nodal
    u_x and u_y of an elasticity run (the bar) and the cells' level."""
    with exodus(base + ".e") as d:
        nodal = names(d.variables["name_nod_var"]) if "name_nod_var" in d.variables else []
        cell = names(d.variables["name_elem_var"]) if "name_elem_var" in d.variables else []
    missing = [n for n in ("u_x", "u_y") if n not in nodal]
    if missing:
        raise InputError(f"{base}.e: no nodal variable {', '.join(missing)} (nodal variables: "
                         f"{', '.join(nodal) or 'none'}): not an elasticity run such as the bar of Example 6.2")
    if "level" not in cell:
        raise InputError(f"{base}.e: no element variable level")


def frame_data(f, i):
    with exodus(f) as d:
        x, y = d.variables["coordx"][:], d.variables["coordy"][:]
        conn = d.variables["connect1"][:] - 1
        nodal = names(d.variables["name_nod_var"])
        ux = d.variables[f"vals_nod_var{nodal.index('u_x') + 1}"][i, :]
        uy = d.variables[f"vals_nod_var{nodal.index('u_y') + 1}"][i, :]
        cell = names(d.variables["name_elem_var"])
        level = d.variables[f"vals_elem_var{cell.index('level') + 1}eb1"][i, :]
    return x, y, conn, ux, uy, level


def foundation(base, f):
    """(x0, x1, y, g) of the foundation drawn under the bar: Gamma_C (the side set of the Exodus file
    f, a horizontal edge y from x0 to x1) and the deck's constant Problem/Obstacle g (u_y >= g, Contact
    Direction +y); None, said so, if the deck gives another obstacle (a function of x, another direction)."""
    deck = run_deck(base)
    obstacle = deck_parameter(deck, "Problem/Obstacle")
    direction = (deck_parameter(deck, "Problem/Contact Direction") or "").strip()
    try:
        g = float(obstacle)
    except (TypeError, ValueError):
        g = None
    a, b, _, axis, position = multiplier_frame(f, 0)
    if g is None or direction != "+y" or axis != 0:
        print(f"note: {base}: the foundation is not drawn (Problem/Obstacle '{obstacle}', Contact Direction "
              f"'{direction}': only a constant obstacle under a horizontal Gamma_C, direction +y, is drawn)",
              file=sys.stderr)
        return None
    return float(a.min()), float(b.max()), position, g


def plot_meshes(base, panels, k, out, scale=5.0):
    """panels: [(step, caption)]."""
    frames = list(exodus_frames(base))
    ground = foundation(base, frames[0][1])
    s = read_csv(base + ".steps.csv")
    active = dict(zip(np.rint(s["t"] / k).astype(int), s["active"]))
    rows = (len(panels) + 2) // 3
    fig, axes = plt.subplots(rows, 3, figsize=(15, 2.3 * rows + 0.6), squeeze=False)
    for j, (ax, (step, caption)) in enumerate(zip(axes.flat, panels)):
        time, f, i, step = nearest_frame(frames, step, k)
        x, y, conn, ux, uy, _ = frame_data(f, i)
        X, Y = x + scale * ux, y + scale * uy
        # Each edge once (neighbours share theirs), one collection per panel: the file stays small.
        edges = np.sort(np.stack([conn, np.roll(conn, -1, axis=1)], axis=2).reshape(-1, 2), axis=1)
        edges = np.unique(edges, axis=0)
        ax.add_collection(LineCollection(np.stack([np.c_[X[edges[:, 0]], Y[edges[:, 0]]],
                                                   np.c_[X[edges[:, 1]], Y[edges[:, 1]]]], axis=1),
                                         colors="k", linewidths=0.15, antialiased=False))
        if ground:
            x0, x1, y0, g = ground
            ax.plot([x0, x1], [y0 + scale * g] * 2, "r-", lw=1.5)  # the gap scales with u
        ax.set_aspect("equal")
        ax.set_title(f"({chr(ord('a') + j)}) n = {step}, t = {time * 1e3:.2f} ms{': ' + caption if caption else ''}\n"
                     f"{int(active.get(step, 0))} active segments, {len(conn)} cells", fontsize=8)
        ax.set_xticks([])
        ax.set_yticks([])
    for ax in list(axes.flat)[len(panels):]:
        ax.axis("off")
    drawn = f"; red: the foundation u_y = {ground[3]:g} m (scaled too)" if ground else ""
    fig.suptitle(f"paper Fig. 6.4: meshes of the final adaptive cycle{adaptive_setting(base)} of {deck_file(base)}, "
                 f"displacement scaled by {scale:g}{drawn}", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "bar_meshes.png"), dpi=150)
    plt.close(fig)


def gamma_c_frame(f, i):
    """Per contact edge of a frame: its length, the level of its cell and whether its multiplier
    is non-zero (active)."""
    with exodus(f) as d:
        x, y = d.variables["coordx"][:], d.variables["coordy"][:]
        conn = d.variables["connect1"][:] - 1
        cell = names(d.variables["name_elem_var"])
        level = d.variables[f"vals_elem_var{cell.index('level') + 1}eb1"][i, :]
        elems = d.variables["elem_ss1"][:] - 1
        sides = d.variables["side_ss1"][:] - 1
        lam = d.variables[f"vals_sset_var{names(d.variables['name_sset_var']).index('lambda') + 1}ss1"][i, :]
    a = conn[elems, sides]
    b = conn[elems, (sides + 1) % 4]
    length = np.hypot(x[a] - x[b], y[a] - y[b])
    return length, np.asarray(level[elems]), np.asarray(lam) != 0, int(level.max())


def correlation(a, b):
    a, b = np.asarray(a, float), np.asarray(b, float)
    return float(np.corrcoef(a, b)[0, 1]) if len(a) > 2 and a.std() > 0 and b.std() > 0 else float("nan")


def contact_zone_vs_refinement(base, k, out):
    """The active contact zone against the refinement along Gamma_C, per written step: the length
    of Gamma_C in cells of the run's finest level and the length-weighted mean level of the cells
    on Gamma_C. Returns {measure: (overall correlation, [(contact, correlation)])}."""
    s = read_csv(base + ".steps.csv")
    times, active, finest, mean_level, frame_max = [], [], [], [], []
    rows = [gamma_c_frame(f, i) + (time,) for time, f, i in exodus_frames(base)]
    top = max(r[3] for r in rows)  # the finest level of the run
    for length, level, on, most, time in rows:
        times.append(time)
        active.append(1e3 * length[on].sum())
        finest.append(1e3 * length[level >= top].sum())
        mean_level.append(float((length * level).sum() / length.sum()))
        frame_max.append(most)
    times, active = np.array(times), np.array(active)
    steps = np.rint(times / k).astype(int)
    intervals = contact_step_intervals(s, k)
    # per contact: its written steps and up to 6 steps on either side, at most to the middle of the gaps
    windows = []
    for j, (a, b, _) in enumerate(intervals):
        lo = a - 6 if j == 0 else max(a - 6, (intervals[j - 1][1] + a) / 2)
        hi = b + 6 if j == len(intervals) - 1 else min(b + 6, (b + intervals[j + 1][0]) / 2)
        windows.append((steps >= lo) & (steps <= hi))
    measures = {"finest": (np.array(finest), f"length of $\\Gamma_C$ in cells of level {top} (the run's finest)"),
                "mean level": (np.array(mean_level), "mean level of the cells on $\\Gamma_C$ (length-weighted)")}
    result = {name: (correlation(active, v), [correlation(active[w], v[w]) for w in windows])
              for name, (v, _) in measures.items()}

    fig, (ax, bx) = plt.subplots(2, 1, figsize=(11, 6.4), sharex=True)
    ms = times * 1e3
    for axis in (ax, bx):
        for a, b, _ in intervals:
            axis.axvspan((a - 0.5) * k * 1e3, (b + 0.5) * k * 1e3, color="0.85", lw=0)
        axis.grid(True, alpha=0.3)
    ax.plot(ms, active, "r-", lw=1, label="active contact zone ($\\lambda_H \\neq 0$)")
    ax.plot(ms, finest, "b-", lw=1, label=measures["finest"][1])
    ax.set_ylabel("length on $\\Gamma_C$ [mm]")
    bx.plot(ms, mean_level, "k-", lw=1, label=measures["mean level"][1])
    bx.set_ylabel("level")
    bx.set_xlabel("t [ms]")
    for axis, name in [(ax, "finest"), (bx, "mean level")]:
        for j, ((a, b, _), r) in enumerate(zip(intervals, result[name][1])):  # staggered: contacts can be close
            axis.annotate(f"{r:.2f}", ((a + b) / 2 * k * 1e3, 1.0), xycoords=("data", "axes fraction"),
                          xytext=(0, 2 + 9 * (j % 2)), textcoords="offset points", ha="center", va="bottom", fontsize=7)
        axis.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, frameon=False)
    gamma = f"finest level {top} in every written step" if min(frame_max) == top else \
        f"finest level of the written steps {min(frame_max)}-{top}"
    fig.suptitle(f"{os.path.basename(base)} (final adaptive cycle, {gamma}); grey: contact intervals;\n"
                 "numbers above a contact: correlation with the active length over its steps +-6 (at most to the "
                 f"middle of the gaps); over the run: r = {result['finest'][0]:.2f} (top), "
                 f"{result['mean level'][0]:.2f} (bottom)", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "bar_contact_zone.png"), dpi=150)
    plt.close(fig)
    return result


def main():
    ap = ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--adaptive", required=True, help="output base of the adaptive run (folder/basename)")
    ap.add_argument("--uniform", help="output base of the uniform comparison run")
    ap.add_argument("--more-adaptive", action="append", default=[], metavar="BASE:LABEL",
                    help="a further adaptive run for the estimate plot (repeatable)")
    ap.add_argument("--steps", default="auto",
                    help="steps for the mesh pictures, or auto: nine steps chosen from the contact intervals")
    ap.add_argument("--time-step", type=float, help="the run's time step (default: from its step table)")
    ap.add_argument("--adaptive-label", help="legend of --adaptive (default: from the run's deck, e.g. 'adaptive, "
                    "fixed fraction 50%%')")
    ap.add_argument("--out", default="out/plots-bar", help="folder for the plots (created; default %(default)s)")
    a = ap.parse_args()
    try:  # every input first: a missing file or column stops before any plot is written
        for base in [a.adaptive, a.uniform] + [spec.split(":", 1)[0] for spec in a.more_adaptive]:
            if base:
                read_cycles(base)
        steps = read_csv(a.adaptive + ".steps.csv", ["t", "active"])
        require_exodus(a.adaptive)
        require_bar_variables(a.adaptive)
        k = a.time_step or time_step(steps)
        mesh_steps = None if a.steps == "auto" else parse_steps(a.steps)
    except InputError as e:
        fail(e)
    output_folder(a.out)
    plot_eta(a.adaptive, a.uniform, a.more_adaptive, a.out, a.adaptive_label, eta_unit="m", h_unit="m",
             title="paper Example 6.2 (bar), cf. Fig. 6.5")
    os.replace(os.path.join(a.out, "eta_vs_unknowns.png"), os.path.join(a.out, "bar_eta_vs_unknowns.png"))
    intervals = contact_intervals(a.adaptive + ".steps.csv")
    print(f"{a.adaptive}: {len(intervals)} contact intervals [ms]: "
          + ", ".join(f"{t0 * 1e3:.2f}-{t1 * 1e3:.2f}" for t0, t1 in intervals))
    if mesh_steps is None:
        written = [int(round(t / k)) for t, _, _ in exodus_frames(a.adaptive)]
        panels = choose_mesh_steps(steps, k, written)
        if not panels:
            print("note: no contact in the run: the meshes of steps 0 and the last written step", file=sys.stderr)
            panels = [(written[0], "no contact in the run"), (written[-1], "no contact in the run")]
    else:
        panels = [(n, "") for n in mesh_steps]
    print("meshes of steps " + "; ".join(f"({chr(ord('a') + j)}) {n}: {c}" for j, (n, c) in enumerate(panels)))
    plot_meshes(a.adaptive, panels, k, a.out)
    result = contact_zone_vs_refinement(a.adaptive, k, a.out)
    for name, (overall, per) in result.items():
        what = {"finest": "length of Gamma_C in cells of the run's finest level",
                "mean level": "mean level of the cells on Gamma_C"}[name]
        print(f"correlation of the active contact length with the {what} (per written step): "
              f"{overall:.2f} over the run; per contact " + ", ".join(f"{r:.2f}" for r in per))


if __name__ == "__main__":
    main()
