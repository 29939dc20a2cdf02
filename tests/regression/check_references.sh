#!/bin/sh
# Re-runs every decks/verification/<case>/reference.py into a scratch directory and checks that
# the committed golden.csv is exactly what the script produces, so the provenance of each golden
# table stays executable. Usage: check_references.sh VERIFICATION_DIR [PYTHON]
set -u

if [ "$#" -lt 1 ]; then
  echo "usage: $0 VERIFICATION_DIR [PYTHON]" >&2
  exit 3
fi
root=${1%/}
python=${2:-python3}
out=$(mktemp -d "${TMPDIR:-/tmp}/clinch-references.XXXXXX") || exit 3
trap 'rm -rf "$out"' EXIT

failed=0
for script in "$root"/*/reference.py; do
  case_dir=$(dirname "$script")
  case_name=$(basename "$case_dir")
  if ! PYTHONDONTWRITEBYTECODE=1 GOLDEN_OUT_DIR="$out" "$python" "$script"; then
    echo "reference $case_name: reference.py failed" >&2
    failed=1
  elif ! cmp -s "$out/$case_name.golden.csv" "$case_dir/golden.csv"; then
    echo "reference $case_name: golden.csv differs from what reference.py writes" >&2
    failed=1
  fi
done
exit $failed
