#!/usr/bin/env bash
# Driver cases that need a shell: a deck on stdin under mpirun (rank 0 reads it for every rank;
# the other ranks' stdin is empty, and they used to fail alone while rank 0 waited forever), a deck
# from a process substitution (/dev/fd/N needs Output/Basename), a batch whose second deck reaches the
# first one's output base through a symbolic link, a deck on stdin with a relative Mesh/File, the
# lock of an output base (one run at a time per base), the command line's --opt=value forms, and
# --print-parameters DECK (a complete deck that reproduces the run).
# Usage: shell_cases.sh SIGNORINI MPIEXEC SOURCE_DIR WORK_DIR
# MPIEXEC is the launcher "EXECUTABLE|NUMPROC_FLAG|PREFLAGS..." (FindMPI's MPIEXEC_EXECUTABLE,
# MPIEXEC_NUMPROC_FLAG, MPIEXEC_PREFLAGS; see cmake/SignoriniTesting.cmake); a bare executable gets -n.
set -uo pipefail
signorini=$1 src=$3 work=$4
IFS='|' read -r -a launcher <<< "$2"
mpirun_np() {  # the command prefix that runs a program on $1 ranks, into the array mpirun
  mpirun=("${launcher[0]}" "${launcher[1]:--n}" "$1" "${launcher[@]:2}")
}
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
good="$src/tests/driver/decks/good.xml"

mpirun_np 2
timeout 20 "${mpirun[@]}" "$signorini" --check --output-dir "$work/stdin" \
  /dev/stdin < "$good" > "$work/stdin.log" 2>&1
status=$?
[ "$status" = 0 ] || { cat "$work/stdin.log"; fail "a deck on stdin on 2 ranks: exit status $status"; }
grep -q "/dev/stdin is valid" "$work/stdin.log" || fail "a deck on stdin: not checked"

# A process substitution passes the deck as /dev/fd/N: its number is no basename for the outputs.
"$signorini" --check --output-dir "$work/fd" <(cat "$good") > "$work/fd.log" 2>&1
status=$?
[ "$status" = 1 ] || { cat "$work/fd.log"; fail "a deck from <(...) without Output/Basename: exit status $status"; }
grep -q "/dev/fd/[0-9]*: a deck read through a file descriptor .* set Output/Basename" "$work/fd.log" ||
  { cat "$work/fd.log"; fail "a deck from <(...): no message asking for Output/Basename"; }
"$signorini" --check --output-dir "$work/fd" --set Output/Basename=run <(cat "$good") > "$work/fd-named.log" 2>&1 ||
  { cat "$work/fd-named.log"; fail "a deck from <(...) with Output/Basename was refused"; }
grep -q "output: .*/fd/run[.][*]" "$work/fd-named.log" || { cat "$work/fd-named.log"; fail "a deck from <(...): not named run"; }

# Two decks whose Output/Directory differ only by a link, with the same Output/Basename.
mkdir -p "$work/real" && ln -s real "$work/link"
for d in real link; do
  sed "s|<Parameter name=\"Write Exodus\" type=\"bool\" value=\"true\"/>|&\
    <Parameter name=\"Directory\" type=\"string\" value=\"$work/$d\"/>\
    <Parameter name=\"Basename\" type=\"string\" value=\"same\"/>|" "$good" > "$work/deck-$d.xml"
done
"$signorini" "$work/deck-real.xml" "$work/deck-link.xml" > "$work/batch.log" 2>&1
status=$?
[ "$status" = 1 ] || { cat "$work/batch.log"; fail "a batch writing one output base twice (through a link): exit status $status"; }
grep -q "deck-link[.]xml: writes to the output base '.*/link/same' of the batch's deck .*deck-real[.]xml" "$work/batch.log" ||
  { cat "$work/batch.log"; fail "no message naming both decks"; }
# A deck on stdin takes a relative Mesh/File from the working directory (its "folder" is /dev).
(cd "$src/tests/driver/decks" && "$signorini" --check --output-dir "$work/stdin-exodus" /dev/stdin < good-exodus.xml) \
  > "$work/stdin-exodus.log" 2>&1 || { cat "$work/stdin-exodus.log"; fail "a deck on stdin with a relative Mesh/File"; }

# One run at a time per output base: a second run under the base of a run in progress (here the
# lock held by this shell through flock(1)) fails at its start, writes nothing and leaves the lock alone; a lock file
# that a killed run left is taken over, and a run removes its lock file at its end.
mkdir -p "$work/locked"
exec 9> "$work/locked/good.lock"
flock -n 9 || fail "flock(1) could not lock $work/locked/good.lock"
"$signorini" --output-dir "$work/locked" "$good" 9>&- > "$work/locked.log" 2>&1
status=$?
exec 9>&-  # the holder ends: its lock file stays, as a killed run's would
[ "$status" = 1 ] || { cat "$work/locked.log"; fail "a run under a locked output base: exit status $status"; }
grep -q "another run is writing its results under the output base '.*/locked/good' (it holds '.*/locked/good[.]lock')" \
  "$work/locked.log" || { cat "$work/locked.log"; fail "a run under a locked output base: no message naming the lock"; }
[ "$(ls "$work/locked")" = "good.lock" ] || fail "a run under a locked output base wrote: $(ls "$work/locked")"
"$signorini" --output-dir "$work/locked" "$good" > "$work/unlocked.log" 2>&1 ||
  { cat "$work/unlocked.log"; fail "a run after the lock's holder ended (a stale lock file) failed"; }
[ ! -e "$work/locked/good.lock" ] || fail "a run left its lock file"
[ -e "$work/locked/good.steps.csv" ] || fail "the run after the stale lock wrote no step table"

# Command-line forms: --output-dir=DIR and --set=SPEC; '-' and no deck are usage errors that say so.
"$signorini" --check --output-dir="$work/equals" --set='Time Integration/Final Time=0.005' "$good" \
  > "$work/equals.log" 2>&1 || { cat "$work/equals.log"; fail "--output-dir=DIR --set=SPEC refused"; }
grep -q "output: .*/equals/good[.][*]" "$work/equals.log" || { cat "$work/equals.log"; fail "--output-dir=DIR not used"; }
grep -q "2 steps" "$work/equals.log" || { cat "$work/equals.log"; fail "--set=SPEC not used"; }
"$signorini" - > "$work/dash.log" 2>&1
status=$?
[ "$status" = 2 ] && grep -q "'-' is not a deck name: .* /dev/stdin" "$work/dash.log" ||
  { cat "$work/dash.log"; fail "'-' as the deck: exit status $status"; }
"$signorini" --check > "$work/none.log" 2>&1
status=$?
[ "$status" = 2 ] && grep -q "no deck given" "$work/none.log" || { cat "$work/none.log"; fail "no deck: exit status $status"; }
# --print-parameters DECK: standard output is the deck as the run uses it, a complete deck (every
# default, --set applied, the relative Mesh/File made absolute), which run from another folder
# under another name gives the same step tables; nothing is written. With two decks: a usage error.
sets=(--set 'Adaptivity/Strategy=uniform' --set 'Adaptivity/Cycles=2' --set 'Problem/Density=1.5')
exodus="$src/tests/driver/decks/good-exodus.xml"
mkdir -p "$work/printed"
"$signorini" --print-parameters --output-dir "$work/printed/none" "${sets[@]}" "$exodus" \
  > "$work/printed/complete.xml" 2> "$work/printed/print.log" || { cat "$work/printed/print.log"; fail "--print-parameters DECK"; }
[ ! -e "$work/printed/none" ] || fail "--print-parameters DECK wrote $(ls "$work/printed/none")"
head -n 1 "$work/printed/complete.xml" | grep -qx '<ParameterList name="good-exodus">' &&
  tail -n 1 "$work/printed/complete.xml" | grep -qx '</ParameterList>' ||
  { head -n 3 "$work/printed/complete.xml"; fail "--print-parameters DECK: standard output is not the deck's XML alone"; }
grep -q '<Parameter name="Density" type="double" value="1.5"/>' "$work/printed/complete.xml" &&
  grep -q '<Parameter name="Beta" type="double" value="0.5"/>' "$work/printed/complete.xml" &&
  grep -q "<Parameter name=\"File\" type=\"string\" value=\"$src/inputs/meshes/unit-square-4x4.exo\"/>" \
    "$work/printed/complete.xml" || fail "--print-parameters DECK: --set, a default or the absolute Mesh/File missing"
"$signorini" --output-dir "$work/printed" "${sets[@]}" "$exodus" > "$work/printed/original.log" 2>&1 ||
  { cat "$work/printed/original.log"; fail "the deck with --set did not run"; }
(cd / && "$signorini" --output-dir "$work/printed" "$work/printed/complete.xml") > "$work/printed/complete.log" 2>&1 ||
  { cat "$work/printed/complete.log"; fail "the printed deck did not run"; }
/usr/bin/python3 "$src/tools/compare_step_tables.py" "$work/printed/good-exodus" "$work/printed/complete" \
  > "$work/printed/compare.log" 2>&1 || { cat "$work/printed/compare.log"; fail "the printed deck's step tables differ"; }
"$signorini" --print-parameters "$good" "$exodus" > "$work/two.log" 2>&1
status=$?
[ "$status" = 2 ] && grep -q "print-parameters prints one deck" "$work/two.log" ||
  { cat "$work/two.log"; fail "--print-parameters with two decks: exit status $status"; }
# "--" ends the options: a deck whose name starts with '-' follows it.
mkdir -p "$work/dash" && cp "$good" "$work/dash/-x.xml"
(cd "$work/dash" && "$signorini" --check -- -x.xml) > "$work/dash-deck.log" 2>&1 &&
  grep -q "^signorini: -x[.]xml is valid" "$work/dash-deck.log" || { cat "$work/dash-deck.log"; fail "a deck after --"; }
# After "--" not even --help, --version or --set=... is an option: each is a deck, here a missing file.
for name in --help --version --set=a.xml; do
  (cd "$work/dash" && "$signorini" --check -- "$name") > "$work/dash-option.log" 2>&1
  status=$?
  [ "$status" = 1 ] && grep -qF -- "$name: cannot open the deck" "$work/dash-option.log" ||
    { cat "$work/dash-option.log"; fail "$name after --: exit status $status, not read as a deck"; }
done
echo "a deck on stdin runs on 2 ranks and takes Mesh/File from the working directory; a deck from <(...) needs"
echo "Output/Basename; one output base through a link is refused; a locked output base is refused, a stale lock"
echo "taken over; --output-dir=DIR and --set=SPEC work; '-' and no deck are usage errors; --print-parameters DECK"
echo "prints a complete deck that reproduces the run; decks follow -- (even --help, --version, --set=...)"
