#!/usr/bin/env bash
# The README's "first deck of one's own" runs as printed: extracted from README.md, it runs without
# a warning, and its step 0 has the kinetic energy the README states, rho |A| v^2 / 2 =
# 2770 * (0.1 * 0.05) * 5^2 / 2 = 173.125 J/m (to rounding).
# Usage: readme_first_deck.sh SIGNORINI MPIEXEC SOURCE_DIR WORK_DIR
source "$(dirname "$0")/../dynamics/run_helpers.sh" "$@"
$py - "$src/README.md" "$work/drop.xml" <<'PY' || fail "no deck after 'A first deck of one's own' in README.md"
import re, sys
text = open(sys.argv[1]).read()
at = text.index("A first deck of one's own")
block = re.search(r"```xml\n(.*?)```", text[at:], re.S)
open(sys.argv[2], "w").write(block.group(1))
PY
run drop 1 "$work/drop.xml"
grep -q "warning" "$work/drop.log" && { cat "$work/drop.log"; fail "the README's deck draws a warning"; }
$py - "$work/drop/drop.steps.csv" <<'PY' || exit 1
import sys
from step_tables import fail, table
rows = table(sys.argv[1])
kinetic = float(rows[0]["kinetic_energy"])
if abs(kinetic - 173.125) > 1e-12 * 173.125:
    fail(f"step 0's kinetic_energy {kinetic!r}, the README says 173.125")
if len(rows) != 201 or not any(int(r["active"]) > 0 for r in rows):
    fail("the README's deck: not 200 steps with contact")
PY
echo "README first deck: ok"
