#!/bin/sh
# Every deck that `clinch check` passes is accepted by `clinch run` (cli-contract.md exit codes:
# run exit 1 means the deck was refused). Runs check, then run, over every .inp under decks/ and
# tests/ except tests/diagnostics/ (decks meant to fail) and fragments that check rejects anyway.
# A run may stop early (exit 2, a deck that tests a failure) or time out: only exit 1 fails.
# Usage: check_then_run.sh CLINCH SOURCE_DIR WORK_DIR
clinch=$1
source_dir=$2
work=$3
rm -rf "$work" && mkdir -p "$work" || exit 3
failed=0
checked=0
for deck in $(cd "$source_dir" && find decks tests -name '*.inp' -not -path 'tests/diagnostics/*' | sort); do
  if ! "$clinch" check "$source_dir/$deck" >/dev/null 2>&1; then
    continue
  fi
  checked=$((checked + 1))
  job=$(echo "$deck" | tr '/.' '__')
  timeout 120 "$clinch" run --quiet --out "$work" --job "$job" "$source_dir/$deck" \
    >"$work/$job.stdout" 2>"$work/$job.stderr"
  status=$?
  if [ "$status" -eq 1 ]; then
    echo "FAIL: clinch check passes $deck but clinch run refuses it:"
    cat "$work/$job.stderr"
    failed=1
  fi
done
echo "$checked decks passed clinch check"
[ "$checked" -gt 0 ] || exit 1
exit $failed
