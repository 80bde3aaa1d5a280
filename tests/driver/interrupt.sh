#!/usr/bin/env bash
# Ctrl-C ends a run cleanly: SIGINT to the driver (1 rank) or SIGTERM to mpirun (2 ranks, as
# mpirun passes Ctrl-C on) in the middle of the adaptive paper deck leaves no file of the run and
# no '.part' file; on 1 rank the exit status is 130 (128 + SIGINT). A later successful run
# removes the '.part' files that a run killed outright (SIGKILL) left.
# Usage: interrupt.sh SIGNORINI MPIEXEC SOURCE_DIR WORK_DIR
set -uo pipefail
signorini=$1 mpiexec=$2 src=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

interrupt() {  # name signal command...: starts the run, signals it after its second progress line
  local name=$1 signal=$2
  shift 2
  mkdir -p "$work/$name"
  "$@" --output-dir "$work/$name" "$src/inputs/membrane.xml" > "$work/$name.log" 2>&1 &
  local pid=$!
  for _ in $(seq 600); do
    [ "$(grep -c '^  step ' "$work/$name.log")" -ge 2 ] && break
    sleep 0.1
  done
  kill -"$signal" "$pid"
  wait "$pid"
  echo $?
}

status=$(interrupt one INT "$signorini")
[ "$status" = 130 ] || { cat "$work/one.log"; fail "1 rank: exit status $status after SIGINT, expected 130"; }
grep -q "interrupted by signal 2" "$work/one.log" || fail "1 rank: no 'interrupted' message"
[ -z "$(ls -A "$work/one")" ] || fail "1 rank: files left: $(ls -A "$work/one")"

status=$(interrupt two TERM "$mpiexec" --allow-run-as-root --oversubscribe -np 2 "$signorini")
[ "$status" != 0 ] || fail "2 ranks: exit status 0 after SIGTERM"
[ -z "$(ls -A "$work/two")" ] || fail "2 ranks: files left: $(ls -A "$work/two")"

status=$(interrupt killed KILL "$signorini")
ls "$work/killed" | grep -q '[.]part$' || fail "SIGKILL left no '.part' file (the control)"
"$signorini" --output-dir "$work/killed" --set 'Adaptivity/Cycles=1' --set 'Time Integration/Final Time=0.01' \
  "$src/inputs/membrane.xml" > "$work/rerun.log" 2>&1 || { cat "$work/rerun.log"; fail "the rerun failed"; }
! ls "$work/killed" | grep '[.]part$' || fail "the rerun kept the killed run's '.part' files"
echo "interrupted runs leave nothing; a rerun removes a killed run's '.part' files"
