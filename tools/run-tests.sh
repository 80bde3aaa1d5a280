#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite (GoogleTest under ctest, 1-3 MPI ranks).
# Usage: bash tools/run-tests.sh [CTEST ARGUMENTS...]   (e.g. -R tools, -LE long; -h, --help: this text)
# The arguments go on to ctest (ctest --help lists them).
set -euo pipefail
source "$(dirname "$0")/script_args.sh"
help_only "$@"
cd "$(dirname "$0")/.."
bash tools/build.sh
cd build
ctest --output-on-failure --timeout 900 "$@"
