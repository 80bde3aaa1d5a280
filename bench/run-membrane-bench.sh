#!/usr/bin/env bash
# Benchmark (not a test): the uniform membrane at 263,169 unknowns per step; prints the phase
# split per step and the contact overhead ratio R. Usage: bash bench/run-membrane-bench.sh [-np N]
# (-h, --help: this text; SIGNORINI_NO_BUILD=1: use the existing build/src/signorini)
set -euo pipefail
source "$(dirname "$0")/bench_args.sh"
help_only "$@"
parse_ranks "usage: bash bench/run-membrane-bench.sh [-np N]" "$@"  # its own usage for a bad argument
exec bash "$(dirname "$0")/run-contact-bench.sh" "$(dirname "$0")/membrane-250k.xml" "$@"
