#!/usr/bin/env bash
# Sets up, builds and runs the main job: paper Example 6.1 (inputs/membrane.xml); results in ./out.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
mkdir -p out
./build/src/signorini --output-dir out inputs/membrane.xml "$@"
