#!/usr/bin/env bash
# Paper Example 6.1: the adaptive run with a 10% fixed fraction (inputs/membrane-fraction10.xml) must reach
# the estimate of the finest uniform cycle (inputs/membrane-uniform.xml) with at least 10 times fewer total
# unknowns (the paper: "nearly a factor of 10"). The two runs go side by side (about 20 s on 2 cores).
# Usage: adaptivity_factor.sh SIGNORINI SOURCE_DIR WORK_DIR
set -euo pipefail
signorini=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
"$signorini" --output-dir "$work" --set 'Output/Exodus Interval=400' "$src/inputs/membrane-uniform.xml" \
  > "$work/uniform.log" 2>&1 &
uniform=$!
"$signorini" --output-dir "$work" --set 'Output/Exodus Interval=400' "$src/inputs/membrane-fraction10.xml" \
  > "$work/adaptive.log" 2>&1 || { cat "$work/adaptive.log"; exit 1; }
wait $uniform || { cat "$work/uniform.log"; exit 1; }
/usr/bin/python3 "$src/tools/compare_runs.py" "$work/membrane-fraction10" "$work/membrane-uniform" --require-factor 10
