#!/usr/bin/env bash
# --check names the step table's columns: for a run on one mesh (with reactions, probes of u, v and
# the stress, the work and momentum columns) and an adaptive run (its last cycle's table and an
# earlier cycle's: the estimate's and the transfer's columns), the list --check prints is the header
# of the table the run then writes, column for column.
# Usage: check_plan_columns.sh SIGNORINI SOURCE_DIR WORK_DIR
set -uo pipefail
signorini=$1 src=$2 work=$3
decks=$src/tests/driver/decks
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
compare() {  # compare NAME TABLE... ARGS: --check's list against each TABLE's header
  local name=$1; shift
  local tables=()
  while [ "$1" != "--" ]; do tables+=("$1"); shift; done
  shift
  "$signorini" --check --output-dir "$work/$name" "$@" > "$work/$name.check" 2>&1 || { cat "$work/$name.check"; fail "$name: --check"; }
  "$signorini" --output-dir "$work/$name" "$@" > "$work/$name.log" 2>&1 || { cat "$work/$name.log"; fail "$name: the run"; }
  local listed
  listed=$(sed -n 's/^ *step table .*\.steps\.csv, [0-9]* columns: //p' "$work/$name.check" | sed 's/, /,/g')
  [ -n "$listed" ] || { cat "$work/$name.check"; fail "$name: --check lists no columns"; }
  local count
  count=$(sed -n 's/^ *step table .*\.steps\.csv, \([0-9]*\) columns: .*/\1/p' "$work/$name.check")
  [ "$count" = "$(echo "$listed" | tr ',' '\n' | wc -l)" ] || fail "$name: --check says $count columns and lists others"
  for table in "${tables[@]}"; do
    [ "$(head -1 "$work/$name/$table")" = "$listed" ] ||
      fail "$name: --check lists '$listed', $table has '$(head -1 "$work/$name/$table")'"
  done
  echo "$name: $count columns as listed"
}
compare block block-into-wall.steps.csv -- --set "Adaptivity/Strategy=none" --set "Mesh/Boundary Segments/left=left" \
  --set "Problem/Dirichlet Y Segments=left" \
  --set "Output/Probes/p=0.05, 0.025" --set "Output/Probe Fields=sigma, v" "$decks/block-into-wall.xml"
compare adaptive good.steps.csv good.cycle0.steps.csv -- --set "Adaptivity/Strategy=fixed fraction" \
  --set "Adaptivity/Cycles=2" --set "Output/Probes/middle=0.5, 0.5" "$decks/good.xml"
echo "PASS"
