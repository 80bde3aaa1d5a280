#!/usr/bin/env bash
# Ctrl-C ends a run cleanly: SIGINT to the driver (1 rank, also twice at once), SIGHUP, a closed
# stdout (SIGPIPE) or SIGTERM to mpirun (2 ranks, as mpirun passes Ctrl-C on) in the middle of the
# adaptive paper deck leaves no file of the run and no '.part' file; on 1 rank the exit status is
# 128 + the signal. Killed right after SIGTERM, a run has removed its files in the signal's
# handler. A later successful run
# removes the '.part' files that a run killed outright (SIGKILL) left.
# Usage: interrupt.sh SIGNORINI MPIEXEC SOURCE_DIR WORK_DIR
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

# Sends the signals (a comma list, 0.1 s apart) to the background job PID once the command after
# them succeeds; returns the job's exit status (255 if the command never succeeded in 60 s).
signal_when() {  # signals pid command...
  local signals=$1 pid=$2 first=1
  shift 2
  for _ in $(seq 600); do
    "$@" && break
    sleep 0.1
  done
  "$@" || { echo "the condition '$*' never held" >&2; kill -KILL "$pid"; wait "$pid"; return 255; }
  for signal in ${signals//,/ }; do
    [ "$first" = 1 ] || sleep 0.1
    first=0
    kill -"$signal" "$pid"
  done
  wait "$pid"
}
steps_at_least() { [ "$(grep -c '^  step ' "$1")" -ge "$2" ]; }  # log count

interrupt() {  # name signal command...: starts the run, signals it after its second progress line
  local name=$1 signal=$2
  shift 2
  mkdir -p "$work/$name"
  "$@" --output-dir "$work/$name" "$src/inputs/membrane.xml" > "$work/$name.log" 2>&1 &
  signal_when "$signal" $! steps_at_least "$work/$name.log" 2
  echo $?
}

status=$(interrupt one INT "$signorini")
[ "$status" = 130 ] || { cat "$work/one.log"; fail "1 rank: exit status $status after SIGINT, expected 130"; }
grep -q "interrupted by signal 2" "$work/one.log" || fail "1 rank: no 'interrupted' message"
[ -z "$(ls -A "$work/one")" ] || fail "1 rank: files left: $(ls -A "$work/one")"

mpirun_np 2
status=$(interrupt two TERM "${mpirun[@]}" "$signorini")
[ "$status" != 0 ] && [ "$status" != 255 ] || fail "2 ranks: exit status $status after SIGTERM"
grep -q "interrupted by signal 15" "$work/two.log" || { cat "$work/two.log"; fail "2 ranks: no 'interrupted' message"; }
! grep -qiE "segmentation|core dumped|aborted|terminate called|exited on signal|noticed that process" "$work/two.log" ||
  { cat "$work/two.log"; fail "2 ranks: a rank crashed or was killed"; }
[ -z "$(ls -A "$work/two")" ] || fail "2 ranks: files left: $(ls -A "$work/two")"

# The same signal twice at once (timeout(1) signals the process and its group) is one request.
interrupt_twice() {
  mkdir -p "$work/twice"
  # Steps of about half a second (a fine mesh, Exodus output), so both signals arrive within one.
  "$signorini" --output-dir "$work/twice" --set 'Mesh/Refinement Level=8' --set 'Time Integration/Final Time=0.05' \
    "$src/tests/driver/decks/good.xml" > "$work/twice.log" 2>&1 &
  signal_when INT,INT $! steps_at_least "$work/twice.log" 1  # separate deliveries, within a second
  echo $?
}
status=$(interrupt_twice)
[ "$status" = 130 ] || { cat "$work/twice.log"; fail "twice: exit status $status, expected 130"; }
grep -q "interrupted by signal 2" "$work/twice.log" || fail "twice: killed at once instead of stopping cleanly"
[ -z "$(ls -A "$work/twice")" ] || fail "twice: files left: $(ls -A "$work/twice")"

status=$(interrupt hangup HUP "$signorini")
[ "$status" = 129 ] || { cat "$work/hangup.log"; fail "SIGHUP: exit status $status, expected 129"; }
grep -q "interrupted by signal 1 " "$work/hangup.log" || { cat "$work/hangup.log"; fail "SIGHUP: killed instead of stopping cleanly"; }
[ -z "$(ls -A "$work/hangup")" ] || fail "SIGHUP: files left: $(ls -A "$work/hangup")"

# stdout closed by the reader (SIGPIPE at the next progress line): the run stops cleanly.
mkdir -p "$work/pipe"
"$signorini" --output-dir "$work/pipe" "$src/inputs/membrane.xml" 2> "$work/pipe.log" | head -2 > /dev/null
status=${PIPESTATUS[0]}
[ "$status" = 141 ] || { cat "$work/pipe.log"; fail "SIGPIPE: exit status $status, expected 141"; }
[ -z "$(ls -A "$work/pipe")" ] || fail "SIGPIPE: files left: $(ls -A "$work/pipe")"


# A --check of a batch stops at the next deck (it used to check them all and exit 0).
deck="$src/tests/driver/decks/good.xml"
"$signorini" --check --output-dir "$work/check" --set 'Mesh/Refinement Level=8' "$deck" "$deck" "$deck" "$deck" \
  > "$work/check.log" 2>&1 &
signal_when INT $! grep -q '^signorini: checking' "$work/check.log"
status=$?
[ "$status" = 130 ] || { cat "$work/check.log"; fail "--check: exit status $status after SIGINT, expected 130"; }
grep -q "interrupted by signal 2 (Interrupt) before .*good[.]xml, which did not run" "$work/check.log" ||
  { cat "$work/check.log"; fail "--check: no message naming the deck that did not run"; }
grep -q "batch interrupted: 1 of 4 deck(s) checked, 0 failed, 3 stopped or not checked" "$work/check.log" ||
  { cat "$work/check.log"; fail "--check: no summary of the interrupted batch"; }

# A batch interrupted in its second deck keeps the first deck's results and says what ran.
mkdir -p "$work/batch"
"$signorini" --output-dir "$work/batch" "$deck" "$src/inputs/membrane.xml" > "$work/batch.log" 2>&1 &
membrane_steps_begun() { grep -A2 '^signorini: running .*membrane[.]xml' "$work/batch.log" | grep -q '^  step '; }
signal_when INT $! membrane_steps_begun
status=$?
[ "$status" = 130 ] || { cat "$work/batch.log"; fail "batch: exit status $status after SIGINT, expected 130"; }
grep -q "batch interrupted: 1 of 2 deck(s) done, 0 failed, 1 stopped or not run" "$work/batch.log" ||
  { cat "$work/batch.log"; fail "batch: no summary of the interrupted batch"; }
[ "$(ls "$work/batch" | tr '\n' ' ')" = "good.e good.steps.csv " ] ||
  fail "batch: expected the first deck's files only, found: $(ls -A "$work/batch")"

# Killed right after the signal, within a step (mpirun kills its ranks about a second after it passes a
# Ctrl-C on as SIGTERM): the handler itself removes the run's '.part' files before it prints its
# notice; only the lock stays (and the folders that hold it: removed, it would let a second run in
# while this one still writes), and the next run takes it over. Steps of about half a second (a
# fine mesh, Exodus output); SIGKILL as soon as the notice is out. (Before, the '.part' files
# stayed until the next step's check.)
mkdir -p "$work/soon"
"$signorini" --output-dir "$work/soon/made/deeper" --set 'Mesh/Refinement Level=8' \
  --set 'Time Integration/Final Time=0.05' --set 'Output/Progress Interval=1' "$deck" > "$work/soon.log" 2>&1 &
pid=$!
notice_out() { grep -q 'stopping at the next time step' "$work/soon.log"; }
signal_when TERM $pid steps_at_least "$work/soon.log" 1 > /dev/null &
waiter=$!
for _ in $(seq 6000); do notice_out && break; sleep 0.01; done
notice_out || { kill -KILL $pid; cat "$work/soon.log"; fail "killed soon after SIGTERM: no notice in 60 s"; }
kill -KILL $pid
wait $waiter
left=$(cd "$work/soon" && find . -type f | tr '\n' ' ')
[ "$left" = "./made/deeper/good.lock " ] || fail "killed soon after SIGTERM: files left: $left (only the lock may stay)"
"$signorini" --output-dir "$work/soon/made/deeper" --set 'Time Integration/Final Time=0.01' "$deck" > "$work/soon-rerun.log" 2>&1 ||
  { cat "$work/soon-rerun.log"; fail "killed soon after SIGTERM: the next run did not take the lock over"; }
[ ! -e "$work/soon/made/deeper/good.lock" ] || fail "killed soon after SIGTERM: the next run left the lock"

status=$(interrupt killed KILL "$signorini")
ls "$work/killed" | grep -q '[.]part$' || fail "SIGKILL left no '.part' file (the control)"
"$signorini" --output-dir "$work/killed" --set 'Adaptivity/Cycles=1' --set 'Time Integration/Final Time=0.01' \
  "$src/inputs/membrane.xml" > "$work/rerun.log" 2>&1 || { cat "$work/rerun.log"; fail "the rerun failed"; }
! ls "$work/killed" | grep '[.]part$' || fail "the rerun kept the killed run's '.part' files"
echo "interrupted runs leave nothing (also when killed right after the signal); a rerun removes a killed run's '.part' files"
