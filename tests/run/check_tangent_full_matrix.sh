#!/bin/sh
# `clinch run --check-tangent DECK` compares the whole assembled matrix with finite differences:
# every logged check must have compared n² entries for its n equations (prescribed DOFs included,
# symmetric storage read through both triangles; the DOFs that kinematic constraints eliminate
# are no equations), and the run must complete.
# Usage: check_tangent_full_matrix.sh CLINCH DECK OUT_DIR
set -u
clinch=$1
deck=$2
out=$3
rm -rf "$out"
"$clinch" run --check-tangent --quiet --out "$out" --job job "$deck" || exit 1
checks=$(grep -c '^tangent check at step' "$out/job.log")
if [ "$checks" -eq 0 ]; then
  echo "no tangent check in the log" >&2
  exit 1
fi
grep '^tangent check at step' "$out/job.log" | awk '
  { for (i = 1; i <= NF; ++i) {
      if ($i == "equations," || $i == "equations") n = $(i - 1)
      if ($i == "entries") m = $(i - 1)
    }
    if (n == "" || m != n * n) { print "not the full matrix: " $0 > "/dev/stderr"; bad = 1 } }
  END { exit bad }'
