#!/bin/sh
# Kinematic constraints of a distributed model (docs/parallel.md "Vectors by rows"): rigid
# bodies, kinematic couplings and *EQUATION chains that tie nodes from all over a lattice
# (tests/run/scattered_constraints.py, NLGEOM), on 2 and 3 ranks against the serial run, PETSc
# both: a static step, and (--dynamic) a step under automatic stabilization followed by a
# *DYNAMIC one (HHT, INITIAL=YES) with masses, rotary inertia at the reference nodes, dashpots
# and *ENERGY OUTPUT. The vectors run by rows, the log counts the dependent DOFs of the whole
# model, and every history value agrees to 1e-8 of its column's scale (values of order 1 to 10:
# --atol 1e-7, which also covers the columns that stay near zero); both runs converge Newton to
# 1e-9 of the forces (the deck's *CONTROLS) in the same fixed increments. Both solve with MUMPS's
# Cholesky factorization (PETSC_OPTIONS), so that Newton takes the same iterations and the status
# files are the same: a tangent that missed the curvature of the rigid arms, which only the rank
# that owns a body adds, would reach the same history in more iterations.
# Usage: mpi_scattered_constraints.sh CLINCH PYTHON GENERATOR OUT_DIR
set -eu
clinch=$1
python=$2
generator=$3
out=$4
rm -rf "$out"
mkdir -p "$out"
export PETSC_OPTIONS="-ksp_type preonly -pc_type cholesky -pc_factor_mat_solver_type mumps"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
for variant in static dynamic; do
  flag=
  [ "$variant" = dynamic ] && flag=--dynamic
  dir="$out/$variant"
  mkdir -p "$dir"
  "$python" "$generator" --size 24 --bodies 20 --couplings 10 --equations 24 $flag \
    --out "$dir/deck.inp"
  "$clinch" run "$dir/deck.inp" --out "$dir/serial" --job job --quiet --solver petsc
  followers=$(grep "of the active DOFs follow others" "$dir/serial/job.log")
  for ranks in 2 3; do
    mpirun --oversubscribe -n "$ranks" -x PETSC_OPTIONS "$clinch" run "$dir/deck.inp" \
      --out "$dir/ranks-$ranks" --job job --quiet --solver petsc
    grep -qF "$followers" "$dir/ranks-$ranks/job.log"
    grep -q "the vectors run over each rank's own rows" "$dir/ranks-$ranks/job.log"
    "$clinch" compare "$dir/ranks-$ranks/job.history.csv" "$dir/serial/job.history.csv" \
      --rtol 1e-8 --atol 1e-7
    diff "$dir/ranks-$ranks/job.sta" "$dir/serial/job.sta"
  done
done
