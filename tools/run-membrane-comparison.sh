#!/usr/bin/env bash
# Paper Example 6.1 reproduced: the adaptive run (inputs/membrane.xml, the paper's 50% fixed fraction),
# the same with a 10% fixed fraction (inputs/membrane-fraction10.xml), their uniform comparison
# (inputs/membrane-uniform.xml), the multiplier for H = 2h and H = h on one uniform mesh, the plots
# (out/plots/*.png) and the factors in unknowns and wall time. About 4 minutes on 2 cores.
# Usage: bash tools/run-membrane-comparison.sh
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh > /dev/null
mkdir -p out
./build/src/signorini --output-dir out inputs/membrane.xml inputs/membrane-fraction10.xml inputs/membrane-uniform.xml \
  inputs/membrane-level2.xml
./build/src/signorini --output-dir out --set 'Contact/Multiplier Segments=H = h' --set 'Output/Basename=membrane-Hh' \
  inputs/membrane-level2.xml
/usr/bin/python3 tools/plot_results.py --adaptive out/membrane --uniform out/membrane-uniform \
  --more-adaptive "out/membrane-fraction10:adaptive, fixed fraction 10%" \
  --two-h out/membrane-level2 --h-equals-h out/membrane-Hh --steps 20,40,100,200,300,400 --out out/plots
/usr/bin/python3 tools/compare_runs.py out/membrane out/membrane-uniform
/usr/bin/python3 tools/compare_runs.py out/membrane-fraction10 out/membrane-uniform
