#!/usr/bin/env bash
# Adaptivity/Tolerance stops after the cycle whose estimate max_n eta^n is AT or below it: the
# tiny deck's cycle 0 estimate (read from its cycles.csv, written as shortest round-trip text, so
# the deck reads back the same double) as the tolerance ends the run after cycle 0; the next
# double below it does not (cycle 1 runs). '<' for '<=' in the stop rule fails the first case.
# Usage: tolerance_boundary.sh SIGNORINI SOURCE_DIR WORK_DIR
set -uo pipefail
signorini=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
run() {  # basename, [--set ...]
  local base=$1
  shift
  "$signorini" --output-dir "$work" --set "Output/Basename=$base" --set 'Adaptivity/Strategy=uniform' "$@" \
    "$src/tests/driver/decks/good.xml" > "$work/$base.log" 2>&1 || { cat "$work/$base.log"; fail "$base"; }
}
cycles() { /usr/bin/python3 -c 'import csv,sys; print(len(list(csv.DictReader(open(sys.argv[1])))))' "$1"; }
run first --set 'Adaptivity/Cycles=1'
eta=$(/usr/bin/python3 -c 'import csv,sys; print(next(csv.DictReader(open(sys.argv[1])))["eta"])' "$work/first.cycles.csv")
below=$(/usr/bin/python3 -c 'import math,sys; print(repr(math.nextafter(float(sys.argv[1]), 0)))' "$eta")
echo "cycle 0 estimate $eta; the double below it $below"
run at --set 'Adaptivity/Cycles=3' --set "Adaptivity/Tolerance=$eta"
grep -q "cycle 0 ends the run: its estimate is at or below Adaptivity/Tolerance" "$work/at.log" ||
  { cat "$work/at.log"; fail "a tolerance equal to cycle 0's estimate did not end the run after cycle 0"; }
[ "$(cycles "$work/at.cycles.csv")" = 1 ] || fail "at: cycles.csv has more than cycle 0"
run below --set 'Adaptivity/Cycles=2' --set "Adaptivity/Tolerance=$below"
[ "$(cycles "$work/below.cycles.csv")" = 2 ] ||
  { cat "$work/below.log"; fail "a tolerance just below cycle 0's estimate ended the run"; }
echo "Tolerance = eta stops after cycle 0; the next double below does not"
