#!/usr/bin/env bash
# Paper Example 6.1 compared at finer levels than the paper's decks: the uniform run to cycle 5
# (h = 1/512, 105 M total unknowns), the paper's 50% adaptive run to cycle 6 and the 10% run until it
# reaches the uniform cycle-4 estimate (or the uniform cycle 4's unknowns). Prints the factor in total
# unknowns at every uniform level and draws out/plots-finer/eta_vs_unknowns.png (copied to
# docs/figures/eta_vs_unknowns_finer.png). No Exodus output.
# About 6 minutes on 2 cores (the two longest runs side by side).
# Usage: bash tools/run-membrane-finer.sh   (SIGNORINI_NO_BUILD=1: use the existing build/src/signorini)
# Takes no arguments (-h, --help: this text).
set -euo pipefail
source "$(dirname "$0")/script_args.sh"
no_arguments "$@"
cd "$(dirname "$0")/.."
build_first
out=out/finer
mkdir -p "$out"
run() {  # deck basename extra --set arguments...
  local deck=$1 base=$2
  shift 2
  ./build/src/signorini --output-dir "$out" --set "Output/Basename=$base" --set "Output/Write Exodus=false" "$@" \
    "inputs/$deck" | grep -E "cycle [0-9]+:|done"
}
run membrane-uniform.xml uniform --set "Adaptivity/Cycles=6" &
uniform_pid=$!
run membrane.xml fraction50 --set "Adaptivity/Cycles=7"
wait "$uniform_pid"
read -r tol dofs < <(/usr/bin/python3 -c "
import numpy as np
c = np.atleast_1d(np.genfromtxt('$out/uniform.cycles.csv', delimiter=',', names=True))
print(repr(float(c['eta'][4])), repr(float(c['total_dofs'][4])))")
run membrane-fraction10.xml fraction10 --set "Adaptivity/Cycles=40" --set "Adaptivity/Tolerance=$tol" \
  --set "Adaptivity/Maximum Total Unknowns=$dofs"
# (no Exodus output, so no deck to take the legend from: the 50% run's is given)
/usr/bin/python3 tools/plot_results.py --eta-only --adaptive "$out/fraction50" --adaptive-label "adaptive, fixed fraction 50%" \
  --uniform "$out/uniform" \
  --more-adaptive "$out/fraction10:adaptive, fixed fraction 10%" --out out/plots-finer
/usr/bin/python3 tools/compare_runs.py "$out/fraction50" "$out/uniform" || true
/usr/bin/python3 tools/compare_runs.py "$out/fraction10" "$out/uniform" || true
cp out/plots-finer/eta_vs_unknowns.png docs/figures/eta_vs_unknowns_finer.png
echo "copied out/plots-finer/eta_vs_unknowns.png to docs/figures/eta_vs_unknowns_finer.png"
