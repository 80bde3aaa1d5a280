#!/usr/bin/env bash
# Parallel/Reproducible Arithmetic on 3 ranks: the paper's adaptive membrane deck as it is (it
# switches the option on; its own scheme, 3 cycles to t = 0.3, past the first impact) gives the
# same step tables bit for bit on 1 and on 3 ranks (tools/compare_step_tables.py, every column but
# the wall-clock times). Control: with the option switched off the 3-rank run differs from the
# 1-rank run.
# Usage: reproducible_ranks.sh SIGNORINI MPIEXEC SOURCE_DIR WORK_DIR
# MPIEXEC is the launcher "EXECUTABLE|NUMPROC_FLAG|PREFLAGS..." (FindMPI's MPIEXEC_EXECUTABLE,
# MPIEXEC_NUMPROC_FLAG, MPIEXEC_PREFLAGS; see cmake/SignoriniTesting.cmake); a bare executable gets -n.
set -euo pipefail
signorini=$1 src=$3 work=$4
IFS='|' read -r -a launcher <<< "$2"
mpirun_np() {  # the command prefix that runs a program on $1 ranks, into the array mpirun
  mpirun=("${launcher[0]}" "${launcher[1]:--n}" "$1" "${launcher[@]:2}")
}
rm -rf "$work" && mkdir -p "$work"
run() {  # ranks, basename, [--set ...]
  local np=$1 base=$2
  shift 2
  mpirun_np "$np"
  "${mpirun[@]}" "$signorini" --output-dir "$work" \
    --set "Output/Basename=$base" --set 'Adaptivity/Cycles=3' --set 'Time Integration/Final Time=0.3' \
    --set 'Output/Write Exodus=false' "$@" "$src/inputs/membrane.xml" \
    > "$work/$base.log" 2>&1 || { cat "$work/$base.log"; exit 1; }
}
run 1 one
run 3 three
grep -q "reproducible arithmetic" "$work/three.log" || { echo "the deck does not switch on reproducible arithmetic"; exit 1; }
/usr/bin/python3 "$src/tools/compare_step_tables.py" "$work/one" "$work/three"
run 1 one-ordinary --set 'Parallel/Reproducible Arithmetic=false'
run 3 three-ordinary --set 'Parallel/Reproducible Arithmetic=false'
if /usr/bin/python3 "$src/tools/compare_step_tables.py" "$work/one-ordinary" "$work/three-ordinary" > "$work/control.log"; then
  echo "control failed: without reproducible arithmetic 1 and 3 ranks gave the same bits"
  exit 1
fi
grep -q "differs first in row" "$work/control.log" || { cat "$work/control.log"; echo "control failed for another reason"; exit 1; }
echo "control: without the option 1 and 3 ranks differ"
