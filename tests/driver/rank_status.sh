#!/bin/sh
# rank_status.sh STATUS_DIR COMMAND [ARGS...]
# Runs COMMAND on one MPI rank and records its exit status in STATUS_DIR/rank-<rank>.status.
# Always exits 0 itself, so that mpirun does not abort the other ranks while they are still
# running: run_bad_deck.cmake then checks the status of EVERY rank (a rank that was killed, hung
# or crashed leaves no status file or a status other than the expected one).
status_dir=$1
shift
"$@"
status=$?
rank=${OMPI_COMM_WORLD_RANK:-${PMIX_RANK:-${PMI_RANK:-0}}}
echo "$status" > "$status_dir/rank-$rank.status"
exit 0
