#!/usr/bin/python3
"""Plots of an adaptive run against its uniform comparison, from signorini's CSV and Exodus output.

  tools/plot_results.py --adaptive out/membrane --uniform out/membrane-uniform [--steps 20,60,200,400]
                        [--more-adaptive out/membrane-fraction10:"fixed fraction 10%"]
                        [--two-h out/membrane-level2] [--h-equals-h out/membrane-Hh]
                        [--two-h-stabilised BASE] [--h-equals-h-stabilised BASE] --out out/plots

Writes (PNG): eta_vs_unknowns.png (paper Fig. 6.3), estimator_contributions.png (Fig. 4.1),
meshes.png (Fig. 6.2, meshes of the final cycle at the chosen steps), multiplier.png (Fig. 3.1, the
contact multiplier along Gamma_C for H = 2h and, if given, H = h: one step, and the mean and range
over the steps of a window around it, since the paper's scheme chatters in time; with the
*-stabilised runs, a panel of the same with Time Integration/Contact Stabilisation), energy_and_probe.png
(energy per step across mesh changes and the probe value, adaptive against the uniform cycles).
Every estimate plot names the Estimator/Scaling of the run (read from the deck in its Exodus file;
without Exodus output the default, physical). Uses Debian's python3 with numpy, matplotlib and netCDF4.
"""
import argparse
import glob
import os
import re
import sys
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from deck_from_exodus import info_lines  # noqa: E402
from exodus_text import names as exodus_names  # noqa: E402
from tool_errors import ArgumentParser, InputError, exodus, fail, read_table, require_complete_exodus  # noqa: E402


read_csv = read_table  # the name plot_bar.py imports


def read_cycles(base):
    """The cycle table of an adaptive run; InputError naming a run on one mesh as such."""
    if not os.path.exists(base + ".cycles.csv") and os.path.isfile(base + ".steps.csv"):
        raise InputError(f"{base}.cycles.csv: no such file: a run on one mesh, not an adaptive run "
                         "(tools/plot_steps.py draws any run's step-table columns)")
    return read_csv(base + ".cycles.csv", ["total_dofs", "eta"])


def require_exodus(base):
    """InputError unless the run at base wrote Exodus output and no file of its series is cut short."""
    if not os.path.isfile(base + ".e"):
        raise InputError(f"{base}.e: no such file (the run wrote no Exodus output? Output/Write Exodus)")
    for f in exodus_files(base):
        require_complete_exodus(f)


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
    files = [base + ".e"] + sorted(glob.glob(glob.escape(base) + ".e-s.*"), key=lambda f: int(re.findall(r"(\d+)$", f)[0]))
    return [f for f in files if os.path.exists(f)]


def exodus_frames(base):
    """Yields (time, file, index) for every output time of a series."""
    for f in exodus_files(base):
        with exodus(f) as d:
            for i, t in enumerate(d.variables["time_whole"][:]):
                yield float(t), f, i


def names(var):
    return exodus_names(var)


def run_deck(base):
    """The deck a run ran with (the info records of its Exodus file) as an XML element, or None
    without Exodus output."""
    if not os.path.isfile(base + ".e"):
        return None
    lines = info_lines(base + ".e")
    start = next((i for i, line in enumerate(lines) if line.startswith("<ParameterList")), None)
    try:
        return None if start is None else ET.fromstring("\n".join(lines[start:]))
    except ET.ParseError:
        return None


def deck_file(base):
    """The deck file a run was started with (from its Exodus info records), or its output base."""
    if os.path.isfile(base + ".e"):
        for line in info_lines(base + ".e"):
            if line.startswith("deck: "):
                return line[len("deck: "):]
    return os.path.basename(base)


def paper_deck(base):
    """Whether a run is of the paper's membrane deck (inputs/membrane.xml): its plots carry the paper's titles."""
    return os.path.splitext(os.path.basename(deck_file(base)))[0] == "membrane"


def deck_parameter(deck, path):
    """The value of the parameter 'Sublist/.../Name' of a deck (run_deck), or None."""
    *lists, name = path.split("/")
    node = deck
    for sub in lists:
        node = None if node is None else node.find(f"ParameterList[@name='{sub}']")
    found = None if node is None else node.find(f"Parameter[@name='{name}']")
    return None if found is None else found.get("value")


def adaptive_setting(base):
    """' (fixed fraction 50%)' from the deck of a run, '' without one."""
    deck = run_deck(base)
    strategy, fraction = (deck_parameter(deck, f"Adaptivity/{key}") for key in ("Strategy", "Refinement Fraction"))
    if strategy == "fixed fraction" and fraction:
        return f" ({strategy} {100 * float(fraction):g}%)"
    return f" ({strategy})" if strategy else ""


def adaptive_label(base):
    """The legend of an adaptive run from its deck: 'adaptive, fixed fraction 50%' (the paper's
    setting, inputs/membrane.xml and inputs/bar.xml), 'adaptive, <strategy>'; 'adaptive' without a
    recorded deck (no Exodus output: give --adaptive-label)."""
    setting = adaptive_setting(base)
    return "adaptive" + (", " + setting[2:-1] if setting else "")


def output_folder(path):
    """Creates the folder --out (and its parents); one line (fail) if it cannot be one."""
    if os.path.exists(path) and not os.path.isdir(path):
        fail(f"--out {path}: not a folder (a file of that name exists)")
    try:
        os.makedirs(path, exist_ok=True)
    except OSError as e:
        fail(f"--out {path}: cannot create the folder: {e.strerror or e}")


def estimator_scaling(base):
    """(scaling, kappa) of a run: Estimator/Scaling and what the physical scaling's kappa is ("" for
    the scalar wave with Stiffness 1; for elasticity lambda_L + 2 mu, for the scalar wave its
    Problem/Stiffness, as matplotlib TeX), from the run's deck; without Exodus output the default
    (physical), said so."""
    deck = run_deck(base)
    if deck is None:
        print(f"note: {base}.e: no deck recorded (no Exodus output?): "
              "assuming the default Estimator/Scaling = physical",
              file=sys.stderr)
        return "physical", ""
    scaling = deck_parameter(deck, "Estimator/Scaling") or "physical"
    elasticity = "elasticity" in (deck_parameter(deck, "Problem/Type") or "")
    stiffness = deck_parameter(deck, "Problem/Stiffness")
    if elasticity:
        kappa = r"\lambda_L + 2\mu"
    elif stiffness is None or float(stiffness) == 1.0:
        kappa = ""
    else:
        kappa = f"{float(stiffness):g}"
    return scaling, kappa


def scaled_terms(scaling, kappa):
    """Labels (matplotlib TeX) of eta_star, s0, s1 as the run's scaling reports them."""
    if scaling != "physical":
        return r"$\eta_\star$", r"$s_0$", r"$s_1$"
    k = r"\beta k^2\kappa" if kappa else r"\beta k^2"
    return rf"$\eta_\star/({k})$", rf"$s_0/\sqrt{{{k}}}$", r"$s_1$"


def scaling_note(base):
    """One line naming the Estimator/Scaling of a run and what it does to the three terms."""
    scaling, kappa = estimator_scaling(base)
    terms = ", ".join(scaled_terms(scaling, kappa))
    if scaling == "physical":
        where = "" if not kappa else rf" ($\kappa = {kappa}$)" if kappa.startswith("\\") else \
            rf" ($\kappa$ = Problem/Stiffness = {kappa})"
        return f"Estimator/Scaling = physical (default): {terms}{where}"
    return f"Estimator/Scaling = {scaling}: {terms} as in the paper's Sec. 4"


def h_text(h, unit=""):
    """A mesh size: 1/N for a unit-free mesh with N whole, else with its unit."""
    n = 1.0 / h
    if not unit and abs(n - round(n)) < 1e-6 * n:
        return f"1/{round(n)}"
    if unit == "m" and h < 0.1:
        return f"{h * 1e3:.3g} mm"
    return f"{h:.3g} {unit}".strip()


def cell_sizes(f, i=0):
    """The edge lengths along x of the cells of frame i of an Exodus file."""
    with exodus(f) as d:
        x = d.variables["coordx"][:]
        conn = d.variables["connect1"][:] - 1
    return np.ptp(x[conn], axis=1)


def uniform_h(base):
    """h of the last cycle of a uniform run (from its Exodus file), or None without one."""
    if not os.path.isfile(base + ".e"):
        return None
    sizes = cell_sizes(base + ".e")
    return float(sizes.min()) if np.allclose(sizes, sizes.min(), rtol=1e-9) else None


def plot_eta(adaptive, uniform, more, out, label=None, eta_unit="", h_unit="", title=""):
    fig = plt.figure(figsize=(6.2, 4.8))
    runs = [(adaptive, label or adaptive_label(adaptive), "o-")]
    if uniform:
        c = np.atleast_1d(read_csv(uniform + ".cycles.csv", ["total_dofs", "eta"]))
        h = uniform_h(uniform)
        label = "uniform refinement"
        if h is not None:  # the cycles halve h
            label += f", h = {h_text(h * 2 ** (c.size - 1), h_unit)} ... {h_text(h, h_unit)}"
        runs.append((uniform, label, "s--"))
    runs += [(spec.split(":", 1)[0], spec.split(":", 1)[-1], "^-") for spec in more]
    for base, label, style in runs:
        if base:
            c = np.atleast_1d(read_csv(base + ".cycles.csv", ["total_dofs", "eta"]))
            plt.loglog(c["total_dofs"], c["eta"], style, label=label)
    plt.xlabel("total unknowns (sum over time steps)")
    unit = f" [{eta_unit}]" if eta_unit else ""
    plt.ylabel(rf"estimated error $\eta = \max_n \eta^n${unit}")
    plt.title((title + "\n" if title else "") + scaling_note(adaptive), fontsize=8)
    plt.grid(True, which="both", alpha=0.3)
    plt.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "eta_vs_unknowns.png"), dpi=150)
    plt.close(fig)


def plot_contributions(adaptive, out, label=None, unit=""):
    s = read_csv(adaptive + ".steps.csv")[1:]
    cycles = np.atleast_1d(read_csv(adaptive + ".cycles.csv", ["cycle"]))
    scaling, kappa = estimator_scaling(adaptive)
    fig = plt.figure(figsize=(6.5, 4.3))
    for col, label in zip(["eta_star", "s0", "s1"], scaled_terms(scaling, kappa)):
        # gaps where it is 0 (markers keep single steps visible)
        plt.semilogy(s["t"], np.where(s[col] > 0, s[col], np.nan), ".-", ms=2, lw=1, label=label)
    plt.xlabel("t")
    plt.ylabel("contribution to $\\eta^n$" + (f" [{unit}]" if unit else ""))
    plt.title(f"{os.path.basename(adaptive)}: {label or adaptive_label(adaptive)}, "
              f"last cycle (cycle {int(cycles['cycle'][-1])})\n{scaling_note(adaptive)}", fontsize=8)
    plt.legend()
    plt.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "estimator_contributions.png"), dpi=150)
    plt.close(fig)


def plot_energy_and_probe(adaptive, uniform, out, label=None):
    """Energy per step across mesh changes, and the probe value, adaptive against uniform cycles."""
    fig, axes = plt.subplots(1, 3, figsize=(16, 4.3))
    runs = []
    if uniform:
        h = uniform_h(uniform)
        cycles = sorted(glob.glob(glob.escape(uniform) + ".cycle*.steps.csv"), key=cycle_number)
        last = max([cycle_number(f) for f in cycles], default=-1) + 1  # the last cycle has no number
        mesh = (lambda c: f", h = {h_text(h * 2 ** (last - c))}") if h is not None else (lambda c: "")
        runs += [(f, f"uniform cycle {cycle_number(f)}{mesh(cycle_number(f))}", "-") for f in cycles]
        runs.append((uniform + ".steps.csv", f"uniform cycle {last}{mesh(last)} (last cycle)", "-"))
    runs.append((adaptive + ".steps.csv", f"{label or adaptive_label(adaptive)}, last cycle", "k--"))
    probe_name = None
    for path, label, style in runs:
        if not os.path.exists(path):
            continue
        s = read_csv(path)
        axes[0].plot(s["t"], s["energy"], style, label=label, lw=1)
        probes = [n for n in s.dtype.names if n.startswith("probe")]
        if probes:
            probe_name = probes[0]
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
    # the column probe:NAME reads as probeNAME
    probe = probe_name[len("probe"):] if probe_name else None
    where = deck_parameter(run_deck(adaptive), f"Output/Probes/{probe}") if probe else None
    axes[1].set_ylabel(f"u({where})" if where else "u at the probe")
    axes[1].set_title(f"probe '{probe}': u at x = ({where})" if where else "probe value")
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
        with exodus(f) as d:
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
    fig.suptitle(f"paper Fig. 6.2: meshes of the final adaptive cycle{adaptive_setting(adaptive)} "
                 f"of {deck_file(adaptive)}" if paper_deck(adaptive) else
                 f"meshes of the final adaptive cycle{adaptive_setting(adaptive)} of {deck_file(adaptive)} "
                 "(cf. paper Fig. 6.2)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "meshes.png"), dpi=150)
    plt.close(fig)


def multiplier_frame(f, i):
    """Multiplier per contact edge of frame i of an Exodus file: (edge starts, edge ends along
    Gamma_C, values, axis along Gamma_C (0: x1, 1: x2), the other coordinate of Gamma_C)."""
    with exodus(f) as d:
        xy = np.column_stack([d.variables["coordx"][:], d.variables["coordy"][:]])
        conn = d.variables["connect1"][:] - 1
        elems = d.variables["elem_ss1"][:] - 1
        sides = d.variables["side_ss1"][:] - 1
        var = names(d.variables["name_sset_var"]).index("lambda") + 1
        lam = np.array(d.variables[f"vals_sset_var{var}ss1"][i, :])
    ends = np.array([(xy[conn[e][s]], xy[conn[e][(s + 1) % 4]]) for e, s in zip(elems, sides)])  # (n, 2, 2)
    axis = 1 if np.ptp(ends[:, :, 1]) > np.ptp(ends[:, :, 0]) else 0
    a, b = np.sort(ends[:, :, axis], axis=1).T
    order = np.argsort(a)
    return a[order], b[order], lam[order], axis, float(ends[0, 0, 1 - axis])


def on_breaks(breaks, a, b, lam):
    """A piecewise constant function on the edges [a, b] sampled on the intervals between breaks."""
    mid = 0.5 * (breaks[:-1] + breaks[1:])
    idx = np.clip(np.searchsorted(a, mid, side="right") - 1, 0, len(a) - 1)
    return np.where((mid >= a[idx]) & (mid <= b[idx]), lam[idx], 0.0)


def local_extrema(values):
    """Local extrema of a sequence of segment values between its first and last non-zero one (1 for
    a profile that falls and rises once)."""
    nz = np.nonzero(values)[0]
    if len(nz) < 3:
        return 0
    d = np.diff(values[nz[0]:nz[-1] + 1])
    d = d[d != 0]
    return int(np.sum(np.sign(d[1:]) != np.sign(d[:-1])))


def multiplier_series(base, t, window):
    """The multiplier of a run along Gamma_C at the output time nearest t and at every output time
    within t +- window, on the common breaks of their edges: a dict with the breaks, the values
    (frames x intervals), the times, the index of the frame nearest t, the axis, the mesh size on
    Gamma_C and the median over the window of local extrema (counted on the multiplier's own
    segments: H = 2h values come in equal pairs)."""
    frames = list(exodus_frames(base))
    nearest = min(frames, key=lambda fr: abs(fr[0] - t))
    chosen = [fr for fr in frames if abs(fr[0] - t) <= window * (1 + 1e-9)] or [nearest]
    if len(chosen) == 1 and window > 0:
        print(f"note: {base}: no output in t = {t:g} +- {window:g} but t = {nearest[0]:.4g}; "
              "the multiplier is drawn at that step only", file=sys.stderr)
    edges = [multiplier_frame(f, i) for _, f, i in chosen]
    breaks = np.unique(np.concatenate([np.concatenate([a, b]) for a, b, *_ in edges]))
    values = np.array([on_breaks(breaks, a, b, lam) for a, b, lam, *_ in edges])
    extrema = [local_extrema(merge_pairs(lam)) for _, _, lam, *_ in edges]
    sizes = np.concatenate([b - a for a, b, *_ in edges])
    times = np.array([fr[0] for fr in chosen])
    at = int(np.argmin(np.abs(times - t)))
    return dict(breaks=breaks, values=values, times=times, at=at, axis=edges[0][3], position=edges[0][4],
                h=(sizes.min(), sizes.max()), extrema=float(np.median(extrema)), extrema_at=extrema[at])


def merge_pairs(lam):
    """The values of the multiplier's own segments: with H = 2h every value comes on two edges."""
    if len(lam) % 2 == 0 and np.array_equal(lam[0::2], lam[1::2]):
        return lam[0::2]
    return lam


def mesh_label(h):
    lo, hi = h
    return f"h = {h_text(lo)}" if np.isclose(lo, hi, rtol=1e-9) else f"h = {h_text(hi)} ... {h_text(lo)}"


def plot_multiplier(paper, stabilised, t, window, out):
    """Paper Fig. 3.1: the multiplier along Gamma_C for H = 2h and H = h. paper and stabilised are
    lists of (base, label); the stabilised runs (Contact Stabilisation) get a panel of their own."""
    paper = [(b, l) for b, l in paper if b and exodus_files(b)]
    stabilised = [(b, l) for b, l in stabilised if b and exodus_files(b)]
    series = {b: multiplier_series(b, t, window) for b, _ in paper + stabilised}
    panels = 2 + bool(stabilised)
    fig, axes = plt.subplots(1, panels, figsize=(5.6 * panels, 5.6), squeeze=False)
    axes = axes[0]
    colours = ["C0", "C3"]

    def draw(ax, runs, snapshot, band, mean):
        for (base, label), colour in zip(runs, colours):
            r = series[base]
            x = r["breaks"]
            step = lambda v: np.append(v, v[-1])  # noqa: E731
            name = f"{label}, {mesh_label(r['h'])}"
            if band and len(r["times"]) > 1:
                ax.fill_between(x, step(r["values"].min(axis=0)), step(r["values"].max(axis=0)), step="post",
                                color=colour, alpha=0.18, lw=0, label=f"{label}: min-max over the window")
            if mean:
                m = r["values"].mean(axis=0)
                ax.step(x, step(m), where="post", color=colour,
                        label=f"{name}: mean over {len(r['times'])} steps "
                              f"({local_extrema(merge_pairs(m))} local extrema)")
            if snapshot:
                ax.step(x, step(r["values"][r["at"]]), where="post", color=colour, lw=1.2,
                        label=f"{name}, t = {r['times'][r['at']]:.4g} ({r['extrema_at']} local extrema)")

    for (base, label), scheme in [(run, "paper's scheme") for run in paper] + \
            [(run, "stabilised") for run in stabilised]:
        r = series[base]
        print(f"multiplier {base} ({label}, {scheme}, {deck_file(base)}): local extrema along Gamma_C at "
              f"t = {r['times'][r['at']]:.4g}: {r['extrema_at']}, median over the {len(r['times'])} steps "
              f"{r['times'].min():.4g} <= t <= {r['times'].max():.4g}: {r['extrema']:g}, of their mean: "
              f"{local_extrema(merge_pairs(r['values'].mean(axis=0)))}; lambda in the window "
              f"{r['values'].min():.3g} .. {r['values'].max():.3g}, "
              f"minimum of the mean {r['values'].mean(axis=0).min():.3g}")
    some = series[(paper + stabilised)[0][0]]
    t_at = some["times"][some["at"]]
    lo, hi = some["times"].min(), some["times"].max()
    draw(axes[0], paper, snapshot=True, band=False, mean=False)
    axes[0].set_title(f"paper's scheme: one step, t = {t_at:.4g}", fontsize=9)
    draw(axes[1], paper, snapshot=False, band=True, mean=True)
    axes[1].set_title(f"paper's scheme: mean and min-max over the {len(some['times'])} steps\n"
                      f"{lo:.4g} <= t <= {hi:.4g} (the scheme chatters in time)", fontsize=9)
    if stabilised:
        draw(axes[2], stabilised, snapshot=True, band=True, mean=False)
        axes[2].set_title(f"Contact Stabilisation = predictor projection (not the paper's scheme):\n"
                          f"one step, t = {t_at:.4g}; shaded: min-max over {lo:.4g} <= t <= {hi:.4g}", fontsize=9)
    name = ("$x_1$", "$x_2$")[some["axis"]]
    other = ("$x_2$", "$x_1$")[some["axis"]]
    # only the part of Gamma_C where some step is in contact, with a margin
    touched = []
    for r in series.values():
        on = np.any(r["values"] != 0, axis=0)  # per interval between breaks
        touched.append(r["breaks"][np.r_[on, False] | np.r_[False, on]])
    touched = np.concatenate(touched)
    if touched.size:
        lo_x, hi_x = touched.min(), touched.max()
        margin = 0.25 * (hi_x - lo_x)
        full = np.concatenate([r["breaks"] for r in series.values()])
        for ax in axes:
            ax.set_xlim(max(lo_x - margin, full.min()), min(hi_x + margin, full.max()))
    for ax in axes:
        ax.set_xlabel(f"{name} along $\\Gamma_C$ ({other} = {some['position']:g})")
        ax.set_ylabel(r"contact multiplier $\lambda_H/(\beta k^2)$ (physical)")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.16))
    decks = sorted({deck_file(b) for b, _ in paper + stabilised})
    fig.suptitle(f"paper Fig. 3.1: the multiplier along $\\Gamma_C$ for H = 2h and H = h ({', '.join(decks)})",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "multiplier.png"), dpi=150)
    plt.close(fig)


def main():
    ap = ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--adaptive", required=True, help="output base of the adaptive run (folder/basename)")
    ap.add_argument("--uniform", help="output base of the uniform comparison run")
    ap.add_argument("--more-adaptive", action="append", default=[], metavar="BASE:LABEL",
                    help="a further adaptive run for the estimate plot (repeatable)")
    ap.add_argument("--two-h", help="output base of a run with H = 2h for the multiplier plot (default: --adaptive)")
    ap.add_argument("--h-equals-h", help="output base of the same run with Contact/Multiplier Segments = H = h")
    ap.add_argument("--two-h-stabilised", help="output base of the --two-h run with Time Integration/Contact "
                    "Stabilisation = predictor projection (a third multiplier panel)")
    ap.add_argument("--h-equals-h-stabilised", help="the same for the --h-equals-h run")
    ap.add_argument("--steps", default="20,60,100,200,300,400", help="steps whose meshes are drawn")
    ap.add_argument("--time-step", type=float, help="the run's time step (default: from its step table)")
    ap.add_argument("--multiplier-time", type=float, default=0.5,
                    help="centre of the time window of the multiplier plot (default 0.5)")
    ap.add_argument("--multiplier-window", type=float, default=0.05,
                    help="half width of the time window of the multiplier's mean and range (default 0.05)")
    ap.add_argument("--title", help="first title line of eta_vs_unknowns.png (default: 'paper Example 6.1 "
                    "(membrane), cf. Fig. 6.3' for a run of inputs/membrane.xml, else '<deck>, cf. paper Fig. 6.3')")
    ap.add_argument("--adaptive-label", help="legend of --adaptive (default: from the run's deck, e.g. 'adaptive, "
                    "fixed fraction 50%%'; 'adaptive' for a run without Exodus output)")
    ap.add_argument("--eta-only", action="store_true",
                    help="draw only eta_vs_unknowns.png (runs without Exodus output, e.g. the finer study)")
    ap.add_argument("--out", required=True, help="folder for the plots (created)")
    a = ap.parse_args()
    try:  # every input first: a missing file or column stops before any plot is written
        for base in [a.adaptive, a.uniform] + [spec.split(":", 1)[0] for spec in a.more_adaptive]:
            if base:
                read_cycles(base)
        if not a.eta_only:
            steps = read_csv(a.adaptive + ".steps.csv", ["t", "energy", "eta_star", "s0", "s1"])
            if a.uniform:  # every cycle's step table (the energy plot)
                for f in [a.uniform + ".steps.csv"] + glob.glob(glob.escape(a.uniform) + ".cycle*.steps.csv"):
                    read_csv(f, ["t", "energy"])
            for base in [a.adaptive, a.two_h, a.h_equals_h, a.two_h_stabilised, a.h_equals_h_stabilised]:
                if base:
                    require_exodus(base)
                    kind = deck_parameter(run_deck(base), "Problem/Type")
                    if kind not in (None, "scalar wave"):
                        raise InputError(f"{base}.e: a run of Problem/Type = {kind}: plot_results.py draws the "
                                         "membrane's figures (paper Example 6.1); tools/plot_bar.py draws an "
                                         "elasticity run's")
            k = a.time_step or time_step(steps)
            mesh_steps = parse_steps(a.steps)
    except InputError as e:
        fail(e)
    output_folder(a.out)
    title = a.title if a.title is not None else "paper Example 6.1 (membrane), cf. Fig. 6.3" if paper_deck(
        a.adaptive) else f"{deck_file(a.adaptive)}, cf. paper Fig. 6.3"
    plot_eta(a.adaptive, a.uniform, a.more_adaptive, a.out, a.adaptive_label, title=title)
    if a.eta_only:
        print("wrote", os.path.join(a.out, "eta_vs_unknowns.png"))
        return
    plot_contributions(a.adaptive, a.out, a.adaptive_label)
    plot_energy_and_probe(a.adaptive, a.uniform, a.out, a.adaptive_label)
    plot_meshes(a.adaptive, mesh_steps, k, a.out)
    plot_multiplier([(a.two_h or a.adaptive, "H = 2h"), (a.h_equals_h, "H = h")],
                    [(a.two_h_stabilised, "H = 2h"), (a.h_equals_h_stabilised, "H = h")],
                    a.multiplier_time, a.multiplier_window, a.out)
    print("wrote", ", ".join(sorted(os.listdir(a.out))))


if __name__ == "__main__":
    main()
