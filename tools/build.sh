#!/usr/bin/env bash
# Installs the Debian packages signorini needs (idempotent) and builds it in ./build.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "${SIGNORINI_BUILD_JOBS:-2}"
