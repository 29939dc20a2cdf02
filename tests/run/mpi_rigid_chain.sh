#!/bin/sh
# A chain of 300 rigid bodies joined by BUSHING connectors (decks/bench/generate_rigid_chain.py,
# NLGEOM, twisted to a quarter turn) on 2 MPI ranks against the serial run, both with PETSc:
# every history value agrees to 1e-8 of the solution's scale (|U1| reaches 2.99 and UR1 1.57 at
# the tip: --atol 3e-8), near-zero columns included; both runs converge Newton to 1e-8 of the
# forces (the deck's *CONTROLS), and they solve differently only through the order of sums and
# the iterative solver's iterates.
# Usage: mpi_rigid_chain.sh CLINCH PYTHON GENERATOR OUT_DIR
set -eu
clinch=$1
python=$2
generator=$3
out=$4
rm -rf "$out"
mkdir -p "$out"
"$python" "$generator" --bodies 300 --out "$out/chain.inp"
"$clinch" run "$out/chain.inp" --out "$out/serial" --job job --quiet --solver petsc
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun --oversubscribe -n 2 "$clinch" run "$out/chain.inp" --out "$out/distributed" --job job \
  --quiet --solver petsc
grep -q "distributed over 2 processes" "$out/distributed/job.log"
"$clinch" compare "$out/distributed/job.history.csv" "$out/serial/job.history.csv" \
  --rtol 1e-8 --atol 3e-8
