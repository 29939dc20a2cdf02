#!/bin/sh
# Runs one verification case twice: as written (each step stores the upper triangle of its
# symmetric tangent and solves with CHOLMOD, or UMFPACK with multipliers) and with every *STEP
# given UNSYMM=YES (the full pattern and UMFPACK), then compares the two histories column by
# column to 1e-9 of each column's scale (`clinch compare --rtol 1e-9`). The two runs solve the
# same equations with different storage, ordering and factorization, so they agree to round-off
# amplified by the conditioning and the Newton tolerances, well inside 1e-9. A column that is zero
# up to round-off (a component that carries nothing, e.g. CU2 = -3.5e-18) has no scale of its own:
# --atol 1e-12 lets such values differ by their round-off.
# Usage: run_case_unsymmetric.sh CLINCH CASE_DIR
set -u

if [ "$#" -ne 2 ]; then
  echo "usage: $0 CLINCH CASE_DIR" >&2
  exit 3
fi
clinch=$1
case_dir=${2%/}
case_name=$(basename "$case_dir")
deck="$case_dir/$case_name.inp"

out=$(mktemp -d "${TMPDIR:-/tmp}/clinch-unsymm-$case_name.XXXXXX") || exit 3
trap 'rm -rf "$out"' EXIT

# *STEP lines (any case, with or without parameters) gain ", UNSYMM=YES".
sed -E 's/^(\*[Ss][Tt][Ee][Pp])([ ,].*)?$/\1\2, UNSYMM=YES/' "$deck" > "$out/$case_name.inp"
if ! grep -qi '^\*step.*UNSYMM=YES' "$out/$case_name.inp"; then
  echo "unsymm $case_name: no *STEP line found" >&2
  exit 3
fi

mkdir -p "$out/symmetric" "$out/full"
for run in symmetric full; do
  input=$deck
  [ "$run" = full ] && input="$out/$case_name.inp"
  "$clinch" run "$input" --out "$out/$run" --job job --quiet
  status=$?
  if [ "$status" -ne 0 ]; then
    echo "unsymm $case_name: the $run run exited with status $status" >&2
    exit 1
  fi
done
if ! grep -q 'on the full pattern' "$out/full/job.log"; then
  echo "unsymm $case_name: the UNSYMM=YES run did not assemble the full pattern" >&2
  exit 1
fi
"$clinch" compare "$out/full/job.history.csv" "$out/symmetric/job.history.csv" \
  --rtol 1e-9 --atol 1e-12
status=$?
if [ "$status" -ne 0 ]; then
  echo "unsymm $case_name: UNSYMM=YES history differs from the symmetric run" >&2
  exit 1
fi
echo "unsymm $case_name: passed"
