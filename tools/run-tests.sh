#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite (GoogleTest under ctest, 1-3 MPI ranks).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
cd build
ctest --output-on-failure --timeout 900 "$@"
