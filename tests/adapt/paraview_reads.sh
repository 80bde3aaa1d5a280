#!/usr/bin/env bash
# ParaView itself reads the results as the README says (tools/check_paraview.py under pvpython,
# headless): an adaptive membrane run (2 cycles to t = 0.1, meshes changing between outputs, the
# side set with contact) and the adaptive bar (2 cycles, vector fields, a new mesh in almost every
# file, its probes of u, v, a and the stress and its other global variables, which the reader must not
# take for clashing vectors) through ParaView's default reader, the bar also through the old Exodus reader;
# the segments' side sets with names the default reader would change or clash, one empty on some meshes.
# Usage: paraview_reads.sh PVPYTHON SIGNORINI SOURCE_DIR WORK_DIR
set -euo pipefail
pvpython=$1 signorini=$2 src=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
"$signorini" --output-dir "$work" --set Adaptivity/Cycles=2 --set "Time Integration/Final Time=0.1" \
  "$src/inputs/membrane.xml" > "$work/membrane.log" 2>&1 || { cat "$work/membrane.log"; exit 1; }
"$signorini" --output-dir "$work" --set Adaptivity/Cycles=2 --set "Time Integration/Final Time=1e-3" \
  --set "Output/Probe Fields=u, v, a, sigma" "$src/inputs/bar.xml" > "$work/bar.log" 2>&1 || { cat "$work/bar.log"; exit 1; }
"$pvpython" "$src/tools/check_paraview.py" "$work/membrane.e" "$work/membrane.steps.csv"
"$pvpython" "$src/tools/check_paraview.py" "$work/bar.e" "$work/bar.steps.csv"
"$pvpython" "$src/tools/check_paraview.py" --reader legacy "$work/bar.e" "$work/bar.steps.csv"
# The segments' side sets as both readers show them: a name with capitals and a blank, one that only
# the reader's lower case would make "contact", and one empty on some meshes of the series.
"$signorini" --output-dir "$work/sets" --set Adaptivity/Cycles=3 --set "Time Integration/Final Time=1e-4" \
  --set "Output/Exodus Interval=1" --set "Mesh/Boundary Segments/corner=right, y >= 0.049" \
  --set "Mesh/Boundary Segments/Contact=bottom, x <= 0.15" --set "Mesh/Boundary Segments/Free Top=top, x <= 0.1" \
  "$src/inputs/bar.xml" > "$work/sets.log" 2>&1 || { cat "$work/sets.log"; exit 1; }
"$pvpython" "$src/tools/check_paraview.py" "$work/sets/bar.e" "$work/sets/bar.steps.csv"
"$pvpython" "$src/tools/check_paraview.py" --reader legacy "$work/sets/bar.e" "$work/sets/bar.steps.csv"
