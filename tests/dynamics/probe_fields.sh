#!/usr/bin/env bash
# Output/Probe Fields: the probes of v and a are the run's velocity and acceleration at the probe.
#  - Newmark's relations (3.1)-(3.2) hold at every probe in every step (check_probe_rates.py), with
#    Alpha = 0.6, Beta = 0.4 so that each term counts, through contact, for the membrane (1 rank) and
#    for an elastic block on 2 ranks;
#  - the block flies freely at 5 m/s until its first contact: v = (5, 0) and a = 0 at both probes, and
#    the step table's kinetic_energy is m |v|^2 / 2 = 62.5 J/m (0.1 m x 0.05 m at 1000 kg/m^3), all of
#    the energy (a rigid translation strains nothing);
#  - the other columns (time_* aside) are bit for bit those of a run with the default "u";
#  - the Exodus files carry the new columns as global variables;
#  - controls: the checker fails on a table whose v is one step late, with a NaN acceleration, with a
#    velocity column without its acceleration, and on a table without v.
# Usage: probe_fields.sh SIGNORINI MPIEXEC SOURCE_DIR WORK_DIR
# (MPIEXEC: the launcher of cmake/SignoriniTesting.cmake; run_helpers.sh reads the arguments.)
source "$(dirname "$0")/run_helpers.sh" "$@"
check="$py $src/tests/dynamics/check_probe_rates.py"
newmark=(--set "Time Integration/Alpha=0.6" --set "Time Integration/Beta=0.4")
membrane=(--set "Time Integration/Final Time=1.2" --set "Output/Probes/middle=0.5, 0.5"
          --set "Output/Probes/edge=1, 0.25" "${newmark[@]}")
run membrane 1 "${membrane[@]}" --set "Output/Probe Fields=u, v, a" "$decks/good.xml"
run membrane_u 1 "${membrane[@]}" "$decks/good.xml"
block=(--set "Adaptivity/Strategy=none" --set "Output/Probes/face=0.1, 0.025" --set "Output/Probes/inside=0.03, 0.01"
       --set "Output/Probe Fields=u, v, a" "${newmark[@]}")
run block 2 "${block[@]}" "$decks/block-into-wall.xml"

$check "$work/membrane/good.steps.csv" 0.6 0.4 0.0025 || fail "membrane: Newmark relations at the probes"
$check "$work/block/block-into-wall.steps.csv" 0.6 0.4 2e-6 || fail "block: Newmark relations at the probes"

$py - "$work" <<'PY' || exit 1
import glob, sys
import netCDF4
from step_tables import fail, table
work = sys.argv[1]
full, plain = table(f"{work}/membrane/good.steps.csv"), table(f"{work}/membrane_u/good.steps.csv")
if not any(int(r["active"]) > 0 for r in full):
    fail("the membrane run has no contact: the relations were not checked through contact")
columns = [c for c in plain[0] if not c.startswith("time_")]
extra = [c for c in full[0] if c not in plain[0]]
if extra != ["probe:middle:v", "probe:middle:a", "probe:edge:v", "probe:edge:a"]:
    fail(f"the columns Probe Fields adds: {extra}")
if len(full) != len(plain):
    fail(f"{len(full)} steps with v and a probed, {len(plain)} without")
for a, b in zip(full, plain):
    for c in columns:
        if a[c] != b[c]:
            fail(f"step {a['step']}: {c} is {a[c]} with v and a probed, {b[c]} without")
block = table(f"{work}/block/block-into-wall.steps.csv")
first = next(n for n, r in enumerate(block) if int(r["active"]) > 0)
if first < 10:
    fail(f"the block touches the wall in step {first}: too early for the free-flight check")
for r in block[:first]:
    for p in ("face", "inside"):
        values = [float(r[f"probe:{p}:{s}"]) for s in ("v:x", "v:y", "a:x", "a:y")]
        if not (abs(values[0] - 5) <= 1e-12 and max(abs(x) for x in values[1:]) <= 1e-6):
            fail(f"block step {r['step']}: probe {p} (v, a) = {values} in free flight at (5, 0) m/s")
    kinetic, energy = float(r["kinetic_energy"]), float(r["energy"])
    if not (abs(kinetic - 62.5) <= 1e-12 * 62.5 and abs(energy - kinetic) <= 1e-9 * kinetic):
        fail(f"block step {r['step']}: kinetic_energy {kinetic!r}, energy {energy!r} in free flight: "
             "both should be m |v|^2 / 2 = 62.5")
names = set()
for f in glob.glob(f"{work}/block/block-into-wall.e*"):
    with netCDF4.Dataset(f) as d:
        names |= {bytes(row).rstrip(b"\0").decode() for row in d.variables["name_glo_var"][:].data}
wanted = {f"probe:{p}:{s}" for p in ("face", "inside") for s in ("x", "y", "v:x", "v:y", "a:x", "a:y")}
if not wanted <= names:
    fail(f"Exodus global variables lack {sorted(wanted - names)}")
print(f"membrane: contact in {sum(int(r['active']) > 0 for r in full)} steps, other columns bit for bit; "
      f"block: free flight to step {first} (kinetic energy {block[first - 1]['kinetic_energy']}), Exodus globals present")
PY

# Controls: v one step late, a NaN acceleration, a v without its a, and a table without v fail the checker.
$py - "$work" <<'PY'
import csv, sys
work = sys.argv[1]
with open(f"{work}/membrane/good.steps.csv", newline="") as f:
    rows = list(csv.DictReader(f))
def write(name, table, columns):
    with open(f"{work}/{name}.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        w.writeheader()
        w.writerows(table)
late = [dict(r) for r in rows]
for n in range(len(rows) - 1, 0, -1):
    late[n]["probe:middle:v"] = rows[n - 1]["probe:middle:v"]
write("late", late, list(rows[0]))
nan = [dict(r) for r in rows]
nan[7]["probe:edge:a"] = "nan"
write("nan", nan, list(rows[0]))
write("no_a", rows, [c for c in rows[0] if c != "probe:edge:a"])
PY
control() {  # control NAME MESSAGE: the checker fails on $work/NAME.csv with MESSAGE
  $check "$work/$1.csv" 0.6 0.4 0.0025 > "$work/$1.log" && fail "control $1: the checker passed"
  grep -qF "$2" "$work/$1.log" || { cat "$work/$1.log"; fail "control $1: not '$2'"; }
}
control late "probe:middle:v step 1: the Newmark relation"
control nan "probe:edge:a step 7 is nan"
control no_a "probe:edge:v without probe:edge:a"
cp "$work/membrane_u/good.steps.csv" "$work/plain.csv"
control plain "no probe with the columns of u, v and a"
echo "PASS"
