#!/usr/bin/env bash
# Benchmark (not a test): the uniform membrane at 263,169 unknowns per step; prints the phase
# split per step and the contact overhead ratio R. Usage: bash bench/run-membrane-bench.sh [-np N]
exec bash "$(dirname "$0")/run-contact-bench.sh" bench/membrane-250k.xml "$@"
