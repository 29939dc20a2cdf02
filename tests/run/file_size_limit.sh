#!/bin/sh
# Usage: file_size_limit.sh CLINCH DECK WORKDIR
# Outputs that outgrow the file-size limit (ulimit -f 1: 512 bytes in a POSIX shell) are an I/O
# error (cli-contract.md: exit 3), not a death by SIGXFSZ (exit 153): stderr and the status file
# (when it is not the file that failed) name the file, why, and the increment.
set -u
clinch=$1 deck=$2 dir=$3
rm -rf "$dir" && mkdir -p "$dir"
(ulimit -f 1 && exec "$clinch" run --quiet --out "$dir/out" --job job "$deck" 2>"$dir/stderr")
status=$?
reason="cannot write '$dir/out/job\.\(log\|sta\|history\.csv\)': File too large (step 1, increment [0-9]*, time [0-9.e+-]*)"
fail=0
if [ "$status" -ne 3 ]; then
  echo "exit $status, expected 3" >&2
  fail=1
fi
if ! grep -qx "analysis stopped: $reason" "$dir/stderr"; then
  echo "stderr does not say which file was too large:" >&2
  cat "$dir/stderr" >&2
  fail=1
fi
if ! grep -q "job\.sta': File too large" "$dir/stderr" &&
  ! tail -n 1 "$dir/out/job.sta" | grep -qx "FAILED: $reason"; then
  echo "the status file ends with: $(tail -n 1 "$dir/out/job.sta")" >&2
  fail=1
fi
exit $fail
