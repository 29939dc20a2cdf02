#!/usr/bin/env bash
# The whole test suite under AddressSanitizer and UndefinedBehaviorSanitizer (ARCHITECTURE.md,
# conventions): builds with -DCLINCH_SANITIZE=ON into build-asan/ and runs ctest there. Any
# sanitizer report fails the test that produced it (UBSan halts instead of printing and going on).
# Not part of CI: the build and the run take several times the plain ones.
# Usage: scripts/sanitize.sh [ctest arguments...]   (e.g. -R Expression); JOBS (default 2).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${JOBS:-2}
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCLINCH_SANITIZE=ON \
  -DCLINCH_BUILD_TESTS=ON -DCLINCH_BUILD_BENCHMARKS=OFF -DCLINCH_BUILD_FUZZERS=OFF >/dev/null
cmake --build build-asan -j"$jobs"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:strict_string_checks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
start=$(date +%s)
status=0
# Open MPI and PETSc leave allocations behind in the components Open MPI unloads at MPI_Finalize,
# which LeakSanitizer reports with stacks into unloaded code: the tests that start them (the PETSc
# backend, the automatic choice that may load it, the runs under mpirun) run with leak detection
# off, every other check on. With arguments, one pass as given.
mpi_tests='Petsc|LinearSolverChoice|^mpi|^petsc_'
if (($#)); then
  ctest --test-dir build-asan -j"$jobs" --output-on-failure "$@" || status=$?
else
  ctest --test-dir build-asan -j"$jobs" --output-on-failure -E "$mpi_tests" || status=$?
  ASAN_OPTIONS=${ASAN_OPTIONS/detect_leaks=1/detect_leaks=0} \
    ctest --test-dir build-asan -j"$jobs" --output-on-failure -R "$mpi_tests" || status=$?
fi
echo "sanitize: ctest took $(($(date +%s) - start)) s"
exit $status
