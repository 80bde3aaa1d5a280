#!/usr/bin/env bash
# Benchmark (not a test): the paper's bar (Example 6.2) on a uniform mesh with 296,834 unknowns per
# step, 60 steps (one impact, 18 steps in contact); prints the phase split per step, MueLu iterations and the contact
# overhead ratio R (target <= 4). Usage: bash bench/run-bar-bench.sh [-np N]
exec bash "$(dirname "$0")/run-contact-bench.sh" bench/bar-300k.xml "$@"
