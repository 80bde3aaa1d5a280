#!/usr/bin/env bash
# Sets up, builds and runs the main job: paper Example 6.1 (inputs/membrane.xml); results in ./out.
# Usage: bash tools/run-membrane.sh [SIGNORINI ARGUMENTS...]   (-h, --help: this text)
# The arguments go on to signorini after the deck: --set 'Sublist/key=value', --check, more decks
# (build/src/signorini --help lists them); an option signorini does not know is refused before the build.
set -euo pipefail
source "$(dirname "$0")/script_args.sh"
help_only "$@"
value_of=""  # signorini's options (src/signorini.cpp), checked here so that a typo fails before the build
for a in "$@"; do
  if [ -n "$value_of" ]; then value_of=""; continue; fi
  case $a in
    --) break ;;  # decks only from here on
    --set | --output-dir) value_of=$a ;;
    --set=* | --output-dir=* | --check | --print-parameters | --version | --kokkos-*) ;;
    -?*) usage_error "unknown option '$a' (build/src/signorini --help lists signorini's options)" ;;
  esac
done
[ -z "$value_of" ] || usage_error "option '$value_of' needs a value"
cd "$(dirname "$0")/.."
bash tools/build.sh
mkdir -p out
./build/src/signorini --output-dir out inputs/membrane.xml "$@"
