#!/usr/bin/env bash
# Paper Example 6.2 reproduced: the adaptive bar (inputs/bar.xml, the paper's 50% fixed fraction, 5 cycles),
# the same with a 20% fixed fraction and 7 cycles, the uniform comparison (inputs/bar-uniform.xml), the plots
# (out/plots-bar/*.png, copied to docs/figures/; the meshes of Fig. 6.4 at steps chosen from the contact
# intervals), the contact intervals, the correlations of refined zone and contact zone and the factors in
# unknowns and wall time. About 8 minutes on 2 cores (the adaptive runs and the uniform run go side by side).
# Usage: bash tools/run-bar-comparison.sh   (SIGNORINI_NO_BUILD=1: use the existing build/src/signorini)
# Takes no arguments (-h, --help: this text).
set -euo pipefail
source "$(dirname "$0")/script_args.sh"
no_arguments "$@"
cd "$(dirname "$0")/.."
build_first
mkdir -p out
./build/src/signorini --output-dir out inputs/bar-uniform.xml > out/bar-uniform.log 2>&1 &
uniform=$!
# If an adaptive run fails, the script stops: the uniform run is stopped with it, not left running.
trap '[ -z "$uniform" ] || kill "$uniform" 2> /dev/null || true' EXIT
progress() { grep -E "^signorini: (cycle|.* done)|error"; }  # the cycles and the summary, not the 'wrote' lines
./build/src/signorini --output-dir out inputs/bar.xml | progress
./build/src/signorini --output-dir out --set 'Output/Basename=bar-fraction20' --set 'Adaptivity/Refinement Fraction=0.2' \
  --set 'Adaptivity/Cycles=7' --set 'Output/Exodus Interval=250' inputs/bar.xml | progress
wait $uniform || { uniform=""; cat out/bar-uniform.log; exit 1; }
uniform=""
grep -E "^signorini: cycle" out/bar-uniform.log
/usr/bin/python3 tools/plot_bar.py --adaptive out/bar --uniform out/bar-uniform \
  --more-adaptive "out/bar-fraction20:adaptive, fixed fraction 20%" --steps auto --out out/plots-bar
/usr/bin/python3 tools/compare_runs.py out/bar out/bar-uniform || true
/usr/bin/python3 tools/compare_runs.py out/bar-fraction20 out/bar-uniform || true
# The committed figures are these plots.
cp out/plots-bar/{bar_eta_vs_unknowns,bar_meshes,bar_contact_zone}.png docs/figures/
echo "copied out/plots-bar/*.png to docs/figures/"
