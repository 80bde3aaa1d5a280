# Sourced by the dynamics test scripts (energy_balance.sh, momentum_balance.sh, probe_fields.sh,
# probe_stress.sh) with their arguments SIGNORINI MPIEXEC SOURCE_DIR WORK_DIR (MPIEXEC is the
# launcher "EXECUTABLE|NUMPROC_FLAG|PREFLAGS..." of cmake/SignoriniTesting.cmake). Sets signorini,
# src, work (emptied), launcher, py (Debian's python3, with step_tables.py importable), decks;
# defines fail MESSAGE and run NAME NP ARGS... (the run's folder is $work/NAME, its output
# $work/NAME.log; a failed run prints the output and fails the test).
set -uo pipefail
signorini=$1 src=$3 work=$4
IFS='|' read -r -a launcher <<< "$2"
py=/usr/bin/python3
export PYTHONPATH="$src/tests/dynamics${PYTHONPATH:+:$PYTHONPATH}"
decks=$src/tests/driver/decks
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
run() {
  local name=$1 np=$2; shift 2
  "${launcher[0]}" "${launcher[1]:--n}" "$np" "${launcher[@]:2}" "$signorini" --output-dir "$work/$name" "$@" > "$work/$name.log" 2>&1 ||
    { cat "$work/$name.log"; fail "run $name"; }
}
