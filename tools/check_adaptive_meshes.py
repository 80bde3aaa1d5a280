#!/usr/bin/python3
"""Checks the meshes of an Exodus series (<base>.e, <base>.e-s.NNNN) written by an adaptive run with
nothing but geometry (independent of the program and of p4est):
  - Algorithm 5.2: no cell edge has more than one hanging node (a corner of another cell strictly
    inside the edge);
  - Algorithm 5.3: no cell of a step's mesh is more than one level coarser than a cell of the next
    step's mesh that it overlaps, and the other way round (forward and backward). This holds between
    consecutive steps only, so it is checked only where both are written: every written time must be
    a step of <base>.steps.csv, with its number of cells, and the pairs of consecutive steps that are
    both written are counted. A run written every step (Output/Exodus Interval = 1) is checked
    throughout; the default output (every 4th step) has no two consecutive steps written, and then
    5.3 is reported as not checked (no violation, exit status 0; --graded fails). Without the table,
    the time step of the deck in the Exodus info records says which written times are consecutive
    steps (if the deck gives none, the written times must be equally spaced and are taken as
    consecutive steps).
The meshes must be dyadic refinements of one uniform grid of axis-parallel rectangles (the
rectangle decks). All corners then lie on the lattice of the finest cell of the series; a cell's
level is fixed by its size on that lattice (the `level` variable must agree up to a constant), and
two cells overlap with positive area exactly when they share a lattice square (a "pixel").
Options: --max-level N: no cell's `level` above N (the largest level found is printed);
--coarser-than BASE2: some step has cells coarser than the mesh of BASE2's series at the same time
  (with --in-every-step: every step compared has)
(a run with coarsening against its previous cycle, Adaptivity/Write All Cycles).
Prints a summary; exit status 1 on any violation.
Usage: check_adaptive_meshes.py BASE [--every N] [--max-level N] [--coarser-than BASE2 [--in-every-step]] [--graded]
(--every N checks only every N-th written mesh: the kept meshes are then not consecutive steps, which
the checker must report: it checks 5.3 between none of them, and --graded fails)."""
import argparse
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from deck_from_exodus import info_lines  # noqa: E402
from exodus_text import names as exodus_names  # noqa: E402
from tool_errors import ArgumentParser, exodus, fail, read_table, reporting  # noqa: E402

parser = ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("base", help="the run's output base (folder/basename): its meshes <base>.e, <base>.e-s.NNNN")
parser.add_argument("--every", type=int, default=1, help="keep only every N-th written mesh")
parser.add_argument("--max-level", type=int, help="no cell's level variable above this")
parser.add_argument("--coarser-than", metavar="BASE2", help="expect cells coarser than BASE2's at the same time")
parser.add_argument("--in-every-step", action="store_true",
                    help="with --coarser-than: in every step compared, not only in some")
parser.add_argument("--graded", action="store_true",
                    help="expect the bounds to be reached: edges with a hanging node, and consecutive meshes "
                         "with cells one level coarser than the other's (forward and backward), so that a run "
                         "whose meshes are uniform or equal fails")
args = parser.parse_args()
if args.every < 1:
    parser.error(f"argument --every: {args.every}: not a positive number")


def series(base):
    files = sorted(glob.glob(glob.escape(base) + ".e") + glob.glob(glob.escape(base) + ".e-s.*"),
                   key=lambda f: int(f.rsplit(".", 1)[1]) if ".e-s." in f else 0)
    if not files:
        fail(f"{base}.e: no such file (no Exodus files {base}.e*)")
    return files


def element_variable(d, name):
    """The element variable `name` at the file's first time (block 1), or None."""
    if "name_elem_var" not in d.variables:
        return None
    names = exodus_names(d["name_elem_var"])
    return d[f"vals_elem_var{names.index(name) + 1}eb1"][0] if name in names else None


def read(files):
    """Per file: times, cell corner coordinates (cells x 4), level variable."""
    out = []
    for f in files:
        with exodus(f) as d:
            x, y = np.asarray(d["coordx"][:]), np.asarray(d["coordy"][:])
            blocks = sorted(v for v in d.variables if v.startswith("connect"))
            conn = np.concatenate([np.asarray(d[b][:]) - 1 for b in blocks])
            level = element_variable(d, "level") if len(blocks) == 1 else None
            out.append({"file": os.path.basename(f), "times": np.asarray(d["time_whole"][:]),
                        "x": x[conn], "y": y[conn], "level": None if level is None else np.asarray(level)})
    return out


meshes = reporting(lambda: read(series(args.base)[::args.every]))
others = reporting(lambda: read(series(args.coarser_than))) if args.coarser_than else []

violations = []

# The common lattice: origin at the lower left corner, spacing the finest cell's sides.
x0 = min(m["x"].min() for m in meshes + others)
y0 = min(m["y"].min() for m in meshes + others)
hx = min((m["x"].max(1) - m["x"].min(1)).min() for m in meshes + others)
hy = min((m["y"].max(1) - m["y"].min(1)).min() for m in meshes + others)


def on_lattice(v, origin, h, name):
    i = np.rint((v - origin) / h).astype(np.int64)
    if np.abs(origin + i * h - v).max() > 1e-6 * h:
        fail(f"{name}: cell corners off the lattice of the series' finest cell: not a dyadic refinement of a "
             "uniform grid")
    return i


for m in meshes + others:
    i, j = on_lattice(m["x"], x0, hx, m["file"]), on_lattice(m["y"], y0, hy, m["file"])
    m["i0"], m["j0"] = i.min(1), j.min(1)
    wx, wy = i.max(1) - m["i0"], j.max(1) - m["j0"]
    # Axis-parallel rectangles: the corners are (i0 or i0 + wx, j0 or j0 + wy), all four of them.
    di, dj = i - m["i0"][:, None], j - m["j0"][:, None]
    at_side = ((di == 0) | (di == wx[:, None])) & ((dj == 0) | (dj == wy[:, None]))
    which = np.sort((di == wx[:, None]) * 1 + (dj == wy[:, None]) * 2, axis=1)
    if not at_side.all() or np.any(which != [0, 1, 2, 3]):
        fail(f"{m['file']}: a cell that is not an axis-parallel rectangle")
    if np.any(wx != wy):
        fail(f"{m['file']}: cells refined differently in x and y")
    m["w"] = wx
    if np.any(m["w"] & (m["w"] - 1)):
        fail(f"{m['file']}: a cell whose size is not a power of two of the finest")
nx = max((m["i0"] + m["w"]).max() for m in meshes + others)
ny = max((m["j0"] + m["w"]).max() for m in meshes + others)
largest = int(np.log2(max(m["w"].max() for m in meshes + others)))
for m in meshes + others:
    m["geometric_level"] = largest - np.rint(np.log2(m["w"])).astype(np.int64)  # 0: the series' largest cells

# The `level` variable must be the geometric level up to one constant for the whole series.
offsets = {int(o) for m in meshes + others if m["level"] is not None for o in np.unique(np.rint(m["level"]) - m["geometric_level"])}
if len(offsets) > 1:
    violations.append(f"the `level` variable differs from the cell sizes' levels by {sorted(offsets)}")


def pixel_levels(m):
    """Per lattice square: the level of the cell covering it; every square covered exactly once
    (computed once per mesh)."""
    if "pixels" in m:
        return m["pixels"]
    levels = np.full((nx, ny), -1, dtype=np.int64)
    covered = np.zeros((nx, ny), dtype=np.int64)
    for i, j, w, lev in zip(m["i0"], m["j0"], m["w"], m["geometric_level"]):
        levels[i:i + w, j:j + w] = lev
        covered[i:i + w, j:j + w] += 1
    if np.any(covered != 1):
        violations.append(f"{m['file']}: the cells do not tile the domain")
    m["pixels"] = levels
    return levels


def max_hanging_nodes_per_edge(m):
    """Largest number of cell corners strictly inside one cell edge."""
    corner = np.zeros((nx + 1, ny + 1), dtype=np.int64)
    for di in (0, 1):
        for dj in (0, 1):
            corner[m["i0"] + di * m["w"], m["j0"] + dj * m["w"]] = 1
    # along_x[i, j]: corners (i', j) with i' < i; along_y[i, j]: corners (i, j') with j' < j.
    along_x = np.vstack([np.zeros((1, ny + 1), dtype=np.int64), np.cumsum(corner, axis=0)])
    along_y = np.hstack([np.zeros((nx + 1, 1), dtype=np.int64), np.cumsum(corner, axis=1)])
    i0, j0, w = m["i0"], m["j0"], m["w"]
    inside = [along_x[i0 + w, j] - along_x[i0 + 1, j] for j in (j0, j0 + w)]   # bottom, top
    inside += [along_y[i, j0 + w] - along_y[i, j0 + 1] for i in (i0, i0 + w)]  # left, right
    return int(max(c.max() for c in inside)), int(sum((c == 1).sum() for c in inside))


# Step numbers of the written times: Algorithm 5.3 applies between consecutive steps only.
times = np.concatenate([m["times"] for m in meshes])
owner = np.concatenate([np.full(len(m["times"]), k) for k, m in enumerate(meshes)])  # mesh of each time
table = args.base + ".steps.csv"
total_steps = None  # steps of the run, when known
if len(times) > 1 and np.diff(times).min() <= 0:
    violations.append("the written times do not increase")
if os.path.exists(table):
    steps = reporting(lambda: read_table(table, ["t", "cells"]))
    step_times, step_cells = np.atleast_1d(steps["t"]), np.atleast_1d(steps["cells"])
    total_steps = len(step_times)
    tolerance = 1e-9 * max(1.0, np.abs(step_times).max())
    step_of = np.abs(times[:, None] - step_times[None, :]).argmin(axis=1)
    found = np.abs(step_times[step_of] - times) <= tolerance
    if not found.all():
        violations.append(f"{(~found).sum()} written times are not steps of {os.path.basename(table)} "
                          f"(first t = {times[~found][0]:.6g})")
    else:
        cells = np.concatenate([np.full(len(m["times"]), len(m["w"])) for m in meshes])
        differ = cells != step_cells[step_of]
        if differ.any():
            violations.append(f"written cells differ from the step table's at t = {times[differ][0]:.6g}")
    step_of = np.where(found, step_of, -10**9)  # an unknown step is no one's neighbour
else:
    def deck_time_step():
        """The deck's Time Step from the first file's info records, or None."""
        values = [line.split('value="', 1)[1].split('"', 1)[0] for line in
                  reporting(lambda: info_lines(series(args.base)[0])) if 'name="Time Step"' in line and 'value="' in line]
        try:
            return float(values[0]) if len(values) == 1 and float(values[0]) > 0 else None
        except ValueError:
            return None
    dt = deck_time_step()
    if dt is not None:
        step_of = np.rint((times - times[0]) / dt).astype(np.int64)
        off = np.abs(times - times[0] - step_of * dt) > 1e-6 * dt
        if off.any():
            violations.append(f"written time t = {times[off][0]:.6g} is not on the deck's time steps (Time Step {dt:g})")
            step_of = np.where(off, -10**9, step_of)
    else:
        gaps = np.diff(times)
        if len(gaps) and (gaps.min() <= 0 or gaps.max() - gaps.min() > 1e-9 * gaps.max()):
            violations.append("the written times are not equally spaced")
        step_of = np.arange(len(times))  # taken as consecutive steps
consecutive = np.diff(step_of) == 1  # per pair of successive written times: consecutive steps
every_step_written = bool(consecutive.all()) and (total_steps is None or len(times) == total_steps)

most_hanging, edges_with_one = 0, 0
for m in meshes:
    hanging, ones = max_hanging_nodes_per_edge(m)
    most_hanging, edges_with_one = max(most_hanging, hanging), edges_with_one + ones
    if hanging > 1:
        violations.append(f"{m['file']} (t = {m['times'][0]:.6g}): an edge with {hanging} hanging nodes")

# Per pixel both meshes' levels: a cell K of one mesh and K' of the other overlap exactly when they
# share a pixel, so max(level(K') - level(K)) over overlapping pairs is the largest pixel difference.
# Only pairs of meshes written at consecutive steps (the last time of one file, the first of the
# next); successive times of one file have the same mesh.
forward = backward = -10**9
mesh_pairs = 0  # pairs of consecutive steps with a new mesh, checked
previous = pixel_levels(meshes[0])
for k, (a, b) in enumerate(zip(meshes, meshes[1:])):
    current = pixel_levels(b)
    if not consecutive[np.flatnonzero(owner == k)[-1]]:  # steps in between not written: 5.3 does not apply
        previous = current
        continue
    mesh_pairs += 1
    coarser_forward = int((previous - current).max())   # cells of the later mesh vs the earlier's
    coarser_backward = int((current - previous).max())  # cells of the earlier mesh vs the later's
    forward, backward = max(forward, coarser_forward), max(backward, coarser_backward)
    if max(coarser_forward, coarser_backward) > 1:
        violations.append(f"{a['file']} (t = {a['times'][-1]:.6g}) -> {b['file']} (t = {b['times'][0]:.6g}): "
                          f"a cell {coarser_forward} (forward) / {coarser_backward} (backward) levels coarser "
                          "than an overlapping cell")
    previous = current

written = f"{len(times)} steps" if every_step_written or total_steps is None else \
    f"{len(times)} of {total_steps} steps written"
print(f"{len(meshes)} meshes ({written}, t = {times.min():.6g} to {times.max():.6g}), "
      f"{min(len(m['w']) for m in meshes)} to {max(len(m['w']) for m in meshes)} cells, "
      f"levels {min(m['geometric_level'].min() for m in meshes)}-{largest} (0: the largest cells)")
print(f"max hanging nodes per edge {most_hanging} (edges with one: {edges_with_one}); max level excess over "
      f"{mesh_pairs} consecutive pairs: forward {forward if mesh_pairs else '-'}, "
      f"backward {backward if mesh_pairs else '-'}")
if not every_step_written:
    pairs = int(consecutive.sum())
    if pairs:
        print(f"not every step is written: Algorithm 5.3 checked between consecutive steps only, on the "
              f"{pairs} pairs of consecutive steps both written ({mesh_pairs} with a new mesh), of "
              f"{len(times) - 1} pairs of successive written steps")
    else:
        print("not every step is written and no two consecutive steps are, so Algorithm 5.3 (between "
              "consecutive steps) was NOT CHECKED; the 2:1 balance of each mesh (Algorithm 5.2) was. To check "
              "5.3, write every step (--set 'Output/Exodus Interval=1')")
if args.graded:
    if edges_with_one == 0:
        violations.append("--graded: no edge has a hanging node (the meshes are not graded)")
    if mesh_pairs == 0 and not every_step_written:
        violations.append("--graded: no two consecutive steps with different meshes are written (write every step: "
                          "Output/Exodus Interval = 1), so the level excess between consecutive meshes is unknown")
    elif len(meshes) < 2 or forward != 1 or backward != 1:
        violations.append(f"--graded: the largest level excess between consecutive meshes is not 1 both ways "
                          f"(forward {forward}, backward {backward}): the meshes do not change from step to step")
if args.max_level is not None:
    if all(m["level"] is None for m in meshes):
        fail(f"--max-level: no element variable level in {args.base}.e*")
    top = max(int(np.rint(m["level"]).max()) for m in meshes if m["level"] is not None)
    print(f"largest level {top} (allowed: {args.max_level})")
    if top > args.max_level:
        violations.append(f"a cell of level {top} above the maximum level {args.max_level}")
if others:
    # Per written time of BASE: its mesh against BASE2's mesh at that time (either may hold several
    # times in one file, and BASE2's mesh may change within the times of one file of BASE).
    at = {round(float(t), 9): o for o in others for t in o["times"]}
    compared = coarser_steps = coarser_cells = 0
    for m in meshes:
        for t in m["times"]:
            o = at.get(round(float(t), 9))
            if o is None:
                continue
            compared += 1
            coarser = pixel_levels(m) < pixel_levels(o)  # pixels where this mesh's cell is coarser than the other's
            if coarser.any():
                coarser_steps += 1
                coarser_cells += sum(1 for i, j, w in zip(m["i0"], m["j0"], m["w"]) if coarser[i:i + w, j:j + w].any())
    print(f"{coarser_steps} of {compared} steps have cells coarser than in {os.path.basename(args.coarser_than)} "
          f"at the same time ({coarser_cells} cells, summed over these steps)")
    if coarser_steps == 0:
        violations.append(f"no cell is coarser than in {os.path.basename(args.coarser_than)} at the same time")
    elif args.in_every_step and coarser_steps < compared:
        violations.append(f"only {coarser_steps} of {compared} steps have cells coarser than in "
                          f"{os.path.basename(args.coarser_than)} (--in-every-step)")
for v in violations[:20]:
    print("VIOLATION:", v)
if len(violations) > 20:
    print(f"... {len(violations) - 20} more")
sys.exit(1 if violations else 0)
