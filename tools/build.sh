#!/usr/bin/env bash
# Installs the Debian packages signorini needs (idempotent) and builds it in ./build (Release when
# ./build is configured for the first time; an existing build keeps its CMAKE_BUILD_TYPE).
# Usage: bash tools/build.sh   (SIGNORINI_BUILD_JOBS=N: parallel jobs, default 2; -h, --help: this text)
set -euo pipefail
source "$(dirname "$0")/script_args.sh"
no_arguments "$@"
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
if [ -f build/CMakeCache.txt ]; then
  cmake -S . -B build
else
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
fi
cmake --build build -j "${SIGNORINI_BUILD_JOBS:-2}"
