#!/usr/bin/env bash
# Driver cases that need a shell: a deck on stdin under mpirun (rank 0 reads it for every rank;
# the other ranks' stdin is empty, and they used to fail alone while rank 0 waited forever), a deck
# from a process substitution (/dev/fd/N needs Output/Basename), and a batch whose second deck reaches the first one's output base through a symbolic link.
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
echo "a deck on stdin runs on 2 ranks; a deck from <(...) needs Output/Basename; one output base through a link is refused"
