#!/usr/bin/env bash
# Installs the Debian packages signorini needs (idempotent) and builds it in ./build (Release when
# ./build is configured for the first time; an existing build keeps its CMAKE_BUILD_TYPE).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
if [ -f build/CMakeCache.txt ]; then
  cmake -S . -B build
else
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
fi
cmake --build build -j "${SIGNORINI_BUILD_JOBS:-2}"
