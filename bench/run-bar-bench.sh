#!/usr/bin/env bash
# Benchmark (not a test): the paper's bar (Example 6.2) on a uniform mesh with 296,834 unknowns per
# step, 60 steps (one impact, 18 steps in contact); prints the phase split per step, MueLu iterations and the contact
# overhead ratio R (target <= 4). Usage: bash bench/run-bar-bench.sh [-np N]
# (-h, --help: this text; SIGNORINI_NO_BUILD=1: use the existing build/src/signorini)
set -euo pipefail
source "$(dirname "$0")/bench_args.sh"
help_only "$@"
parse_ranks "usage: bash bench/run-bar-bench.sh [-np N]" "$@"  # its own usage for a bad argument
exec bash "$(dirname "$0")/run-contact-bench.sh" "$(dirname "$0")/bar-300k.xml" "$@"
