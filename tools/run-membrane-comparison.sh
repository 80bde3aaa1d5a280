#!/usr/bin/env bash
# Paper Example 6.1 reproduced: the adaptive run (inputs/membrane.xml, the paper's 50% fixed fraction),
# the same with a 10% fixed fraction (inputs/membrane-fraction10.xml), their uniform comparison
# (inputs/membrane-uniform.xml), the multiplier for H = 2h and H = h on one uniform mesh (h = 1/64,
# inputs/membrane-level2.xml, every step written; with the paper's scheme and with the contact
# stabilisation), the plots (out/plots/*.png, copied to docs/figures/) and the factors in unknowns and
# wall time. About 4 minutes on 2 cores.
# Usage: bash tools/run-membrane-comparison.sh   (SIGNORINI_NO_BUILD=1: use the existing build/src/signorini)
# Takes no arguments (-h, --help: this text).
set -euo pipefail
source "$(dirname "$0")/script_args.sh"
no_arguments "$@"
cd "$(dirname "$0")/.."
build_first
mkdir -p out
./build/src/signorini --output-dir out inputs/membrane.xml inputs/membrane-fraction10.xml inputs/membrane-uniform.xml
# Fig. 3.1: H = 2h and H = h, every step written (the paper's scheme chatters in time, so the plot
# shows the multiplier over all steps in contact, not one step), and the same with the contact
# stabilisation (not the paper's scheme), where a single step shows the spatial effect alone.
multiplier() {  # basename, --set arguments...
  local base=$1
  shift
  ./build/src/signorini --output-dir out --set "Output/Basename=$base" --set 'Output/Exodus Interval=1' "$@" \
    inputs/membrane-level2.xml
}
multiplier membrane-level2
multiplier membrane-Hh --set 'Contact/Multiplier Segments=H = h'
stabilised=(--set 'Time Integration/Contact Stabilisation=predictor projection')
multiplier membrane-level2-stabilised "${stabilised[@]}"
multiplier membrane-Hh-stabilised "${stabilised[@]}" --set 'Contact/Multiplier Segments=H = h'
/usr/bin/python3 tools/plot_results.py --adaptive out/membrane --uniform out/membrane-uniform \
  --more-adaptive "out/membrane-fraction10:adaptive, fixed fraction 10%" \
  --two-h out/membrane-level2 --h-equals-h out/membrane-Hh \
  --two-h-stabilised out/membrane-level2-stabilised --h-equals-h-stabilised out/membrane-Hh-stabilised \
  --steps 20,40,100,200,300,400 --out out/plots
/usr/bin/python3 tools/compare_runs.py out/membrane out/membrane-uniform
/usr/bin/python3 tools/compare_runs.py out/membrane-fraction10 out/membrane-uniform
# The committed figures are these plots (eta_vs_unknowns_finer.png comes from run-membrane-finer.sh).
cp out/plots/{eta_vs_unknowns,estimator_contributions,meshes,multiplier,energy_and_probe}.png docs/figures/
echo "copied out/plots/*.png to docs/figures/"
