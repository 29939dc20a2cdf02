#!/bin/sh
# A distributed model shares the connectors (docs/parallel.md): each rank holds the records,
# state and results of its own, and the decisions they take are joined. Six AXIAL connectors
# whose stop, failure, released motion and new motion belong to ranks other than 0 on 2 and 3
# ranks, against the serial run (PETSc both): the same history to 1e-8 (values of order 1 to 12;
# --atol 1e-10 for the columns that stay zero), and the same log but for timings and the solver
# lines (the events: stop changes, the failure, the iterations' norms to 7 digits) and status
# file. The same deck without the spring beside the failing connector stops singular: the same
# message, naming connector 4 from rank 1's share, and exit 2 on every count of ranks.
# Usage: mpi_shared_connectors.sh CLINCH DECK_DIR OUT_DIR
set -eu
clinch=$1
decks=$2
out=$3
rm -rf "$out"
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
steady() { grep -v "time:\|factorize\|petsc\|distributed\|COMPLETED\|FAILED after" "$1"; }
for deck in mpi_shared_connectors mpi_shared_connectors_failing; do
  expected=0
  [ "$deck" = mpi_shared_connectors_failing ] && expected=2
  status=0
  "$clinch" run "$decks/$deck.inp" --out "$out/$deck-1" --job job --quiet --solver petsc ||
    status=$?
  [ "$status" -eq "$expected" ] || { echo "$deck serial: exit $status, expected $expected"; exit 1; }
  for ranks in 2 3; do
    status=0
    mpirun --oversubscribe -n "$ranks" "$clinch" run "$decks/$deck.inp" \
      --out "$out/$deck-$ranks" --job job --quiet --solver petsc || status=$?
    [ "$status" -eq "$expected" ] ||
      { echo "$deck on $ranks ranks: exit $status, expected $expected"; exit 1; }
    grep -q "each holds the records and results of its own elements and assembles its part" "$out/$deck-$ranks/job.log"
    "$clinch" compare "$out/$deck-$ranks/job.history.csv" "$out/$deck-1/job.history.csv" \
      --rtol 1e-8 --atol 1e-10
    steady "$out/$deck-$ranks/job.log" > "$out/$deck-$ranks.steady"
    steady "$out/$deck-1/job.log" > "$out/$deck-1.steady"
    diff "$out/$deck-$ranks.steady" "$out/$deck-1.steady"
    diff "$out/$deck-$ranks/job.sta" "$out/$deck-1/job.sta"
  done
done
grep -q "FAILED: singular system: DOF u1 of node 8 has no stiffness, although connector element 4" \
  "$out/mpi_shared_connectors_failing-3/job.sta"
grep -q "connector element 4 failed (component 1 force" "$out/mpi_shared_connectors-2/job.log"
