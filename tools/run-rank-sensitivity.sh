#!/usr/bin/env bash
# How far 1 and 2 ranks agree on the adaptive paper deck (inputs/membrane.xml, two cycles), set
# against how far one rank moves when the initial velocity is perturbed by 1e-12 (relative): with the
# paper's scheme and with the contact stabilisation in ordinary arithmetic (the deck's
# Parallel/Reproducible Arithmetic switched off), and with the deck as it is (2 ranks then give the
# bits of 1 rank; the perturbation still grows). Prints the difference of the probe u(1, 0.5) and of eta^n over cycle 1 (whose meshes all
# runs share) and the unknowns of cycle 1. About 2 minutes.
# Usage: bash tools/run-rank-sensitivity.sh   (SIGNORINI_NO_BUILD=1: use the existing build/src/signorini)
# Takes no arguments (-h, --help: this text). The MPI launcher is the one of the build's tests (CMake's
# MPIEXEC_* entries in build/CMakeCache.txt), as in the bench scripts.
set -euo pipefail
source "$(dirname "$0")/script_args.sh"
no_arguments "$@"
cd "$(dirname "$0")/.."
build_first
out=out/sensitivity
mkdir -p "$out"
arithmetic=false  # Parallel/Reproducible Arithmetic of the runs below
run() {  # run NP BASENAME [--set ...]
  local np=$1 base=$2
  shift 2
  mpi_launcher "$np"
  "${mpirun[@]}" ./build/src/signorini --output-dir "$out" \
    --set "Output/Basename=$base" --set "Output/Write Exodus=false" --set "Adaptivity/Cycles=2" \
    --set "Parallel/Reproducible Arithmetic=$arithmetic" "$@" \
    inputs/membrane.xml > "$out/$base.log"
}
perturbed="Problem/Initial Velocity=-(1 + 1e-12)*sin(pi*x/2)"
stabilised="Time Integration/Contact Stabilisation=predictor projection"
run 1 paper.np1
run 2 paper.np2
run 1 paper.perturbed --set "$perturbed"
run 1 stabilised.np1 --set "$stabilised"
run 2 stabilised.np2 --set "$stabilised"
run 1 stabilised.perturbed --set "$perturbed" --set "$stabilised"
arithmetic=true
run 1 reproducible.np1
run 2 reproducible.np2
run 1 reproducible.perturbed --set "$perturbed"
/usr/bin/python3 tools/compare_sensitivity.py "$out"
