#!/usr/bin/python3
"""Plots of an adaptive run against its uniform comparison, from signorini's CSV and Exodus output.

  tools/plot_results.py --adaptive out/membrane --uniform out/membrane-uniform [--steps 20,60,200,400]
                        [--more-adaptive out/membrane-fraction10:"fixed fraction 10%"]
                        [--h-equals-h out/membrane-Hh] --out out/plots

Writes (PNG): eta_vs_unknowns.png (paper Fig. 6.3), estimator_contributions.png (Fig. 4.1),
meshes.png (Fig. 6.2, meshes of the final cycle at the chosen steps), multiplier.png (Fig. 3.1, the
contact multiplier along Gamma_C for H = 2h and, if given, H = h), energy_and_probe.png (energy per
step across mesh changes and the probe value, adaptive against the uniform cycles). Uses Debian's python3 with
numpy, matplotlib and netCDF4.
"""
import argparse
import glob
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import netCDF4  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exodus_text import names as exodus_names  # noqa: E402
from tool_errors import ArgumentParser, InputError, fail, read_table  # noqa: E402


read_csv = read_table  # the name plot_bar.py imports


def require_exodus(base):
    """InputError unless the run at base wrote Exodus output."""
    if not os.path.isfile(base + ".e"):
        raise InputError(f"{base}.e: no such file (the run wrote no Exodus output? Output/Write Exodus)")


def parse_steps(text):
    """The step numbers of a --steps argument ("20,60,100"); InputError unless it is such a list."""
    try:
        return [int(s) for s in text.split(",")]
    except ValueError:
        raise InputError(f"--steps {text}: not a comma-separated list of step numbers") from None


def time_step(steps):
    """The time step of a step table (its first two rows)."""
    return float(steps["t"][1] - steps["t"][0]) if steps.size > 1 else 1.0


def nearest_frame(frames, step, k):
    """(time, file, index, step) of the output frame nearest step n = step; says so when that is
    another step (beyond the run, or between Exodus outputs)."""
    time, f, i = min(frames, key=lambda fr: abs(fr[0] - step * k))
    drawn = int(round(time / k))
    if drawn != step:
        print(f"note: step {step} is not in the output of {f}; drawing step {drawn} (t = {time:.4g})", file=sys.stderr)
    return time, f, i, drawn


def cycle_number(path):
    """The cycle l of '<base>.cycle<l>.<suffix>'."""
    return int(re.search(r"\.cycle(\d+)\.", path).group(1))


def exodus_files(base):
    files = [base + ".e"] + sorted(glob.glob(base + ".e-s.*"), key=lambda f: int(re.findall(r"(\d+)$", f)[0]))
    return [f for f in files if os.path.exists(f)]


def exodus_frames(base):
    """Yields (time, file, index) for every output time of a series."""
    for f in exodus_files(base):
        with netCDF4.Dataset(f) as d:
            for i, t in enumerate(d.variables["time_whole"][:]):
                yield float(t), f, i


def names(var):
    return exodus_names(var)


def plot_eta(adaptive, uniform, more, out):
    plt.figure(figsize=(5, 4))
    runs = [(adaptive, "adaptive", "o-"), (uniform, "uniform", "s--")]
    runs += [(spec.split(":", 1)[0], spec.split(":", 1)[-1], "^-") for spec in more]
    for base, label, style in runs:
        if base:
            c = np.atleast_1d(read_csv(base + ".cycles.csv", ["total_dofs", "eta"]))
            plt.loglog(c["total_dofs"], c["eta"], style, label=label)
    plt.xlabel("total unknowns (sum over time steps)")
    plt.ylabel(r"estimated error $\eta = \max_n \eta^n$")
    plt.grid(True, which="both", alpha=0.3)
    plt.legend()
    plt.tight_layout()
    plt.savefig(os.path.join(out, "eta_vs_unknowns.png"), dpi=150)
    plt.close()


def plot_contributions(adaptive, out):
    s = read_csv(adaptive + ".steps.csv")[1:]
    plt.figure(figsize=(6, 4))
    for col, label in [("eta_star", r"$\eta_\star$"), ("s0", "$s_0$"), ("s1", "$s_1$")]:
        # gaps where it is 0 (markers keep single steps visible)
        plt.semilogy(s["t"], np.where(s[col] > 0, s[col], np.nan), ".-", ms=2, lw=1, label=label)
    plt.xlabel("t")
    plt.ylabel("contribution")
    plt.legend()
    plt.grid(True, which="both", alpha=0.3)
    plt.tight_layout()
    plt.savefig(os.path.join(out, "estimator_contributions.png"), dpi=150)
    plt.close()


def plot_energy_and_probe(adaptive, uniform, out):
    """Energy per step across mesh changes, and the probe value, adaptive against uniform cycles."""
    fig, axes = plt.subplots(1, 3, figsize=(16, 4))
    runs = []
    if uniform:
        runs += [(f, f"uniform cycle {cycle_number(f)}", "-")
                 for f in sorted(glob.glob(uniform + ".cycle*.steps.csv"), key=cycle_number)]
        runs.append((uniform + ".steps.csv", "uniform (last cycle)", "-"))
    runs.append((adaptive + ".steps.csv", "adaptive (last cycle)", "k--"))
    for path, label, style in runs:
        if not os.path.exists(path):
            continue
        s = read_csv(path)
        axes[0].plot(s["t"], s["energy"], style, label=label, lw=1)
        probes = [n for n in s.dtype.names if n.startswith("probe")]
        if probes:
            axes[1].plot(s["t"], s[probes[0]], style, label=label, lw=1)
    # The transfer's own effect: energy of (I_h u^{n-1}, I_h v^{n-1}) on step n's mesh minus that of
    # step n-1 on its own mesh (columns written with Adaptivity/Report Transfer Energy).
    s = read_csv(adaptive + ".steps.csv") if os.path.exists(adaptive + ".steps.csv") else None
    if s is not None and "energy_transferred" in s.dtype.names:
        e0 = s["energy"][0]
        for col, before, label, style in [("energy_transferred", "energy", "kinetic + strain", "k-"),
                                          ("kinetic_energy_transferred", "kinetic_energy", "kinetic", "r-")]:
            axes[2].plot(s["t"][1:], (s[col][1:] - s[before][:-1]) / e0, style, label=label, lw=0.8)
    axes[2].set_xlabel("t")
    axes[2].set_ylabel("change / E(0)")
    axes[2].set_title("energy change by the transfer to step n's mesh\n(adaptive, last cycle)")
    axes[0].set_xlabel("t")
    axes[0].set_ylabel("kinetic + strain energy")
    axes[0].set_title("energy per step (mesh changes every step in adaptive runs)")
    axes[1].set_xlabel("t")
    axes[1].set_ylabel("u at the probe")
    axes[1].set_title("probe value")
    for ax in axes:
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "energy_and_probe.png"), dpi=150)
    plt.close(fig)


def plot_meshes(adaptive, steps, k, out):
    frames = list(exodus_frames(adaptive))
    n = len(steps)
    cols = min(n, 3)
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4 * cols, 4 * rows), squeeze=False)
    for ax, step in zip(axes.flat, steps):
        time, f, i, step = nearest_frame(frames, step, k)
        with netCDF4.Dataset(f) as d:
            x, y = d.variables["coordx"][:], d.variables["coordy"][:]
            conn = d.variables["connect1"][:] - 1
            for q in conn:
                xs, ys = x[np.append(q, q[0])], y[np.append(q, q[0])]
                ax.plot(xs, ys, "k-", lw=0.2)
        ax.set_aspect("equal")
        ax.set_title(f"n = {step} (t = {time:.4g}), {len(conn)} cells")
        ax.set_xticks([])
        ax.set_yticks([])
    for ax in list(axes.flat)[n:]:
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "meshes.png"), dpi=150)
    plt.close(fig)


def contact_multiplier(base, t):
    """Multiplier per contact edge at the output time nearest t: (time, edge end points (n, 2, 2),
    values)."""
    frames = list(exodus_frames(base))
    time, f, i = min(frames, key=lambda fr: abs(fr[0] - t))
    with netCDF4.Dataset(f) as d:
        x, y = d.variables["coordx"][:], d.variables["coordy"][:]
        conn = d.variables["connect1"][:] - 1
        elems = d.variables["elem_ss1"][:] - 1
        sides = d.variables["side_ss1"][:] - 1
        var = names(d.variables["name_sset_var"]).index("lambda") + 1
        lam = d.variables[f"vals_sset_var{var}ss1"][i, :]
        ends = []
        for e, s in zip(elems, sides):
            a, b = conn[e][s], conn[e][(s + 1) % 4]
            ends.append(((x[a], y[a]), (x[b], y[b])))
    return time, np.array(ends), np.array(lam)


def plot_multiplier(bases, t, out):
    plt.figure(figsize=(6, 4))
    for base, label in bases:
        if not base or not exodus_files(base):
            continue
        time, ends, lam = contact_multiplier(base, t)
        axis = 1 if np.ptp(ends[:, :, 1]) > np.ptp(ends[:, :, 0]) else 0  # along Gamma_C
        a, b = np.sort(ends[:, :, axis], axis=1).T
        order = np.argsort(a)
        # each edge's constant value from its start to its end, so the jumps sit at the edges' ends
        plt.plot(np.column_stack([a[order], b[order]]).ravel(), np.repeat(lam[order], 2),
                 label=f"{label} (t = {time:.4g})")
    plt.xlabel("position along the contact boundary")
    plt.ylabel(r"contact multiplier $\lambda$")
    plt.legend()
    plt.tight_layout()
    plt.savefig(os.path.join(out, "multiplier.png"), dpi=150)
    plt.close()


def main():
    ap = ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--adaptive", required=True, help="output base of the adaptive run (folder/basename)")
    ap.add_argument("--uniform", help="output base of the uniform comparison run")
    ap.add_argument("--more-adaptive", action="append", default=[], metavar="BASE:LABEL",
                    help="a further adaptive run for the estimate plot (repeatable)")
    ap.add_argument("--two-h", help="output base of a run with H = 2h for the multiplier plot (default: --adaptive)")
    ap.add_argument("--h-equals-h", help="output base of the same run with Contact/Multiplier Segments = H = h")
    ap.add_argument("--steps", default="20,60,100,200,300,400", help="steps whose meshes are drawn")
    ap.add_argument("--time-step", type=float, help="the run's time step (default: from its step table)")
    ap.add_argument("--multiplier-time", type=float, default=0.5)
    ap.add_argument("--eta-only", action="store_true",
                    help="draw only eta_vs_unknowns.png (runs without Exodus output, e.g. the finer study)")
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    try:  # every input first: a missing file or column stops before any plot is written
        for base in [a.adaptive, a.uniform] + [spec.split(":", 1)[0] for spec in a.more_adaptive]:
            if base:
                read_csv(base + ".cycles.csv", ["total_dofs", "eta"])
        if not a.eta_only:
            steps = read_csv(a.adaptive + ".steps.csv", ["t", "energy", "eta_star", "s0", "s1"])
            if a.uniform:  # every cycle's step table (the energy plot)
                for f in [a.uniform + ".steps.csv"] + glob.glob(a.uniform + ".cycle*.steps.csv"):
                    read_csv(f, ["t", "energy"])
            for base in [a.adaptive, a.two_h, a.h_equals_h]:
                if base:
                    require_exodus(base)
            k = a.time_step or time_step(steps)
            mesh_steps = parse_steps(a.steps)
    except InputError as e:
        fail(e)
    os.makedirs(a.out, exist_ok=True)
    plot_eta(a.adaptive, a.uniform, a.more_adaptive, a.out)
    if a.eta_only:
        print("wrote", os.path.join(a.out, "eta_vs_unknowns.png"))
        return
    plot_contributions(a.adaptive, a.out)
    plot_energy_and_probe(a.adaptive, a.uniform, a.out)
    plot_meshes(a.adaptive, mesh_steps, k, a.out)
    plot_multiplier([(a.two_h or a.adaptive, "H = 2h"), (a.h_equals_h, "H = h")], a.multiplier_time, a.out)
    print("wrote", ", ".join(sorted(os.listdir(a.out))))


if __name__ == "__main__":
    main()
