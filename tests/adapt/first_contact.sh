#!/usr/bin/env bash
# The contact zone is resolved before the first contact (paper, Section 7): the last cycle of the
# paper's adaptive membrane run (fixed fraction 50%) and of the 10% variant finds the first contact
# in the step the obstacle-free exact solution predicts, with the contact zone at the finest level
# of the meshes of that step and the one before; the uniform initial mesh (cycle 0) finds it later
# (tools/check_first_contact.py). Both decks to t = 0.15, every step written, side by side. Control:
# after two cycles (meshes no finer than h = 1/32) the check must fail.
# Usage: first_contact.sh SIGNORINI SOURCE_DIR WORK_DIR
set -euo pipefail
signorini=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
run() {  # deck, then --set arguments
  local deck=$1
  shift
  "$signorini" --output-dir "$work" --set 'Time Integration/Final Time=0.15' --set 'Output/Exodus Interval=1' \
    "$@" "$src/inputs/$deck.xml" > "$work/$deck.log" 2>&1 || { cat "$work/$deck.log"; exit 1; }
}
run membrane-fraction10 &
other=$!
run membrane
wait $other
/usr/bin/python3 "$src/tools/check_first_contact.py" "$work/membrane"
/usr/bin/python3 "$src/tools/check_first_contact.py" "$work/membrane-fraction10"
run membrane --set Output/Basename=two-cycles --set Adaptivity/Cycles=2
if /usr/bin/python3 "$src/tools/check_first_contact.py" "$work/two-cycles" > "$work/control.log"; then
  echo "control failed: the check passed after two cycles"
  cat "$work/control.log"
  exit 1
fi
grep -q "FAILED: the last cycle finds the first contact in step 23, not 21" "$work/control.log" ||
  { cat "$work/control.log"; echo "control failed for another reason"; exit 1; }
