#!/bin/sh
# Deck and job names that are not plain UTF-8 text (a Latin-1 0xFF byte, as a file named on a
# Latin-1 system has, and a double quote) through every command that writes JSON or plots
# names: `check --format json` prints valid UTF-8 JSON, and `run`, `report` (with the study's
# table) and `study` (with its plot) write their outputs, each with exit 0.
# usage: unusual_file_names.sh CLINCH WORKDIR CIRCLE_DECK UNKNOWN_KEYWORD_DECK
set -u
clinch=$1 dir=$2 circle=$3 faulty=$4
python=/usr/bin/python3
[ -x "$python" ] || python=python3
name="weld$(printf '\377')\"1\""
rm -rf "$dir" && mkdir -p "$dir" || exit 1
deck="$dir/$name.inp"
cp "$circle" "$deck" || exit 1
fail() { echo "FAIL: $*"; exit 1; }

# The diagnostics name the file: the JSON must still be UTF-8 (the byte replaced), with the quote
# escaped; and the same for a deck that cannot be opened.
cp "$faulty" "$dir/faulty-$name.inp" || exit 1
for path in "$dir/faulty-$name.inp" "$dir/missing-$name.inp"; do
  "$clinch" check --format json "$path" > "$dir/check.json" 2>/dev/null
  status=$?
  [ $status -eq 1 ] || [ $status -eq 3 ] || fail "check --format json exited with $status"
  "$python" -c '
import json, sys
text = open(sys.argv[1], "rb").read().decode("utf-8")  # strict: fails on bytes not UTF-8
name = sys.argv[2]
diagnostics = json.loads(text)
first = diagnostics[0]
assert name in (first["file"] or first["message"]), text
' "$dir/check.json" "weld$(printf '\357\277\275')\"1\"" || fail "check --format json on $path"
done

"$clinch" run --quiet --out "$dir/run" "$deck" || fail "run exited with $?"
"$clinch" study --quiet --levels 2 --work "$dir/study" "$deck" || fail "study exited with $?"
[ -s "$dir/study/$name.study.svg" ] || fail "no study plot"
"$clinch" report --quiet --study "$dir/study/$name.study.csv" "$dir/run" ||
  fail "report exited with $?"
page="$dir/run/$name.report.html"
[ -s "$page" ] || fail "no report page"
grep -q "clinch report: weld$(printf '\357\277\275')&quot;1&quot;" "$page" ||
  fail "the page title does not show the job name"
grep -q 'data-kind="work-precision"' "$page" || fail "no work-precision plot on the page"
echo "check --format json, run, study and report with the name $name: written"
