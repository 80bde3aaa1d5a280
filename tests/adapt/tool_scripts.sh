#!/usr/bin/env bash
# The scripts in tools/ on short runs of the paper's decks: tools/plot_results.py draws every
# figure (a requested step beyond the run is drawn as the last step, and said so), an Exodus series
# starts a file only for a new mesh, and both
# tools/plot_results.py and tools/plot_bar.py stop with one line naming the file or column for a
# missing run, a run without the adaptive columns or a table cut short, before writing anything;
# every script in tools/ refuses a missing argument, a missing or cut-short table (also one cut inside
# its last number), a bad argument and a run of the wrong kind (compare_runs.py: runs of other
# final times; plot_bar.py: a scalar membrane run) with one line naming the problem, a non-zero exit
# status and no traceback, and so do the Exodus readers for a file cut short;
# tools/deck_from_exodus.py gives back the deck of a run from its Exodus
# file, and that deck runs to the same step tables, bit for bit; tools/transfer_vs_coarsening.py
# finds the energy kept to rounding wherever a step's mesh only refines its predecessor's.
# tools/check_adaptive_meshes.py checks Algorithm 5.3 only between consecutive steps both written
# (a run written every 4th step passes, saying 5.3 was not checked; two levels between consecutive
# steps fail).
# Output into a closed pipe ends a script quietly, output onto a full device in one line; the
# membrane's checkers refuse the bar; every script's --help shows its whole description; the shell
# scripts answer -h/--help and refuse arguments they do not take before doing anything.
# tools/exodus_rectangle answers -h/--help, refuses bad arguments, and writes a mesh that a deck runs on.
# Usage: tool_scripts.sh SIGNORINI SOURCE_DIR WORK_DIR EXODUS_RECTANGLE
set -uo pipefail
signorini=$1 src=$2 work=$3 rectangle=$4
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
for h in -h --help; do
  "$rectangle" "$h" > "$work/rect-help.out" 2>&1 && grep -q "^usage: exodus_rectangle OUT.exo" "$work/rect-help.out" ||
    { cat "$work/rect-help.out"; fail "exodus_rectangle $h"; }
done
"$rectangle" "$work/r.exo" 0 1 1 0 4 4 > "$work/rect-bad.out" 2>&1
[ $? = 2 ] && [ ! -e "$work/r.exo" ] || fail "exodus_rectangle with Y0 > Y1: not refused"
"$rectangle" "$work/r.exo" 0 1 0 1 4 4 && "$signorini" --check --set 'Mesh/Type=exodus' --set "Mesh/File=$work/r.exo" \
  --set 'Mesh/Cells X=1' --set 'Mesh/Cells Y=1' "$src/inputs/membrane.xml" > "$work/rect-check.log" 2>&1 ||
  { cat "$work/rect-check.log"; fail "a deck on the mesh of exodus_rectangle"; }
short=(--output-dir "$work" --set 'Time Integration/Final Time=0.1' --set 'Adaptivity/Cycles=2')
"$signorini" "${short[@]}" "$src/inputs/membrane.xml" "$src/inputs/membrane-uniform.xml" > "$work/runs.log" 2>&1 ||
  { cat "$work/runs.log"; fail "the runs failed"; }
"$signorini" "${short[@]}" --set 'Adaptivity/Strategy=none' --set 'Output/Basename=plain' \
  "$src/inputs/membrane.xml" > "$work/plain.log" 2>&1 || { cat "$work/plain.log"; fail "the plain run failed"; }
# Not comparable with the others: 4 steps to t = 0.01 (with a 20% fraction and Stiffness 4: the plots' labels
# come from the run's deck).
"$signorini" "${short[@]}" --set 'Time Integration/Final Time=0.01' --set 'Output/Basename=short' \
  --set 'Adaptivity/Refinement Fraction=0.2' --set 'Problem/Stiffness=4' "$src/inputs/membrane.xml" > "$work/short.log" 2>&1 || { cat "$work/short.log"; fail "the short run failed"; }
plot=(/usr/bin/python3 "$src/tools/plot_results.py")

"${plot[@]}" --adaptive "$work/membrane" --uniform "$work/membrane-uniform" --steps 20,40,60 --out "$work/plots" \
  > "$work/plots.log" 2>&1 || { cat "$work/plots.log"; fail "plot_results.py failed on complete runs"; }
# A new file of the Exodus series only for a new mesh (in this run the mesh of step 4 comes back at step 8).
/usr/bin/python3 - "$work/membrane" <<'PY' || fail "the Exodus series: see the line above"
import glob, sys
import netCDF4
base = sys.argv[1]
files = [base + ".e"] + sorted(glob.glob(base + ".e-s.*"))
meshes = []
for f in files:
    with netCDF4.Dataset(f) as d:
        meshes.append(tuple(d.variables[v][:].tobytes() for v in ("coordx", "coordy", "connect1")))
if len(meshes) < 2:
    sys.exit(f"{base}: one file only, so the run's mesh never changed (the test needs a changing one)")
same = [i for i, (a, b) in enumerate(zip(meshes, meshes[1:])) if a == b]
if same:
    sys.exit(f"{base}: files {same[0]} and {same[0] + 1} of the series have the same mesh")
PY
# Exodus name records: the text ends at the first NUL; what follows is undefined (the library writes
# the name and its NUL into a file without fill values) and was seen to hold pieces of the deck.
# Bytes written after the NUL must not change the names the tools read (check_adaptive_meshes.py
# then found no "level" variable and skipped its level checks).
cp "$work/membrane.e" "$work/garbage.e"
/usr/bin/python3 - "$work/garbage.e" "$src/tools" <<'PY' || fail "names with bytes after their NUL are read wrongly"
import sys
import netCDF4
sys.path.insert(0, sys.argv[2])
from exodus_text import names
with netCDF4.Dataset(sys.argv[1], "a") as d:
    var = d["name_elem_var"]
    before = names(var)
    for i, name in enumerate(before):
        row = var[i].copy()
        junk = b'uble" value="0.5"/>'
        for k, c in enumerate(junk[: row.shape[0] - len(name) - 1]):
            row[len(name) + 1 + k] = bytes([c])
        var[i] = row
with netCDF4.Dataset(sys.argv[1]) as d:
    after = names(d["name_elem_var"])
    joined = [b"".join(c for c in row if c).decode() for row in d["name_elem_var"][:]]  # the old reading
assert "level" in before and after == before, (before, after)
assert "level" not in joined, joined  # control: the junk is there
PY
for f in eta_vs_unknowns estimator_contributions meshes multiplier energy_and_probe; do
  [ -s "$work/plots/$f.png" ] || fail "no $f.png"
done
grep -q "note: step 60 is not in the output of .*; drawing step 40 (t = 0.1)" "$work/plots.log" ||
  { cat "$work/plots.log"; fail "no note on the step beyond the run"; }

expect_error() {  # name regex command...: exit status 1, one line matching regex, nothing written
  local name=$1 regex=$2
  shift 2
  "$@" --out "$work/$name" > "$work/$name.log" 2>&1
  local status=$?
  [ "$status" = 1 ] || { cat "$work/$name.log"; fail "$name: exit status $status, expected 1"; }
  ! grep -q Traceback "$work/$name.log" || { cat "$work/$name.log"; fail "$name: a traceback"; }
  [ "$(wc -l < "$work/$name.log")" = 1 ] || { cat "$work/$name.log"; fail "$name: not one line"; }
  grep -q "$regex" "$work/$name.log" || { cat "$work/$name.log"; fail "$name: message"; }
  [ ! -e "$work/$name" ] || fail "$name: wrote $(ls "$work/$name")"
}
expect_error missing "plot_results.py: error: $work/nothing.cycles.csv: no such file" \
  "${plot[@]}" --adaptive "$work/nothing"
cp "$work/plain.steps.csv" "$work/not-adaptive.steps.csv" && cp "$work/membrane.cycles.csv" "$work/not-adaptive.cycles.csv"
expect_error not_adaptive "not-adaptive.steps.csv: no column eta_star, s0, s1" "${plot[@]}" --adaptive "$work/not-adaptive"
cp "$work/membrane.cycles.csv" "$work/cut.cycles.csv"
head -c -40 "$work/membrane.steps.csv" > "$work/cut.steps.csv"
expect_error cut "cut.steps.csv: not a complete table: .*columns instead of" "${plot[@]}" --adaptive "$work/cut"
for f in "$work"/membrane-uniform.*csv; do cp "$f" "$work/cut-uniform${f#"$work"/membrane-uniform}"; done
head -c -40 "$work/membrane-uniform.steps.csv" > "$work/cut-uniform.steps.csv"
expect_error cut_uniform "cut-uniform.steps.csv: not a complete table" \
  "${plot[@]}" --adaptive "$work/membrane" --uniform "$work/cut-uniform"
expect_error bar_missing "plot_bar.py: error: $work/nothing.cycles.csv: no such file" \
  /usr/bin/python3 "$src/tools/plot_bar.py" --adaptive "$work/nothing"
expect_error one_mesh "plot_results.py: error: $work/plain.cycles.csv: no such file: a run on one mesh, not an adaptive run" \
  "${plot[@]}" --adaptive "$work/plain"
expect_error bar_one_mesh "plot_bar.py: error: $work/plain.cycles.csv: no such file: a run on one mesh" \
  /usr/bin/python3 "$src/tools/plot_bar.py" --adaptive "$work/plain"
expect_error bar_scalar "plot_bar.py: error: $work/membrane.e: no nodal variable u_x, u_y .*not an elasticity run" \
  /usr/bin/python3 "$src/tools/plot_bar.py" --adaptive "$work/membrane"
expect_error bad_steps "plot_results.py: error: --steps 5,abc: not a comma-separated list of step numbers" \
  "${plot[@]}" --adaptive "$work/membrane" --steps 5,abc

refuses() {  # name regex command...: a non-zero exit status, one line matching regex, no traceback
  local name=$1 regex=$2
  shift 2
  "$@" > "$work/$name.log" 2>&1
  local status=$?
  [ "$status" != 0 ] || { cat "$work/$name.log"; fail "$name: exit status 0"; }
  ! grep -q Traceback "$work/$name.log" || { cat "$work/$name.log"; fail "$name: a traceback"; }
  [ "$(wc -l < "$work/$name.log")" = 1 ] || { cat "$work/$name.log"; fail "$name: not one line"; }
  grep -q -- "$regex" "$work/$name.log" || { cat "$work/$name.log"; fail "$name: message"; }
}
py=/usr/bin/python3 tools=$src/tools
# Tables cut short inside their last number: the same columns in every row, no line end.
for f in "$work"/membrane.*csv; do cp "$f" "$work/cut-number${f#"$work"/membrane}"; done
for f in "$work"/membrane.e*; do ln -s "$f" "$work/cut-number${f#"$work"/membrane}"; done
head -c -5 "$work/membrane.cycles.csv" > "$work/cut-number.cycles.csv"
head -c -5 "$work/membrane.steps.csv" > "$work/cut-number.steps.csv"
cut_number="not a complete table: its last line has no line end (cut short)"
# compare_runs.py
"$py" "$tools/compare_runs.py" "$work/membrane" "$work/membrane-uniform" > "$work/compare.log" 2>&1 &&
  grep -q "factor [0-9.]* fewer unknowns" "$work/compare.log" ||
  { cat "$work/compare.log"; fail "compare_runs.py on comparable runs"; }
refuses compare_missing "compare_runs.py: error: $work/nothing.cycles.csv: no such file" \
  "$py" "$tools/compare_runs.py" "$work/nothing" "$work/membrane-uniform"
refuses compare_cut "compare_runs.py: error: $work/cut-number.cycles.csv: $cut_number" \
  "$py" "$tools/compare_runs.py" "$work/cut-number" "$work/membrane-uniform"
refuses compare_cut_steps "compare_runs.py: error: $work/cut.steps.csv: not a complete table" \
  "$py" "$tools/compare_runs.py" "$work/cut" "$work/membrane-uniform"
refuses compare_short "compare_runs.py: error: the runs are not comparable: $work/short.steps.csv ends at step 4, t = 0.01, $work/membrane-uniform.steps.csv at step 40, t = 0.1" \
  "$py" "$tools/compare_runs.py" "$work/short" "$work/membrane-uniform" --require-factor 1
refuses compare_no_argument "compare_runs.py: error: the following arguments are required: uniform (usage:" \
  "$py" "$tools/compare_runs.py" "$work/membrane"
# contact_zone_levels.py
refuses zone_no_argument "contact_zone_levels.py: error: the following arguments are required: base" \
  "$py" "$tools/contact_zone_levels.py"
refuses zone_missing "contact_zone_levels.py: error: $work/nothing.steps.csv: no such file" \
  "$py" "$tools/contact_zone_levels.py" "$work/nothing"
refuses zone_cut "contact_zone_levels.py: error: $work/cut.steps.csv: not a complete table" \
  "$py" "$tools/contact_zone_levels.py" "$work/cut"
refuses zone_cut_number "contact_zone_levels.py: error: $work/cut-number.steps.csv: $cut_number" \
  "$py" "$tools/contact_zone_levels.py" "$work/cut-number"
refuses zone_no_contact "contact_zone_levels.py: error: $work/short.steps.csv: no step with active > 0" \
  "$py" "$tools/contact_zone_levels.py" "$work/short"
# check_first_contact.py
refuses first_no_argument "check_first_contact.py: error: the following arguments are required: base" \
  "$py" "$tools/check_first_contact.py"
refuses first_bad_level "check_first_contact.py: error: argument initial_level: invalid int value: 'x'" \
  "$py" "$tools/check_first_contact.py" "$work/membrane" x
refuses first_cut "check_first_contact.py: error: $work/cut.steps.csv: not a complete table" \
  "$py" "$tools/check_first_contact.py" "$work/cut"
# transfer_vs_coarsening.py: the transfer keeps the energy to rounding in the steps whose mesh only
# refines its predecessor's (the L2 projection is exact there), on a run written in every step.
refuses transfer_no_argument "transfer_vs_coarsening.py: error: the following arguments are required: base" \
  "$py" "$tools/transfer_vs_coarsening.py"
refuses transfer_cut "transfer_vs_coarsening.py: error: $work/cut.steps.csv: not a complete table" \
  "$py" "$tools/transfer_vs_coarsening.py" "$work/cut"
refuses transfer_not_every_step "transfer_vs_coarsening.py: error: $work/membrane: no mesh written at t = " \
  "$py" "$tools/transfer_vs_coarsening.py" "$work/membrane"
"$signorini" "${short[@]}" --set 'Adaptivity/Cycles=3' --set 'Output/Exodus Interval=1' --set 'Output/Basename=every' \
  "$src/inputs/membrane.xml" > "$work/every.log" 2>&1 || { cat "$work/every.log"; fail "the run written in every step failed"; }
"$py" "$tools/transfer_vs_coarsening.py" --check "$work/every" > "$work/transfer.log" 2>&1 ||
  { cat "$work/transfer.log"; fail "a transfer onto a refinement of the mesh changed the energy"; }
# compare_step_tables.py
refuses tables_missing "compare_step_tables.py: error: $work/nothing.steps.csv: no such file" \
  "$py" "$tools/compare_step_tables.py" "$work/nothing" "$work/membrane"
# --atol: a column of rounding noise around 0 (1e-5 against 1e7 in the other) differs relative to
# itself but not within an absolute floor; without --rtol the floor is refused.
"$py" - "$work" <<'PY'
import math, sys
for name, sign in (("noise-a", 1.0), ("noise-b", -1.0)):
    with open(f"{sys.argv[1]}/{name}.steps.csv", "w") as f:
        f.write("step,t,reaction_force_y,reaction_force_x\n")
        for n in range(5):
            f.write(f"{n},{n / 10!r},{1e7 * (1 + n / 10) * (1 + sign * 1e-12)!r},{sign * 1e-5 * math.sin(n)!r}\n")
PY
"$py" "$tools/compare_step_tables.py" "$work/noise-a" "$work/noise-b" --rtol 1e-6 > "$work/noise.log" &&
  fail "compare_step_tables.py --rtol passed the noise column"
"$py" "$tools/compare_step_tables.py" "$work/noise-a" "$work/noise-b" --rtol 1e-6 --atol 1e-4 > "$work/noise.log" &&
  grep -q "within 1e-06 of each column's largest magnitude or 0.0001: all equal" "$work/noise.log" ||
  { cat "$work/noise.log"; fail "compare_step_tables.py --atol"; }
refuses tables_atol_alone "compare_step_tables.py: error: --atol needs --rtol" \
  "$py" "$tools/compare_step_tables.py" "$work/noise-a" "$work/noise-b" --atol 1e-4
refuses tables_cut_number "compare_step_tables.py: error: $work/cut-number.steps.csv: $cut_number" \
  "$py" "$tools/compare_step_tables.py" "$work/membrane" "$work/cut-number"
refuses tables_no_argument "compare_step_tables.py: error: the following arguments are required: base_b" \
  "$py" "$tools/compare_step_tables.py" "$work/membrane"
# check_adaptive_meshes.py, check_mirror_symmetry.py, compare_sensitivity.py, deck_from_exodus.py
refuses meshes_cut "check_adaptive_meshes.py: error: $work/cut-number.steps.csv: $cut_number" \
  "$py" "$tools/check_adaptive_meshes.py" "$work/cut-number"
refuses meshes_every "check_adaptive_meshes.py: error: argument --every: 0: not a positive number" \
  "$py" "$tools/check_adaptive_meshes.py" "$work/membrane" --every 0
refuses meshes_missing "check_adaptive_meshes.py: error: $work/nothing.e: no such file" \
  "$py" "$tools/check_adaptive_meshes.py" "$work/nothing"
# check_adaptive_meshes.py checks Algorithm 5.3 only between consecutive steps that are both written:
# on the default output (every 4th step) it says so and exits 0, and --graded (which needs
# consecutive meshes) fails; written every step, it checks every pair. Two meshes of a 2:1 balanced
# series whose cells differ by two levels: a violation as consecutive steps, none with a step between.
"$py" "$tools/check_adaptive_meshes.py" "$work/membrane" > "$work/meshes-interval4.log" 2>&1 &&
  grep -q "no two consecutive steps are, so Algorithm 5.3 (between consecutive steps) was NOT CHECKED" \
    "$work/meshes-interval4.log" && ! grep -q VIOLATION "$work/meshes-interval4.log" ||
  { cat "$work/meshes-interval4.log"; fail "check_adaptive_meshes.py on a run written every 4th step"; }
"$py" "$tools/check_adaptive_meshes.py" "$work/membrane" --graded > "$work/meshes-interval4-graded.log" 2>&1 &&
  { cat "$work/meshes-interval4-graded.log"; fail "--graded passed without two consecutive steps written"; }
grep -q "VIOLATION: --graded: no two consecutive steps with different meshes are written" \
  "$work/meshes-interval4-graded.log" || { cat "$work/meshes-interval4-graded.log"; fail "--graded: message"; }
"$py" "$tools/check_adaptive_meshes.py" "$work/every" --graded > "$work/meshes-every.log" 2>&1 &&
  grep -q "max level excess over [1-9][0-9]* consecutive pairs: forward 1, backward 1" "$work/meshes-every.log" &&
  ! grep -q "not every step" "$work/meshes-every.log" ||
  { cat "$work/meshes-every.log"; fail "check_adaptive_meshes.py on a run written in every step"; }
/usr/bin/python3 - "$work" <<'PY' || fail "the synthetic mesh series"
import sys
import netCDF4
import numpy as np
def squares(cells):  # (x, y, size) -> one block of quadrilaterals
    xy = sorted({(x + dx * s, y + dy * s) for x, y, s in cells for dx in (0, 1) for dy in (0, 1)})
    index = {p: k + 1 for k, p in enumerate(xy)}
    conn = [[index[(x, y)], index[(x + s, y)], index[(x + s, y + s)], index[(x, y + s)]] for x, y, s in cells]
    return np.array(xy, dtype=float), np.array(conn)
coarse = [(0, 0, 4), (4, 0, 4), (0, 4, 4), (4, 4, 4)]  # level 0
fine = [(4, 0, 4), (0, 4, 4), (4, 4, 4), (2, 0, 2), (0, 2, 2), (2, 2, 2),  # level 2 in the lower left corner
        (0, 0, 1), (1, 0, 1), (0, 1, 1), (1, 1, 1)]
for name, t in (("jump.e", 0.0), ("jump.e-s.0001", 1.0), ("gap.e", 0.0), ("gap.e-s.0001", 2.0)):
    xy, conn = squares(coarse if t == 0 else fine)
    with netCDF4.Dataset(f"{sys.argv[1]}/{name}", "w", format="NETCDF3_64BIT_OFFSET") as d:
        d.createDimension("num_nodes", len(xy))
        d.createDimension("num_el_in_blk1", len(conn))
        d.createDimension("num_nod_per_el1", 4)
        d.createDimension("time_step", None)
        d.createVariable("coordx", "f8", ("num_nodes",))[:] = xy[:, 0]
        d.createVariable("coordy", "f8", ("num_nodes",))[:] = xy[:, 1]
        d.createVariable("connect1", "i4", ("num_el_in_blk1", "num_nod_per_el1"))[:] = conn
        d.createVariable("time_whole", "f8", ("time_step",))[0] = t
with open(f"{sys.argv[1]}/jump.steps.csv", "w") as f:
    f.write("step,t,cells\n0,0,4\n1,1,10\n")
with open(f"{sys.argv[1]}/gap.steps.csv", "w") as f:
    f.write("step,t,cells\n0,0,4\n1,1,4\n2,2,10\n")
PY
"$py" "$tools/check_adaptive_meshes.py" "$work/jump" > "$work/meshes-jump.log" 2>&1 &&
  { cat "$work/meshes-jump.log"; fail "a jump of two levels between consecutive steps passed"; }
grep -q "VIOLATION: jump.e (t = 0) -> jump.e-s.0001 (t = 1): a cell 0 (forward) / 2 (backward) levels coarser" \
  "$work/meshes-jump.log" || { cat "$work/meshes-jump.log"; fail "the jump between consecutive steps: message"; }
"$py" "$tools/check_adaptive_meshes.py" "$work/gap" > "$work/meshes-gap.log" 2>&1 &&
  grep -q "2 of 3 steps written.*was NOT CHECKED" <(tr '\n' ' ' < "$work/meshes-gap.log") ||
  { cat "$work/meshes-gap.log"; fail "the same meshes two steps apart: no violation, 5.3 not checked"; }
refuses mirror_no_argument "check_mirror_symmetry.py: error: the following arguments are required: base" \
  "$py" "$tools/check_mirror_symmetry.py"
refuses sensitivity_no_argument "compare_sensitivity.py: error: the following arguments are required: dir" \
  "$py" "$tools/compare_sensitivity.py"
refuses sensitivity_missing "compare_sensitivity.py: error: $work/paper.np1.steps.csv: no such file" \
  "$py" "$tools/compare_sensitivity.py" "$work"
refuses deck_no_argument "deck_from_exodus.py: error: the following arguments are required: exodus_file" \
  "$py" "$tools/deck_from_exodus.py"
# Exodus files cut short (netCDF reads zeros for what is missing): refused by the header's size.
for f in "$work"/membrane.*csv; do cp "$f" "$work/cut-exodus${f#"$work"/membrane}"; done
for f in "$work"/membrane.e*; do cp "$f" "$work/cut-exodus${f#"$work"/membrane}"; done
last=$(ls "$work"/cut-exodus.e-s.* | sort | tail -1)
truncate -s -1000 "$last"
expect_error cut_exodus "plot_results.py: error: $last: cut short: [0-9]* bytes, its header needs [0-9]*" \
  "${plot[@]}" --adaptive "$work/cut-exodus"
refuses meshes_cut_exodus "check_adaptive_meshes.py: error: $last: cut short" \
  "$py" "$tools/check_adaptive_meshes.py" "$work/cut-exodus"
# The size from the header on netCDF classic files of every kind (CDF-1, -2, -5; one record variable,
# whose records are not padded, or two; types of 1, 2 and 8 bytes): complete files accepted, files
# short of one byte refused.
/usr/bin/python3 - "$work" "$src/tools" <<'PY' || fail "classic netCDF sizes"
import os, sys
import netCDF4
import numpy as np
sys.path.insert(0, sys.argv[2])
from tool_errors import InputError, require_complete_exodus
for fmt in ("NETCDF3_CLASSIC", "NETCDF3_64BIT_OFFSET", "NETCDF3_64BIT_DATA"):
    for dtype in ("S1", "i2", "f8"):
        for nvars in (1, 2):
            path = os.path.join(sys.argv[1], f"nc-{fmt}-{dtype}-{nvars}.nc")
            with netCDF4.Dataset(path, "w", format=fmt) as d:
                d.createDimension("time", None)
                d.createDimension("n", 5)
                for k in range(nvars):
                    v = d.createVariable(f"v{k}", dtype, ("time", "n"))
                    for r in range(7):
                        v[r] = np.array(list("abcde"), dtype="S1") if dtype == "S1" else np.arange(5, dtype=dtype)
            require_complete_exodus(path)  # raises InputError if refused
            with open(path, "r+b") as f:
                f.truncate(os.path.getsize(path) - (4 if nvars == 2 and dtype != "f8" else 1))
            try:
                require_complete_exodus(path)
                sys.exit(f"{path}: cut short, but accepted")
            except InputError:
                pass
PY
cp "$work/membrane.e" "$work/cut-deck.e" && truncate -s -8 "$work/cut-deck.e"
refuses deck_cut_exodus "deck_from_exodus.py: error: $work/cut-deck.e: cut short" \
  "$py" "$tools/deck_from_exodus.py" "$work/cut-deck.e"

/usr/bin/python3 "$src/tools/deck_from_exodus.py" "$work/membrane.e" > "$work/as-run.xml" || fail "no deck from the Exodus file"
"$signorini" --output-dir "$work" --set 'Output/Basename=again' "$work/as-run.xml" > "$work/again.log" 2>&1 ||
  { cat "$work/again.log"; fail "the deck from the Exodus file does not run"; }
/usr/bin/python3 "$src/tools/compare_step_tables.py" "$work/membrane" "$work/again" ||
  fail "the deck from the Exodus file ran to other step tables"
# A deck whose Mesh/File is relative to the deck's folder: the recorded deck runs from elsewhere.
"$signorini" --output-dir "$work" --set 'Output/Basename=exo' "$src/tests/driver/decks/good-exodus.xml" \
  > "$work/exo.log" 2>&1 || { cat "$work/exo.log"; fail "the Exodus-mesh deck failed"; }
/usr/bin/python3 "$src/tools/deck_from_exodus.py" "$work/exo.e" > "$work/exo-as-run.xml" || fail "no deck from exo.e"
"$signorini" --output-dir "$work" --set 'Output/Basename=exo-again' "$work/exo-as-run.xml" > "$work/exo-again.log" 2>&1 ||
  { cat "$work/exo-again.log"; fail "the recorded Exodus-mesh deck does not run from another folder"; }
/usr/bin/python3 "$src/tools/compare_step_tables.py" "$work/exo" "$work/exo-again" ||
  fail "the recorded Exodus-mesh deck ran to other step tables"

# Output that cannot be written (tools/tool_errors.py): into a pipe closed before the script writes
# (| head -1) a script ends quietly, killed by SIGPIPE, with nothing on stderr (not a BrokenPipeError
# traceback); into a full device (/dev/full) it ends with one line 'cannot write output' and exit
# status 1, also for what it prints at its top level and what is left for the flush at exit.
/usr/bin/python3 - "$work" "$tools" <<'PY' || fail "output into a closed pipe"
import os, signal, subprocess, sys
work, tools = sys.argv[1:]
m = f"{work}/membrane"
bad = []
for cmd in (["compare_runs.py", m, m], ["check_adaptive_meshes.py", m], ["deck_from_exodus.py", m + ".e"],
            ["compare_step_tables.py", m, m], ["check_mirror_symmetry.py", m], ["check_paraview.py", "--help"]):
    r, w = os.pipe()
    os.close(r)  # closed before the script writes: every write fails
    p = subprocess.run(["/usr/bin/python3", f"{tools}/{cmd[0]}"] + cmd[1:], stdout=w, stderr=subprocess.PIPE)
    os.close(w)
    if p.returncode != -signal.SIGPIPE or p.stderr:
        bad.append(f"{cmd[0]} into a closed pipe: exit status {p.returncode}, stderr {p.stderr.decode()[-300:]!r}")
if bad:
    sys.exit("\n".join(bad))
PY
full() {  # name regex command...: stdout on /dev/full: exit status 1, one line on stderr matching regex
  local name=$1 regex=$2
  shift 2
  "$@" > /dev/full 2> "$work/$name.log"
  local status=$?
  [ "$status" = 1 ] || { cat "$work/$name.log"; fail "$name: exit status $status, expected 1"; }
  ! grep -q Traceback "$work/$name.log" || { cat "$work/$name.log"; fail "$name: a traceback"; }
  [ "$(wc -l < "$work/$name.log")" = 1 ] || { cat "$work/$name.log"; fail "$name: not one line"; }
  grep -q -- "$regex" "$work/$name.log" || { cat "$work/$name.log"; fail "$name: message"; }
}
if [ -w /dev/full ]; then
  full deck_full "deck_from_exodus.py: error: cannot write output: No space left on device" \
    "$py" "$tools/deck_from_exodus.py" "$work/membrane.e"
  full tables_full "compare_step_tables.py: error: cannot write output: No space left on device" \
    "$py" "$tools/compare_step_tables.py" "$work/membrane" "$work/membrane"
  full mirror_full "check_mirror_symmetry.py: error: cannot write output: No space left on device" \
    "$py" "$tools/check_mirror_symmetry.py" "$work/membrane"
  full compare_full "compare_runs.py: error: cannot write output: No space left on device" \
    "$py" "$tools/compare_runs.py" "$work/membrane" "$work/membrane-uniform"
else
  echo "skipped: the full-disk checks (/dev/full is not writable here)"
fi
# Runs of the wrong kind and bad arguments: the membrane's checkers and plot_results.py refuse the bar (its domain is
# [0,0.2]x[0,0.05], not the membrane's [0,1]^2), a mirror line that is not finite or not inside the
# domain and a negative level; deck_from_exodus.py names a directory as such.
"$signorini" --output-dir "$work" --set 'Time Integration/Final Time=3e-4' --set 'Adaptivity/Cycles=1' \
  "$src/inputs/bar.xml" > "$work/bar.log" 2>&1 || { cat "$work/bar.log"; fail "the bar run failed"; }
not_membrane="$work/bar.e: not a membrane run: the cells do not cover \[0,1\]^2"
refuses first_bar "check_first_contact.py: error: $not_membrane" "$py" "$tools/check_first_contact.py" "$work/bar"
refuses mirror_bar "check_mirror_symmetry.py: error: $not_membrane" "$py" "$tools/check_mirror_symmetry.py" "$work/bar"
refuses zone_bar "contact_zone_levels.py: error: $not_membrane" "$py" "$tools/contact_zone_levels.py" "$work/bar"
refuses plot_bar_run "plot_results.py: error: $work/bar.e: a run of Problem/Type = plane strain elasticity: plot_results.py draws" \
  "$py" "$tools/plot_results.py" --adaptive "$work/bar" --out "$work/plots-of-bar"
[ ! -e "$work/plots-of-bar" ] || fail "plot_results.py made its output folder for an elasticity run"
# plot_steps.py: any run's columns against t (the bar's, the membrane's cycle 0 as rates); one curve per
# run and matched column (counted here from the headers); one-line errors before anything is written.
"$py" "$tools/plot_steps.py" "$work/bar" "$work/bar" --columns 'energy,kinetic_energy' 'probe:*' 'contact_*' \
  --out "$work/bar-steps.png" > "$work/plot-steps.log" 2>&1 || { cat "$work/plot-steps.log"; fail "plot_steps.py on the bar"; }
matched=$("$py" -c "import csv, fnmatch, sys; h = next(csv.reader(open(sys.argv[1]))); print(2 * sum(any(fnmatch.fnmatchcase(n, p) for p in ('energy', 'kinetic_energy', 'probe:*', 'contact_*')) for n in h))" "$work/bar.steps.csv")
[ "$matched" -ge 6 ] && grep -qx "wrote $work/bar-steps.png: $matched curve(s) in 3 panel(s)" "$work/plot-steps.log" && [ -s "$work/bar-steps.png" ] ||
  { cat "$work/plot-steps.log"; fail "plot_steps.py on the bar: not the $matched curves matched"; }
"$py" "$tools/plot_steps.py" "$work/membrane" --cycle 0 --rate --columns energy --out "$work/membrane-rate.png" > "$work/plot-rate.log" 2>&1 &&
  grep -qx "wrote $work/membrane-rate.png: 1 curve(s) in 1 panel(s)" "$work/plot-rate.log" || { cat "$work/plot-rate.log"; fail "plot_steps.py --rate --cycle 0"; }
refuses steps_no_match "plot_steps.py: error: $work/bar.steps.csv: no column matches 'probe:nowhere' (its columns: step, t," \
  "$py" "$tools/plot_steps.py" "$work/bar" --columns energy,probe:nowhere --out "$work/never.png"
refuses steps_missing "plot_steps.py: error: $work/nothing.steps.csv: no such file" \
  "$py" "$tools/plot_steps.py" "$work/bar" "$work/nothing" --columns energy --out "$work/never.png"
refuses steps_no_folder "plot_steps.py: error: --out $work/no/such.png: no folder $work/no" \
  "$py" "$tools/plot_steps.py" "$work/bar" --columns energy --out "$work/no/such.png"
for c in 2 -1; do
  refuses "steps_cycle_$c" "plot_steps.py: error: --cycle $c: $work/membrane.cycles.csv has cycles 0 to 1" \
    "$py" "$tools/plot_steps.py" "$work/membrane" --cycle "$c" --columns energy --out "$work/never.png"
done
# A time window: the bar's steps with 1e-5 <= t <= 3e-5 are three (k = 1e-5; its t are n k).
"$py" "$tools/plot_steps.py" "$work/bar" --columns energy --tmin 1e-5 --tmax 3e-5 --out "$work/bar-window.png" \
  > "$work/plot-window.log" 2>&1 &&
  grep -qx "wrote $work/bar-window.png: 1 curve(s) in 1 panel(s), 3 step(s) of t in \[1e-05, 3e-05\] in bar" "$work/plot-window.log" ||
  { cat "$work/plot-window.log"; fail "plot_steps.py --tmin --tmax"; }
refuses steps_empty_window "plot_steps.py: error: $work/bar.steps.csv: no step with 5 <= t <= 6 (it has t = 0 to " \
  "$py" "$tools/plot_steps.py" "$work/bar" --columns energy --tmin 5 --tmax 6 --out "$work/never.png"
refuses steps_reversed_window "plot_steps.py: error: --tmin 2.0 is after --tmax 1.0" \
  "$py" "$tools/plot_steps.py" "$work/bar" --columns energy --tmin 2 --tmax 1 --out "$work/never.png"
[ ! -e "$work/never.png" ] || fail "plot_steps.py wrote a figure after an error"
# plot_steps.py --scale, --hline: a column times a factor, reference lines in chosen panels.
"$py" "$tools/plot_steps.py" "$work/bar" --columns 'contact_force' 'probe:*' --scale 'probe:*=1000' \
  --hline 1:0 --hline 2:-5:obstacle --out "$work/bar-scaled.png" > "$work/plot-scaled.log" 2>&1 &&
  grep -q "^wrote $work/bar-scaled.png: .* in 2 panel(s), 2 reference line(s)$" "$work/plot-scaled.log" ||
  { cat "$work/plot-scaled.log"; fail "plot_steps.py --scale --hline"; }
refuses steps_hline_panel "plot_steps.py: error: --hline 3:1: expected PANEL:VALUE\[:LABEL\] with PANEL 1 to 2" \
  "$py" "$tools/plot_steps.py" "$work/bar" --columns energy contact_force --hline 3:1 --out "$work/never.png"
refuses steps_scale_zero "plot_steps.py: error: --scale probe:\*=0: expected PATTERN=FACTOR with a finite factor other than 0" \
  "$py" "$tools/plot_steps.py" "$work/bar" --columns 'probe:*' --scale 'probe:*=0' --out "$work/never.png"
refuses steps_scale_unmatched "plot_steps.py: error: --scale stress\*: matches no column drawn from $work/bar.steps.csv" \
  "$py" "$tools/plot_steps.py" "$work/bar" --columns energy --scale 'stress*=2' --out "$work/never.png"
[ ! -e "$work/never.png" ] || fail "plot_steps.py wrote a figure after an error"
# summarize_steps.py: window summaries. (1) A table written here, x = 2 t + 1 and a contact in three
# intervals: the trapezoidal mean and integral are exact for linear data. (2) The bar on one mesh
# with the paper's scheme: the momentum's change over the run is exactly the trapezoidal integral
# of the force resultant, and the angular momentum's that of the moments (to the solves' tolerance).
"$py" - "$work/synthetic.steps.csv" <<'PY'
import sys
active = [0, 1, 1, 0, 0, 2, 0, 0, 1, 1, 1]
with open(sys.argv[1], "w") as f:
    f.write("step,t,active,contact_force,x\n")
    for n in range(11):
        f.write(f"{n},{n / 10!r},{active[n]},{-3.0 * active[n]!r},{2 * n / 10 + 1!r}\n")
PY
"$py" "$tools/summarize_steps.py" "$work/synthetic" --columns x --tmin 0.2 --tmax 0.5 --csv > "$work/summary-window.csv" &&
  "$py" "$tools/summarize_steps.py" "$work/synthetic" --columns x > "$work/summary.log" 2>&1 &&
  "$py" - "$work" <<'PY' || { cat "$work/summary-window.csv" "$work/summary.log"; fail "summarize_steps.py on a table written here"; }
import csv, sys
work = sys.argv[1]
row = next(csv.DictReader(open(f"{work}/summary-window.csv")))
expected = {"steps": 4, "t_first": 0.2, "t_last": 0.5, "mean": 1.7, "integral": 0.51, "min": 1.4, "t_min": 0.2,
            "max": 2.0, "t_max": 0.5, "last": 2.0}
bad = [f"{k} {row[k]} (expected {v})" for k, v in expected.items() if abs(float(row[k]) - v) > 1e-12]
text = open(f"{work}/summary.log").read()
for line in ("contact: 6 of 11 steps with an active segment, from t = 0.1 to t = 1 in 3 interval(s); at most 2 active",
             "contact_force: largest |value| -6 at t = 0.5; impulse -1.95"):
    if line not in text:
        bad.append(f"no line '{line}'")
if bad:
    sys.exit("; ".join(bad))
PY
"$signorini" --output-dir "$work/bar-one-mesh" --set 'Adaptivity/Strategy=none' --set 'Time Integration/Final Time=3e-4' \
  --set 'Output/Write Exodus=false' "$src/inputs/bar.xml" > "$work/bar-one-mesh.log" 2>&1 ||
  { cat "$work/bar-one-mesh.log"; fail "the bar on one mesh"; }
"$py" "$tools/summarize_steps.py" "$work/bar-one-mesh/bar" --csv --columns 'momentum_y,angular_momentum' \
  'applied_load_y,reaction_force_y,contact_force' 'applied_moment,reaction_moment,contact_moment' > "$work/summary-bar.csv" &&
  "$py" - "$work/summary-bar.csv" <<'PY' || { cat "$work/summary-bar.csv"; fail "summarize_steps.py: the bar's impulses"; }
import csv, sys
s = {r["column"]: r for r in csv.DictReader(open(sys.argv[1]))}
def change(c):  # the bar starts at rest: both momenta are 0 at t = 0
    return float(s[c]["last"])
for quantity, forces in (("momentum_y", ("applied_load_y", "reaction_force_y", "contact_force")),
                         ("angular_momentum", ("applied_moment", "reaction_moment", "contact_moment"))):
    impulse = sum(float(s[f]["integral"]) for f in forces)
    scale = max(abs(float(s[f]["integral"])) for f in forces)
    if not abs(change(quantity) - impulse) <= 1e-8 * scale:
        sys.exit(f"{quantity} changes by {change(quantity)!r}, the forces' impulse is {impulse!r}")
if float(s["contact_force"]["max"]) <= 0:
    sys.exit("no contact in the window")
PY
# The peak stress's place: the table's max_von_mises_at_x, _at_y in the step of the largest value;
# the place columns are not summarised themselves.
"$py" "$tools/summarize_steps.py" "$work/bar-one-mesh/bar" --csv --columns 'max_von_mises*' > "$work/summary-peak.csv" &&
  "$py" - "$work" <<'PY' || { cat "$work/summary-peak.csv"; fail "summarize_steps.py: the peak stress's place"; }
import csv, sys
work = sys.argv[1]
rows = list(csv.DictReader(open(f"{work}/summary-peak.csv")))
table = list(csv.DictReader(open(f"{work}/bar-one-mesh/bar.steps.csv")))
peak = max(table, key=lambda r: float(r["max_von_mises"]))
if [r["column"] for r in rows] != ["max_von_mises"]:
    sys.exit(f"summarised {[r['column'] for r in rows]}, expected max_von_mises alone")
if (float(rows[0]["x_at_max"]), float(rows[0]["y_at_max"])) != (float(peak["max_von_mises_at_x"]),
                                                               float(peak["max_von_mises_at_y"])):
    sys.exit(f"place {rows[0]['x_at_max']}, {rows[0]['y_at_max']}; the table's at step {peak['step']}: "
             f"{peak['max_von_mises_at_x']}, {peak['max_von_mises_at_y']}")
PY
# Steps without a value (nan: a Stress Region without a cell on a later mesh) are left out and counted:
# y = 2 t + 1 with nan at t = 0 and 0.5 has its min at t = 0.1, its integral over the intervals between
# two values (0.1..0.4, 0.6..1: 0.96 + 1.36 = ... by hand below).
"$py" - "$work/gaps.steps.csv" <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write("step,t,y\n")
    for n in range(11):
        f.write(f"{n},{n / 10!r},{'nan' if n in (0, 5) else repr(2 * n / 10 + 1)}\n")
PY
"$py" "$tools/summarize_steps.py" "$work/gaps" --columns y --csv > "$work/summary-gaps.csv" &&
  "$py" "$tools/summarize_steps.py" "$work/gaps" --columns y > "$work/summary-gaps.log" &&
  "$py" - "$work" <<'PY' || { cat "$work/summary-gaps.csv" "$work/summary-gaps.log"; fail "summarize_steps.py: steps without a value"; }
import csv, sys
work = sys.argv[1]
row = next(csv.DictReader(open(f"{work}/summary-gaps.csv")))
# intervals [0.1, 0.4] and [0.6, 1.0] of y = 2 t + 1: integrals 0.3 * 1.5 * 2 = 0.9... computed exactly:
integral = (0.4 - 0.1) * (1 + (0.1 + 0.4)) + (1.0 - 0.6) * (1 + (0.6 + 1.0))
expected = {"integral": integral, "mean": integral / 0.7, "min": 1.2, "t_min": 0.1, "max": 3.0, "t_max": 1.0,
            "missing": 2}
bad = [f"{k} {row[k]} (expected {v})" for k, v in expected.items() if abs(float(row[k]) - v) > 1e-12]
if "y: no value (nan) in 2 of 11 steps, left out" not in open(f"{work}/summary-gaps.log").read():
    bad.append("no line on the 2 steps without a value")
if bad:
    sys.exit("; ".join(bad))
PY
refuses summary_places_only "summarize_steps.py: error: $work/bar-one-mesh/bar.steps.csv: 'max_von_mises_at\*' matches only place columns" \
  "$py" "$tools/summarize_steps.py" "$work/bar-one-mesh/bar" --columns 'max_von_mises_at*'
refuses summary_no_match "summarize_steps.py: error: $work/bar.steps.csv: no column matches 'nowhere'" \
  "$py" "$tools/summarize_steps.py" "$work/bar" --columns nowhere
refuses summary_empty_window "summarize_steps.py: error: $work/bar.steps.csv: no step with 5 <= t <= 6" \
  "$py" "$tools/summarize_steps.py" "$work/bar" --tmin 5 --tmax 6
refuses summary_missing "summarize_steps.py: error: $work/nothing.steps.csv: no such file" \
  "$py" "$tools/summarize_steps.py" "$work/nothing"
refuses mirror_nan "check_mirror_symmetry.py: error: argument axis: nan: not a line x2 = c inside" \
  "$py" "$tools/check_mirror_symmetry.py" "$work/membrane" nan
refuses mirror_outside "check_mirror_symmetry.py: error: argument axis: 1.5: not a line x2 = c inside" \
  "$py" "$tools/check_mirror_symmetry.py" "$work/membrane" 1.5
refuses first_negative_level "check_first_contact.py: error: argument initial_level: -5: not a level (0 or more)" \
  "$py" "$tools/check_first_contact.py" "$work/membrane" -5
refuses deck_directory "deck_from_exodus.py: error: $work: a directory, not a file" \
  "$py" "$tools/deck_from_exodus.py" "$work"
# Empty tables (0 bytes: numpy's reader raised IndexError): one line '<table>: empty' in every reader.
: > "$work/empty.steps.csv" && : > "$work/empty.cycles.csv"
refuses empty_compare "compare_runs.py: error: $work/empty.cycles.csv: empty" "$py" "$tools/compare_runs.py" "$work/empty" "$work/membrane-uniform"
refuses empty_first "check_first_contact.py: error: $work/empty.steps.csv: empty" "$py" "$tools/check_first_contact.py" "$work/empty"
refuses empty_zone "contact_zone_levels.py: error: $work/empty.steps.csv: empty" "$py" "$tools/contact_zone_levels.py" "$work/empty"
refuses empty_transfer "transfer_vs_coarsening.py: error: $work/empty.steps.csv: empty" "$py" "$tools/transfer_vs_coarsening.py" "$work/empty"
expect_error empty_plot "plot_results.py: error: $work/empty.cycles.csv: empty" "${plot[@]}" --adaptive "$work/empty"
expect_error empty_bar "plot_bar.py: error: $work/empty.cycles.csv: empty" "$py" "$tools/plot_bar.py" --adaptive "$work/empty"
# --out that cannot be a folder: one line naming --out, no traceback.
: > "$work/afile"
refuses out_file "plot_results.py: error: --out $work/afile: not a folder" \
  "${plot[@]}" --adaptive "$work/membrane" --eta-only --out "$work/afile"
refuses out_under_file "plot_results.py: error: --out $work/afile/x: cannot create the folder" \
  "${plot[@]}" --adaptive "$work/membrane" --eta-only --out "$work/afile/x"
refuses bar_out_file "plot_bar.py: error: --out $work/afile: not a folder" \
  "$py" "$tools/plot_bar.py" --adaptive "$work/bar" --out "$work/afile"
# Labels from the run's deck: the legend of --adaptive (not the paper's 50% for every run; plot_bar.py
# takes --adaptive-label too), kappa of a scalar run with Problem/Stiffness 4 (not lambda_L + 2 mu),
# the foundation of the bar (Problem/Obstacle under Gamma_C).
"$py" - "$work" "$tools" <<'PY' || fail "labels from the run's deck"
import sys
sys.path.insert(0, sys.argv[2])
import plot_bar, plot_results
work = sys.argv[1]
checks = [(plot_results.adaptive_label(f"{work}/membrane"), "adaptive, fixed fraction 50%"),
          (plot_results.adaptive_label(f"{work}/short"), "adaptive, fixed fraction 20%"),
          (plot_results.scaling_note(f"{work}/short").endswith("($\\kappa$ = Problem/Stiffness = 4)"), True),
          ("lambda_L" in plot_results.scaling_note(f"{work}/short"), False),
          (tuple(round(v, 9) for v in plot_bar.foundation(f"{work}/bar", f"{work}/bar.e")), (0.15, 0.2, 0.0, -0.005))]
bad = [f"{got!r}, expected {want!r}" for got, want in checks if got != want]
if bad:
    sys.exit("; ".join(bad))
PY
"$py" "$tools/plot_bar.py" --help | grep -q -- "--adaptive-label" || fail "plot_bar.py has no --adaptive-label"
# compare_runs.py: a required factor that is not a number, and the runs given the other way round.
refuses compare_nan "compare_runs.py: error: argument --require-factor: nan: not a factor" \
  "$py" "$tools/compare_runs.py" "$work/membrane" "$work/membrane-uniform" --require-factor nan
refuses compare_swapped "compare_runs.py: error: .*the arguments swapped?" \
  "$py" "$tools/compare_runs.py" "$work/membrane-uniform" "$work/membrane"
# check_first_contact.py on a run written every 4th step: an input problem (one line), not a failed check.
refuses first_not_every_step "check_first_contact.py: error: $work/membrane: steps [0-9]* and [0-9]* (the first contact) are not both in the Exodus series" \
  "$py" "$tools/check_first_contact.py" "$work/membrane"
# transfer_vs_coarsening.py on a run starting at rest (E(0) = 0, here a copy of the run written every
# step with energy 0 in step 0): relative to the largest energy, never NaN; --check fails when the
# steps that only refine change the energy (1e-3 added to energy_transferred wherever the transfer is not exact).
mkdir -p "$work/rest" "$work/rest-bad"
for f in "$work"/every.e*; do ln -sf "$f" "$work/rest/${f##*/}"; ln -sf "$f" "$work/rest-bad/${f##*/}"; done
"$py" - "$work" <<'PY' || fail "the copies at rest"
import csv, sys
work = sys.argv[1]
rows = list(csv.reader(open(f"{work}/every.steps.csv")))
h = rows[0]
e, tr = h.index("energy"), h.index("energy_transferred")
rows[1][e] = "0"
csv.writer(open(f"{work}/rest/every.steps.csv", "w", newline=""), lineterminator="\n").writerows(rows)
for k in range(2, len(rows)):
    if float(rows[k][tr]) != float(rows[k - 1][e]):
        rows[k][tr] = repr(float(rows[k][tr]) + 1e-3)
csv.writer(open(f"{work}/rest-bad/every.steps.csv", "w", newline=""), lineterminator="\n").writerows(rows)
PY
"$py" "$tools/transfer_vs_coarsening.py" --check "$work/rest/every" > "$work/transfer-rest.log" 2>&1 &&
  grep -q "largest energy change [0-9.e+-]* max E" "$work/transfer-rest.log" && ! grep -qi "nan\|inf\|Warning" "$work/transfer-rest.log" ||
  { cat "$work/transfer-rest.log"; fail "transfer_vs_coarsening.py on a run starting at rest"; }
"$py" "$tools/transfer_vs_coarsening.py" --check "$work/rest-bad/every" > "$work/transfer-rest-bad.log" 2>&1 &&
  { cat "$work/transfer-rest-bad.log"; fail "transfer_vs_coarsening.py --check passed energy changes of 1e-3 in a run at rest"; }
grep -q "a step that only refines changes the energy by more than 1e-12 max E" "$work/transfer-rest-bad.log" ||
  { cat "$work/transfer-rest-bad.log"; fail "transfer_vs_coarsening.py --check at rest: message"; }
# Bases with glob characters: the files of the run are found (compare_step_tables.py compares the cycle
# tables, the Exodus readers find the series).
mkdir -p "$work/glob[1]" "$work/glob[2]"
for f in "$work"/membrane.*csv; do cp "$f" "$work/glob[1]/${f##*/}"; cp "$f" "$work/glob[2]/${f##*/}"; done
for f in "$work"/membrane.e*; do ln -sf "$f" "$work/glob[1]/${f##*/}"; done
sed -i '5s/^\([0-9]*\),\([^,]*\),\([0-9]*\)/\1,\2,99999/' "$work/glob[1]/membrane.cycle0.steps.csv"
"$py" "$tools/compare_step_tables.py" "$work/glob[1]/membrane" "$work/glob[2]/membrane" > "$work/glob-tables.log" 2>&1 &&
  fail "compare_step_tables.py: bases with [..]: a changed cycle table not found"
grep -q "^.cycle0.steps.csv: dofs differs first in row 4: 99999" "$work/glob-tables.log" ||
  { cat "$work/glob-tables.log"; fail "compare_step_tables.py: bases with [..]: message"; }
"$py" "$tools/check_mirror_symmetry.py" "$work/glob[1]/membrane" > "$work/glob-mirror.log" 2>&1 &&
  grep -q "^$(ls "$work"/membrane.e* | wc -l) meshes" "$work/glob-mirror.log" ||
  { cat "$work/glob-mirror.log"; fail "check_mirror_symmetry.py: a base with [..]"; }
"$py" "$tools/check_adaptive_meshes.py" "$work/glob[1]/membrane" > "$work/glob-meshes.log" 2>&1 ||
  { cat "$work/glob-meshes.log"; fail "check_adaptive_meshes.py: a base with [..]"; }
# compare_step_tables.py: a header that differs is named as such (not 'differ in shape' with equal row
# counts); a cell that is not a number: one line naming file, row and column.
mkdir -p "$work/cst"
for f in "$work"/membrane.*csv; do cp "$f" "$work/cst/a${f#"$work"/membrane}"; cp "$f" "$work/cst/b${f#"$work"/membrane}"; done
sed -i '1s/,energy,/,energyX,/' "$work/cst/b.steps.csv"
"$py" "$tools/compare_step_tables.py" "$work/cst/a" "$work/cst/b" > "$work/cst.log" 2>&1 && fail "compare_step_tables.py: other headers passed"
grep -q "^.steps.csv: the headers differ: columns only in $work/cst/a.steps.csv: energy; only in $work/cst/b.steps.csv: energyX" \
  "$work/cst.log" || { cat "$work/cst.log"; fail "compare_step_tables.py: other headers: message"; }
sed -i '1s/,energyX,/,energy,/; 3s/^\([0-9]*\),[^,]*,/\1,abc,/' "$work/cst/b.steps.csv"
refuses tables_not_number "compare_step_tables.py: error: $work/cst/b.steps.csv: row 2, column t: 'abc' is not a number" \
  "$py" "$tools/compare_step_tables.py" "$work/cst/a" "$work/cst/b"
# ... and nothing compared is not "all equal": tables with a header only, and --common-columns on
# tables that share only time_* columns.
mkdir -p "$work/cst0"
head -1 "$work/membrane.steps.csv" > "$work/cst0/a.steps.csv" && cp "$work/cst0/a.steps.csv" "$work/cst0/b.steps.csv"
refuses tables_no_rows "compare_step_tables.py: error: $work/cst0/a.steps.csv: a header and no rows" \
  "$py" "$tools/compare_step_tables.py" "$work/cst0/a" "$work/cst0/b"
printf 'x,time_output\n1,2\n' > "$work/cst0/c.steps.csv" && printf 'y,time_output\n1,2\n' > "$work/cst0/d.steps.csv"
refuses tables_nothing_common "compare_step_tables.py: error: $work/cst0/c and $work/cst0/d: no column to compare" \
  "$py" "$tools/compare_step_tables.py" "$work/cst0/c" "$work/cst0/d" --common-columns
# --rtol: 4 + 2e-10 against 4 in a column whose largest magnitude is 4 is equal within 1e-10, not within 1e-11.
printf 'step,t,x\n0,0,-4\n1,1,4\n' > "$work/cst0/e.steps.csv" && printf 'step,t,x\n0,0,-4\n1,1,4.0000000002\n' > "$work/cst0/f.steps.csv"
"$py" "$tools/compare_step_tables.py" "$work/cst0/e" "$work/cst0/f" > /dev/null && fail "compare_step_tables.py: 4.0000000002 equal to 4 bit for bit"
"$py" "$tools/compare_step_tables.py" "$work/cst0/e" "$work/cst0/f" --rtol 1e-10 > "$work/rtol.log" &&
  grep -qx ".steps.csv: x: largest difference 5e-11 of the column's largest magnitude 4" "$work/rtol.log" ||
  { cat "$work/rtol.log"; fail "compare_step_tables.py --rtol 1e-10"; }
"$py" "$tools/compare_step_tables.py" "$work/cst0/e" "$work/cst0/f" --rtol 1e-11 > "$work/rtol.log" && fail "compare_step_tables.py --rtol 1e-11 passed"
grep -q "^.steps.csv: x differs first in row 2: 4 against 4.0000000002 (largest difference 5e-11" "$work/rtol.log" ||
  { cat "$work/rtol.log"; fail "compare_step_tables.py --rtol 1e-11: message"; }
refuses tables_bad_rtol "compare_step_tables.py: error: --rtol -1.0: not a number >= 0" \
  "$py" "$tools/compare_step_tables.py" "$work/cst0/e" "$work/cst0/f" --rtol -1
# check_adaptive_meshes.py: --coarser-than compares every written time with BASE2's mesh at that time
# (A: one file, one mesh at t = 0, 1, 2; B: a finer mesh at t = 0, A's at t = 1, 2: coarser in 1 of 3
# steps); a mesh off the dyadic lattice: one line naming the file.
"$py" - "$work" <<'PY' || fail "the synthetic series A, B, odd"
import sys
import netCDF4
import numpy as np
def write(path, cells, times, scale=8):
    xy = sorted({(x + dx * w, y + dy * h) for x, y, w, h in cells for dx in (0, 1) for dy in (0, 1)})
    index = {p: k + 1 for k, p in enumerate(xy)}
    conn = [[index[(x, y)], index[(x + w, y)], index[(x + w, y + h)], index[(x, y + h)]] for x, y, w, h in cells]
    xy = np.array(xy, dtype=float) / scale
    with netCDF4.Dataset(path, "w", format="NETCDF3_64BIT_OFFSET") as d:
        d.createDimension("num_nodes", len(xy))
        d.createDimension("num_el_in_blk1", len(conn))
        d.createDimension("num_nod_per_el1", 4)
        d.createDimension("time_step", None)
        d.createVariable("coordx", "f8", ("num_nodes",))[:] = xy[:, 0]
        d.createVariable("coordy", "f8", ("num_nodes",))[:] = xy[:, 1]
        d.createVariable("connect1", "i4", ("num_el_in_blk1", "num_nod_per_el1"))[:] = np.array(conn)
        v = d.createVariable("time_whole", "f8", ("time_step",))
        for i, t in enumerate(times):
            v[i] = t
coarse = [(0, 0, 4, 4), (4, 0, 4, 4), (0, 4, 4, 4), (4, 4, 4, 4)]
fine = coarse[1:] + [(0, 0, 2, 2), (2, 0, 2, 2), (0, 2, 2, 2), (2, 2, 2, 2)]
work = sys.argv[1]
write(f"{work}/A.e", coarse, [0.0, 1.0, 2.0])
write(f"{work}/B.e", fine, [0.0])
write(f"{work}/B.e-s.0001", coarse, [1.0, 2.0])
write(f"{work}/odd.e", [(0, 0, 3, 10), (3, 0, 7, 10)], [0.0], scale=10)  # cells [0,0.3] and [0.3,1] in x
PY
"$py" "$tools/check_adaptive_meshes.py" "$work/A" --coarser-than "$work/B" --in-every-step > "$work/coarser.log" 2>&1 &&
  { cat "$work/coarser.log"; fail "--coarser-than --in-every-step passed with 1 of 3 steps coarser"; }
grep -q "^1 of 3 steps have cells coarser than in B" "$work/coarser.log" &&
  grep -q "VIOLATION: only 1 of 3 steps have cells coarser than in B (--in-every-step)" "$work/coarser.log" ||
  { cat "$work/coarser.log"; fail "--coarser-than: per written time"; }
refuses meshes_off_lattice "check_adaptive_meshes.py: error: odd.e: cell corners off the lattice" \
  "$py" "$tools/check_adaptive_meshes.py" "$work/odd"
# check_paraview.py (pvpython, where installed): a file that is not netCDF and a series cut short named in
# one line each (not a traceback, not a wrong value).
if command -v pvpython > /dev/null; then
  echo hello > "$work/text.e"
  mkdir -p "$work/cutpv"
  for f in "$work"/membrane.e*; do cp "$f" "$work/cutpv/${f##*/}"; done
  cutpv=$(ls "$work"/cutpv/membrane.e-s.* | sort | tail -1)
  truncate -s -3000 "$cutpv"
  pvpython - "$tools/check_paraview.py" "$work" > "$work/paraview.log" 2>&1 <<'PY' || { cat "$work/paraview.log"; fail "check_paraview.py on bad files"; }
import runpy, sys
script, work = sys.argv[1:]
for args in ([f"{work}/text.e", f"{work}/membrane.steps.csv"], [f"{work}/cutpv/membrane.e", f"{work}/membrane.steps.csv"]):
    sys.argv = [script] + args
    try:
        runpy.run_path(script, run_name="__main__")
        sys.exit(f"{args[0]}: accepted")
    except SystemExit as e:
        if e.code != 1:
            raise
PY
  grep -q "^check_paraview: FAIL: $work/text.e: not readable as an Exodus file" "$work/paraview.log" &&
    grep -q "^check_paraview: FAIL: $cutpv: cut short" "$work/paraview.log" && ! grep -q Traceback "$work/paraview.log" ||
    { cat "$work/paraview.log"; fail "check_paraview.py: messages"; }
else
  echo "skipped: check_paraview.py on bad files (no pvpython)"
fi
# --help of every Python script: exit status 0, the script's whole docstring (not cut after its first
# line) and a help text for every argument.
/usr/bin/python3 - "$tools" <<'PY' || fail "--help of the Python scripts"
import ast, glob, os, re, subprocess, sys
bad = []
for path in sorted(glob.glob(os.path.join(sys.argv[1], "*.py"))):
    name = os.path.basename(path)
    if name in ("tool_errors.py", "exodus_text.py", "step_selection.py"):  # modules, not scripts
        continue
    doc = ast.get_docstring(ast.parse(open(path).read()), clean=False)
    p = subprocess.run(["/usr/bin/python3", path, "--help"], capture_output=True, text=True)
    if p.returncode != 0:
        bad.append(f"{name} --help: exit status {p.returncode}")
    elif " ".join(doc.split()) not in " ".join(p.stdout.split()):
        bad.append(f"{name} --help: not the whole docstring")
    lines = p.stdout.splitlines()
    listing = False  # in argparse's lists of arguments: '  name   help', or '  name' with the help below
    for i, line in enumerate(lines):
        if line in ("positional arguments:", "options:", "optional arguments:"):
            listing = True
        elif not line.startswith(" "):
            listing = False
        elif listing and re.match(r"  \S", line) and not re.match(r"  \S.*\S  +\S", line) \
                and not (i + 1 < len(lines) and re.match(r"    +\S", lines[i + 1])):
            bad.append(f"{name} --help: no help for {line.strip()}")
if bad:
    sys.exit("\n".join(bad))
PY
# The shell scripts: -h/--help prints the header comment and exits 0, an argument a script does not take
# is refused (exit status 2, one line), both before anything is installed, built or run: copies of
# the scripts run with every command they could call (apt-get, dpkg-query, cmake, ctest, mpirun,
# signorini) replaced by stubs that log their call. run-tests.sh and run-membrane.sh pass their
# other arguments on (to ctest, to signorini after the deck).
sandbox=$work/sandbox
mkdir -p "$sandbox/tools" "$sandbox/stubs" "$sandbox/build/src" "$sandbox/inputs"
cp "$src"/tools/*.sh "$sandbox/tools/"
cat > "$sandbox/stubs/stub" <<'SH'
#!/usr/bin/env bash
echo "$(basename "$0") $*" >> "$STUB_LOG"
[ "$(basename "$0")" != dpkg-query ] || printf 'install ok installed'
exit "${STUB_STATUS:-1}"
SH
chmod +x "$sandbox/stubs/stub"
for c in apt-get sudo dpkg-query cmake ctest mpirun mpiexec make; do ln -s stub "$sandbox/stubs/$c"; done
ln -s ../../stubs/stub "$sandbox/build/src/signorini"
stubbed() {  # log command...: runs command with the stubs first on PATH, the stubs' calls in $sandbox/log.calls
  local log=$1
  shift
  rm -f "$sandbox/log.calls"
  PATH="$sandbox/stubs:$PATH" STUB_LOG="$sandbox/log.calls" "$@" > "$work/$log.out" 2> "$work/$log.err"
}
for script in run-membrane-comparison run-bar-comparison run-membrane-finer run-rank-sensitivity run-membrane \
    run-tests build install-deps; do
  for h in --help -h; do
    stubbed "sh-$script$h" bash "$sandbox/tools/$script.sh" "$h"
    status=$?
    [ "$status" = 0 ] || { cat "$work/sh-$script$h.err"; fail "$script.sh $h: exit status $status"; }
    [ ! -e "$sandbox/log.calls" ] || { cat "$sandbox/log.calls"; fail "$script.sh $h ran commands"; }
    grep -q "^Usage: bash tools/$script.sh" "$work/sh-$script$h.out" && [ ! -s "$work/sh-$script$h.err" ] &&
      ! grep -q '^#' "$work/sh-$script$h.out" ||
      { cat "$work/sh-$script$h.out" "$work/sh-$script$h.err"; fail "$script.sh $h: not its header"; }
  done
  case $script in
    run-tests) continue ;;  # every other argument is ctest's
    run-membrane) bad=(--bogus) ;;  # an option signorini does not know
    *) bad=(out) ;;
  esac
  stubbed "sh-$script-bad" bash "$sandbox/tools/$script.sh" "${bad[@]}"
  status=$?
  [ "$status" = 2 ] || { cat "$work/sh-$script-bad.err"; fail "$script.sh ${bad[*]}: exit status $status, expected 2"; }
  [ ! -e "$sandbox/log.calls" ] || { cat "$sandbox/log.calls"; fail "$script.sh ${bad[*]} ran commands"; }
  [ "$(wc -l < "$work/sh-$script-bad.err")" = 1 ] &&
    grep -q "^$script.sh: error: .*${bad[0]}.*(Usage: bash tools/$script.sh" "$work/sh-$script-bad.err" ||
    { cat "$work/sh-$script-bad.err"; fail "$script.sh ${bad[*]}: message"; }
done
stubbed sh-run-membrane-set bash "$sandbox/tools/run-membrane.sh" --set
[ $? = 2 ] && [ ! -e "$sandbox/log.calls" ] || fail "run-membrane.sh --set (no value) not refused"
STUB_STATUS=0 stubbed sh-run-tests-pass bash "$sandbox/tools/run-tests.sh" -R tools -LE long ||
  { cat "$work/sh-run-tests-pass.err"; fail "run-tests.sh -R tools -LE long (stubbed)"; }
grep -qx "ctest --output-on-failure --timeout 900 -R tools -LE long" "$sandbox/log.calls" ||
  { cat "$sandbox/log.calls"; fail "run-tests.sh did not pass its arguments to ctest"; }
STUB_STATUS=0 stubbed sh-run-membrane-pass bash "$sandbox/tools/run-membrane.sh" --set 'Adaptivity/Cycles=1' --check ||
  { cat "$work/sh-run-membrane-pass.err"; fail "run-membrane.sh --set ... --check (stubbed)"; }
grep -qx "signorini --output-dir out inputs/membrane.xml --set Adaptivity/Cycles=1 --check" "$sandbox/log.calls" ||
  { cat "$sandbox/log.calls"; fail "run-membrane.sh did not pass its arguments to signorini"; }
# SIGNORINI_NO_BUILD: 1 uses the existing build (run-rank-sensitivity.sh too, which launches the ranks as the
# build's tests do: here mpiexec, without build/CMakeCache.txt), 0 builds, another value is refused.
SIGNORINI_NO_BUILD=1 STUB_STATUS=0 stubbed sh-ranks-nobuild bash "$sandbox/tools/run-rank-sensitivity.sh"
! grep -q "^cmake\|^apt-get\|^sudo" "$sandbox/log.calls" && grep -q "^mpiexec -n 2 --oversubscribe --allow-run-as-root ./build/src/signorini" \
  "$sandbox/log.calls" || { cat "$sandbox/log.calls"; fail "run-rank-sensitivity.sh with SIGNORINI_NO_BUILD=1"; }
SIGNORINI_NO_BUILD=0 stubbed sh-comparison-build bash "$sandbox/tools/run-membrane-comparison.sh"
grep -q "^dpkg-query\|^apt-get\|^cmake" "$sandbox/log.calls" || { cat "$work/sh-comparison-build.err"; fail "SIGNORINI_NO_BUILD=0 did not build"; }
SIGNORINI_NO_BUILD=yes stubbed sh-comparison-yes bash "$sandbox/tools/run-membrane-comparison.sh"
[ $? = 2 ] && [ ! -e "$sandbox/log.calls" ] && grep -q "error: SIGNORINI_NO_BUILD='yes': 1 .* or 0" "$work/sh-comparison-yes.err" ||
  { cat "$work/sh-comparison-yes.err"; fail "SIGNORINI_NO_BUILD=yes not refused"; }
echo "plots drawn; missing arguments, missing, non-adaptive, cut-short and not comparable runs refused in one line," \
  "nothing written; the deck from an Exodus file reruns the run bit for bit; output that cannot be written," \
  "runs of the wrong kind, --help and the shell scripts' arguments handled"
