#!/usr/bin/env bash
# The result Exodus files show every boundary segment of the deck as a side set named after it,
# after the set "contact" that carries lambda and gap (check_segment_side_sets.py):
#  - the bar of Example 6.2, adaptive (2 cycles, meshes with hanging nodes) on 2 ranks: "clamped",
#    "foundation", "load" cover exactly the left side, the bottom's x >= 0.15 and the top's x >= 0.1
#    in every file of the series, and "foundation" holds the sides of "contact";
#  - the membrane, whose segment "contact" is all of Gamma_C: no second set of that name;
#  - names as ParaView's default reader shows them, never twice: a segment "contact" that is only part
#    of Gamma_C is "contact_2", "Upper Part" is "upper_part", "domain" (the element block's name) is
#    "domain_2";
#  - an unused segment narrower than the bar's coarse edges ("corner", right, y >= 0.049) is in every
#    file of the series, empty where the mesh gives it no edge (no edge's midpoint is that high) and
#    on the right side's top where it does;
#  - controls: the checker fails on a piece that is too long, on a piece that is off the set's sides,
#    and on a wrong list of sets.
# Usage: segment_side_sets.sh SIGNORINI MPIEXEC SOURCE_DIR WORK_DIR
source "$(dirname "$0")/../dynamics/run_helpers.sh" "$@"
check="$py $src/tests/io/check_segment_side_sets.py"
quiet=(--set "Output/Progress Interval=100000")

run bar 2 "${quiet[@]}" --set "Time Integration/Final Time=1e-4" --set "Adaptivity/Cycles=2" "$src/inputs/bar.xml"
ls "$work"/bar/bar.e-s.* > /dev/null 2>&1 || fail "the bar's final cycle wrote one mesh: no hanging nodes were checked"
bar=(--sets contact,clamped,foundation,load --piece "clamped=0,0,0,0.05" --piece "foundation=0.15,0,0.2,0"
     --piece "load=0.1,0.05,0.2,0.05" --same contact=foundation)
$check "$work/bar/bar.e" "${bar[@]}" || fail "bar: the segments' side sets"

run membrane 1 "${quiet[@]}" "$decks/good.xml"
$check "$work/membrane/good.e" --sets contact,clamped --piece "clamped=0,0,0,1" --piece "contact=1,0,1,1" ||
  fail "membrane: the segments' side sets"

run split 1 "${quiet[@]}" --set "Mesh/Boundary Segments/contact=right, y <= 0.5" \
  --set "Mesh/Boundary Segments/Upper Part=right, y >= 0.5" --set "Problem/Contact Segments=contact, Upper Part" \
  --set "Mesh/Boundary Segments/domain=bottom" "$decks/good.xml"
$check "$work/split/good.e" --sets "contact,clamped,contact_2,domain_2,upper_part" --piece "contact=1,0,1,1" \
  --piece "contact_2=1,0,1,0.5" --piece "upper_part=1,0.5,1,1" --piece "domain_2=0,0,1,0" ||
  fail "split contact: the segments' side sets"

run corner 2 "${quiet[@]}" --set "Time Integration/Final Time=1e-4" --set "Adaptivity/Cycles=3" \
  --set "Output/Exodus Interval=1" --set "Mesh/Boundary Segments/corner=right, y >= 0.049" "$src/inputs/bar.xml"
$check "$work/corner/bar.e" --sets contact,clamped,corner,foundation,load --piece "clamped=0,0,0,0.05" \
  --within "corner=0.2,0.048,0.2,0.05" --empty-in-some corner || fail "an unused narrow segment's side set"

# Controls: each must fail.
$check "$work/bar/bar.e" --sets contact,clamped,foundation,load --piece "load=0.05,0.05,0.2,0.05" > /dev/null &&
  fail "control: a piece longer than the set passed"
$check "$work/bar/bar.e" --sets contact,clamped,foundation,load --piece "load=0.1,0.0,0.2,0.0" > /dev/null &&
  fail "control: a piece off the set's sides passed"
$check "$work/bar/bar.e" --sets contact,foundation,clamped,load > /dev/null && fail "control: a wrong order of sets passed"
echo "segment side sets: ok"
