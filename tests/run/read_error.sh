#!/bin/sh
# Usage: read_error.sh CLINCH WORKDIR
# A read that fails part-way through the deck's input is an I/O error (cli-contract.md: exit 3),
# with a message naming the file, for `check` and `run` alike; not a deck error (exit 1). The
# failing file is a sysfs attribute: a regular file of 4096 bytes whose every read fails
# (/sys/class/net/lo/speed: EINVAL), included after the deck's first lines, and given as the
# deck itself. Skipped (exit 77) where no such file exists.
set -u
clinch=$1 dir=$2
bad=/sys/class/net/lo/speed
if ! [ -f "$bad" ] || cat "$bad" >/dev/null 2>&1; then
  echo "skipped: $bad is not a regular file whose read fails here"
  exit 77
fi
rm -rf "$dir" && mkdir -p "$dir"
printf '*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*INCLUDE, INPUT=%s\n*ELEMENT, TYPE=CONN3D2\n1, 1, 2\n' \
  "$bad" >"$dir/deck.inp"
fail=0
expect_io_error() {  # what, then the command's arguments
  what=$1
  shift
  "$clinch" "$@" >"$dir/stdout" 2>"$dir/stderr"
  status=$?
  if [ "$status" -ne 3 ] || ! grep -q "clinch: error: cannot read '$bad' after 0 bytes: " "$dir/stderr"; then
    echo "$what: exit $status, expected 3 and a message naming $bad:" >&2
    cat "$dir/stderr" >&2
    fail=1
  fi
}
expect_io_error "check of a deck including it" check "$dir/deck.inp"
expect_io_error "run of a deck including it" run --quiet --out "$dir/out" "$dir/deck.inp"
grep -q "included at $dir/deck.inp:4:17" "$dir/stderr" || { echo "no include location" >&2; fail=1; }
expect_io_error "check of it as the deck" check "$bad"
expect_io_error "run of it as the deck" run --quiet --out "$dir/out" --job bad "$bad"
exit $fail
