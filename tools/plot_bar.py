#!/usr/bin/python3
"""Plots and numbers of paper Example 6.2 (the bar) from signorini's CSV and Exodus output.

  tools/plot_bar.py --adaptive out/bar --uniform out/bar-uniform [--more-adaptive BASE:LABEL]
                    [--steps 20,30,60,110,160,250] --out out/plots-bar

Writes (PNG): bar_eta_vs_unknowns.png (paper Fig. 6.5), bar_meshes.png (Fig. 6.4: meshes of the final
adaptive cycle at the chosen steps, displacement scaled by 5, the foundation y = -0.005 drawn),
bar_contact_zone.png (active contact segments against the cells of the finest level next to the
foundation, per output step). Prints the contact intervals of the adaptive run and the correlation
of refined zone and contact zone. Uses Debian's python3 with numpy, matplotlib and netCDF4.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import netCDF4  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_results import (exodus_frames, names, nearest_frame, parse_steps, plot_eta, read_csv,  # noqa: E402
                          require_exodus, time_step)
from tool_errors import ArgumentParser, InputError, exodus, fail  # noqa: E402

FOUNDATION_X, FOUNDATION_Y = 0.15, -0.005


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
    with netCDF4.Dataset(f) as d:
        x, y = d.variables["coordx"][:], d.variables["coordy"][:]
        conn = d.variables["connect1"][:] - 1
        nodal = names(d.variables["name_nod_var"])
        ux = d.variables[f"vals_nod_var{nodal.index('u_x') + 1}"][i, :]
        uy = d.variables[f"vals_nod_var{nodal.index('u_y') + 1}"][i, :]
        cell = names(d.variables["name_elem_var"])
        level = d.variables[f"vals_elem_var{cell.index('level') + 1}eb1"][i, :]
    return x, y, conn, ux, uy, level


def plot_meshes(base, steps, k, out, scale=5.0):
    frames = list(exodus_frames(base))
    fig, axes = plt.subplots((len(steps) + 2) // 3, 3, figsize=(15, 2.0 * ((len(steps) + 2) // 3)), squeeze=False)
    for ax, step in zip(axes.flat, steps):
        time, f, i, step = nearest_frame(frames, step, k)
        x, y, conn, ux, uy, _ = frame_data(f, i)
        X, Y = x + scale * ux, y + scale * uy
        for q in conn:
            ax.plot(X[np.append(q, q[0])], Y[np.append(q, q[0])], "k-", lw=0.15)
        ax.plot([FOUNDATION_X, 0.2], [scale * FOUNDATION_Y] * 2, "r-", lw=1.5)  # the gap scales with u
        ax.set_aspect("equal")
        ax.set_title(f"n = {step} (t = {time * 1e3:.3f} ms), {len(conn)} cells", fontsize=9)
        ax.set_xticks([])
        ax.set_yticks([])
    for ax in list(axes.flat)[len(steps):]:
        ax.axis("off")
    fig.suptitle(f"final adaptive cycle, displacement scaled by {scale:g}; red: the foundation u_y = -0.005 m (scaled too)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "bar_meshes.png"), dpi=150)
    plt.close(fig)


def contact_zone_vs_refinement(base, out):
    """Active segments (steps CSV) and finest-level cells within 0.01 m of the foundation (Exodus)."""
    s = read_csv(base + ".steps.csv")
    frames = list(exodus_frames(base))
    times, fine = [], []
    for time, f, i in frames:
        x, y, conn, _, _, level = frame_data(f, i)
        cx, cy = x[conn].mean(axis=1), y[conn].mean(axis=1)
        near = (cx >= FOUNDATION_X - 0.01) & (cy <= 0.01)
        times.append(time)
        fine.append(int(np.sum(near & (level >= level.max()))))
    active = np.interp(times, s["t"], s["active"])
    fig, ax = plt.subplots(figsize=(8, 3.5))
    ax.plot(np.array(times) * 1e3, fine, "b-", label="finest-level cells within 0.01 m of the foundation")
    ax.set_xlabel("t [ms]")
    ax.set_ylabel("cells", color="b")
    ax2 = ax.twinx()
    ax2.plot(s["t"] * 1e3, s["active"], "r-", lw=0.8, label="active contact segments")
    ax2.set_ylabel("active segments", color="r")
    fig.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "bar_contact_zone.png"), dpi=150)
    plt.close(fig)
    return float(np.corrcoef(active, fine)[0, 1]) if len(fine) > 2 else float("nan")


def main():
    ap = ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--adaptive", required=True, help="output base of the adaptive run (folder/basename)")
    ap.add_argument("--uniform", help="output base of the uniform comparison run")
    ap.add_argument("--more-adaptive", action="append", default=[], metavar="BASE:LABEL",
                    help="a further adaptive run for the estimate plot (repeatable)")
    ap.add_argument("--steps", default="20,30,60,110,160,250", help="steps for the mesh pictures")
    ap.add_argument("--time-step", type=float, help="the run's time step (default: from its step table)")
    ap.add_argument("--out", default="out/plots-bar")
    a = ap.parse_args()
    try:  # every input first: a missing file or column stops before any plot is written
        for base in [a.adaptive, a.uniform] + [spec.split(":", 1)[0] for spec in a.more_adaptive]:
            if base:
                read_csv(base + ".cycles.csv", ["total_dofs", "eta"])
        steps = read_csv(a.adaptive + ".steps.csv", ["t", "active"])
        require_exodus(a.adaptive)
        require_bar_variables(a.adaptive)
        k = a.time_step or time_step(steps)
        mesh_steps = parse_steps(a.steps)
    except InputError as e:
        fail(e)
    os.makedirs(a.out, exist_ok=True)
    plot_eta(a.adaptive, a.uniform, a.more_adaptive, a.out)
    os.replace(os.path.join(a.out, "eta_vs_unknowns.png"), os.path.join(a.out, "bar_eta_vs_unknowns.png"))
    plot_meshes(a.adaptive, mesh_steps, k, a.out)
    intervals = contact_intervals(a.adaptive + ".steps.csv")
    print(f"{a.adaptive}: {len(intervals)} contact intervals [ms]: "
          + ", ".join(f"{t0 * 1e3:.2f}-{t1 * 1e3:.2f}" for t0, t1 in intervals))
    r = contact_zone_vs_refinement(a.adaptive, a.out)
    print(f"correlation of active segments and finest cells next to the foundation (per output step): {r:.2f}")


if __name__ == "__main__":
    main()
