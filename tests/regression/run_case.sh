#!/bin/sh
# Runs one verification case of decks/verification/ end to end: `clinch run` on the case's deck,
# then `clinch compare` of the history table against the case's golden.csv with the tolerances
# in compare.args. Usage: run_case.sh CLINCH CASE_DIR
set -u

if [ "$#" -ne 2 ]; then
  echo "usage: $0 CLINCH CASE_DIR" >&2
  exit 3
fi
clinch=$1
case_dir=${2%/}
case_name=$(basename "$case_dir")
deck="$case_dir/$case_name.inp"
golden="$case_dir/golden.csv"

for file in "$deck" "$golden"; do
  if [ ! -f "$file" ]; then
    echo "verify $case_name: missing $file" >&2
    exit 3
  fi
done
compare_args=""
if [ -f "$case_dir/compare.args" ]; then
  compare_args=$(cat "$case_dir/compare.args")
fi

out=$(mktemp -d "${TMPDIR:-/tmp}/clinch-verify-$case_name.XXXXXX") || exit 3
trap 'rm -rf "$out"' EXIT

"$clinch" run "$deck" --out "$out" --quiet
status=$?
if [ "$status" -ne 0 ]; then
  echo "verify $case_name: 'clinch run' exited with status $status (expected 0)" >&2
  if [ -f "$out/$case_name.sta" ]; then
    echo "last status line: $(tail -n 1 "$out/$case_name.sta")" >&2
  fi
  exit 1
fi

# compare_args holds plain options such as "--rtol 1e-9 --atol 1e-9": split on blanks.
# shellcheck disable=SC2086
"$clinch" compare "$out/$case_name.history.csv" "$golden" $compare_args
status=$?
if [ "$status" -ne 0 ]; then
  echo "verify $case_name: history differs from golden.csv (clinch compare exited with $status;" \
       "tolerances: ${compare_args:-defaults})" >&2
  exit 1
fi
echo "verify $case_name: passed"
