#!/bin/sh
# Usage: long_column_name.sh CLINCH WORKDIR PATTERN EXPECTED_EXIT
# Compares two tables whose header holds a 50 000-character column name ("aaa...a") next to a
# short one ("ab"), selecting columns with PATTERN. Patterns that make a backtracking engine take
# exponential time, or recurse once per character, must still finish at once with the usual exit.
set -u
clinch=$1 dir=$2 pattern=$3 expected=$4
mkdir -p "$dir"
long=$(head -c 50000 /dev/zero | tr '\0' a)
for table in result golden; do
  printf 'step,increment,step_time,total_time,%s,ab\n1,0,0,0,1,2\n' "$long" >"$dir/$table.csv"
done
"$clinch" compare --columns "$pattern" "$dir/result.csv" "$dir/golden.csv" >"$dir/out.txt" 2>&1
status=$?
if [ "$status" -ne "$expected" ]; then
  echo "exit $status, expected $expected:" >&2
  head -c 2000 "$dir/out.txt" >&2
  exit 1
fi
