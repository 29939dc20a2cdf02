#!/bin/sh
# Runs one verification case of decks/verification/ end to end.
#   run_case.sh CLINCH CASE_DIR          `clinch run` on the case's deck, then `clinch compare` of
#                                        the history against golden.csv with the tolerances in
#                                        compare.args.
#   run_case.sh --solver NAME CLINCH CASE_DIR
#                                        as the first form, with `clinch run --solver NAME`.
#   run_case.sh --mpi RANKS [--solver NAME] CLINCH CASE_DIR
#                                        `mpirun -n RANKS clinch run` against the serial run of
#                                        the same deck and solver, compared to 1e-8 of each
#                                        column's scale (docs/parallel.md): the ranks sum their
#                                        shares of the residual and tangent in another order than
#                                        one process, and an iterative solver stops at 1e-10.
#   run_case.sh --check-tangent CLINCH CASE_DIR
#                                        the deck as written against the same run with
#                                        `--check-tangent`, compared to 1e-12 of each column's
#                                        scale: the check restores the state it moves, so a
#                                        checked run is the unchecked one (the same operations on
#                                        the same numbers, hence equal to the last bit; 1e-12
#                                        leaves room for nothing but a changed answer).
#   run_case.sh --unsymm CLINCH CASE_DIR the deck as written (each step stores the upper triangle
#                                        of its symmetric tangent: CHOLMOD, or UMFPACK with
#                                        multipliers) against the deck with every *STEP given
#                                        UNSYMM=YES (the full pattern and UMFPACK), compared to
#                                        1e-9 of each column's scale.
# The two storages solve the same equations with different orderings and factorizations, so they
# agree to round-off amplified by the conditioning and the Newton tolerances, well inside 1e-9. A
# column that is zero up to round-off (a component that carries nothing, e.g. CU2 = -3.5e-18) has
# no scale of its own: --atol 1e-12 lets such values differ by their round-off.
set -u

unsymm=0
check_tangent=0
solver=auto
ranks=0
if [ "${1:-}" = "--mpi" ] && [ "$#" -ge 2 ]; then
  ranks=$2
  shift 2
fi
if [ "${1:-}" = "--unsymm" ]; then
  unsymm=1
  shift
elif [ "${1:-}" = "--check-tangent" ]; then
  check_tangent=1
  shift
elif [ "${1:-}" = "--solver" ] && [ "$#" -ge 2 ]; then
  solver=$2
  shift 2
fi
if [ "$#" -ne 2 ]; then
  echo "usage: $0 [--unsymm | --check-tangent | [--mpi RANKS] [--solver NAME]] CLINCH CASE_DIR" >&2
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

out=$(mktemp -d "${TMPDIR:-/tmp}/clinch-verify-$case_name.XXXXXX") || exit 3
trap 'rm -rf "$out"' EXIT

# Runs `clinch run` on deck $1 into directory $2 with job name `job` (under mpirun with
# $launch set), with the further options $3.
run_deck() {
  mkdir -p "$2"
  # shellcheck disable=SC2086
  $launch "$clinch" run "$1" --out "$2" --job job --quiet --solver "$solver" ${3:-}
  status=$?
  if [ "$status" -ne 0 ]; then
    echo "verify $case_name: 'clinch run' of $1 exited with status $status (expected 0)" >&2
    [ -f "$2/job.sta" ] && echo "last status line: $(tail -n 1 "$2/job.sta")" >&2
    exit 1
  fi
}

# The variant run of deck $1 into $out/$2 with the further options $3 must log a line matching
# $4 (else $5 says what it missed); it is then compared with the run as written, with the
# options $6.
variant() {
  run_deck "$1" "$out/$2" "$3"
  if ! grep -q "$4" "$out/$2/job.log"; then
    echo "verify $case_name: $5" >&2
    exit 1
  fi
  result="$out/$2/job.history.csv"
  reference="$out/as-written/job.history.csv"
  compare_args=$6
}

launch=
run_deck "$deck" "$out/as-written"
if [ "$ranks" -gt 0 ]; then
  # Open MPI refuses root without these; --oversubscribe lets a 2-core machine run 2 ranks
  # beside other tests.
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  launch="mpirun --oversubscribe -n $ranks"
  variant "$deck" distributed "" "distributed over $ranks processes" \
          "the mpirun -n $ranks run did not distribute its elements" "--rtol 1e-8 --atol 1e-12"
elif [ "$check_tangent" -eq 1 ]; then
  variant "$deck" checked --check-tangent '^tangent check at step' \
          "the --check-tangent run logged no tangent check" "--rtol 1e-12 --atol 0"
elif [ "$unsymm" -eq 1 ]; then
  # *STEP lines (any case, with or without parameters) gain ", UNSYMM=YES".
  sed -E 's/^(\*[Ss][Tt][Ee][Pp])([ ,].*)?$/\1\2, UNSYMM=YES/' "$deck" > "$out/$case_name.inp"
  variant "$out/$case_name.inp" full "" 'on the full pattern' \
          "the UNSYMM=YES run did not assemble the full pattern" "--rtol 1e-9 --atol 1e-12"
else
  result="$out/as-written/job.history.csv"
  reference=$golden
  compare_args=""
  [ -f "$case_dir/compare.args" ] && compare_args=$(cat "$case_dir/compare.args")
fi

# compare_args holds plain options such as "--rtol 1e-9 --atol 1e-9": split on blanks.
# shellcheck disable=SC2086
"$clinch" compare "$result" "$reference" $compare_args
status=$?
if [ "$status" -ne 0 ]; then
  echo "verify $case_name: history differs from $(basename "$reference") (clinch compare exited" \
       "with $status; tolerances: ${compare_args:-defaults})" >&2
  exit 1
fi
echo "verify $case_name: passed"
