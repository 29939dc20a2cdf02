#!/bin/sh
# clinch gives the same answers with its huge-page heap as without it (CLINCH_HUGE_PAGES=0):
# the same diagnostics from `clinch check` of a 300 kB deck (the in-process heap reservation,
# 256 kB to 4 MiB) and the same history from `clinch run` of it (the re-executed process, from
# 128 kB). The deck: a straight chain of 7000 AXIAL connectors along x, pulled at its tip.
# Usage: huge_pages_same_results.sh <clinch> <work directory>
set -eu
clinch=$1
work=$2
rm -rf "$work"
mkdir -p "$work"
deck=$work/chain.inp
awk -v n=7000 'BEGIN {
  print "*NODE, NSET=ALLN"
  for (i = 1; i <= n + 1; ++i) printf "%d, %.6f, 0., 0.\n", i, i - 1
  print "*ELEMENT, TYPE=CONN3D2, ELSET=CHAIN"
  for (i = 1; i <= n; ++i) printf "%d, %d, %d\n", i, i, i + 1
  print "*CONNECTOR SECTION, ELSET=CHAIN, BEHAVIOR=SPRING\nAXIAL,"
  print "*CONNECTOR BEHAVIOR, NAME=SPRING\n*CONNECTOR ELASTICITY, COMPONENT=1\n7.0e3"
  print "*BOUNDARY\nALLN, 2, 3\n1, 1, 1"
  print "*STEP\n*STATIC\n0.5, 1.0\n*BOUNDARY"
  printf "%d, 1, 1, 0.6\n", n + 1
  print "*OUTPUT, HISTORY, FREQUENCY=1\n*ELEMENT OUTPUT, ELSET=CHAIN\nCTF, CU\n*END STEP"
}' > "$deck"
size=$(wc -c < "$deck")
[ "$size" -ge 262144 ] || { echo "deck of $size bytes: below the medium range"; exit 1; }
"$clinch" check "$deck" 2> "$work/check-huge.txt"
CLINCH_HUGE_PAGES=0 "$clinch" check "$deck" 2> "$work/check-plain.txt"
cmp "$work/check-huge.txt" "$work/check-plain.txt"
"$clinch" run --quiet --out "$work/huge" "$deck"
CLINCH_HUGE_PAGES=0 "$clinch" run --quiet --out "$work/plain" "$deck"
cmp "$work/huge/chain.history.csv" "$work/plain/chain.history.csv"
# The tip force is k·δ/n = 7.0e3·0.6/7000 = 0.6 in every connector at the end of the step, to
# 1e-6 (the round-off of the solve over 7000 springs is about 1e-11).
tail -n 1 "$work/huge/chain.history.csv" | awk -F, '{ if ($5 < 0.599999 || $5 > 0.600001) { print "CTF1 " $5 ", expected 0.6"; exit 1 } }'
