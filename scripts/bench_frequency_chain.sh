#!/usr/bin/env bash
# Whole-run wall time of a *FREQUENCY step on a fixed-free spring-mass chain of N masses m = 2
# joined by pairs of SPRING2 k = 1000 in series through massless nodes (2N equations, M singular,
# as tests/frequency/spring_mass_chain.inp at scale): Spectra in one process, SLEPc with
# --solver petsc on 1 rank and under mpirun on 2 (docs/dynamics.md "Natural frequencies"). Each
# run is timed by /usr/bin/time (elapsed), its log line must name the expected eigensolver and its
# ten lowest eigenvalues must match the closed form
#   omega_j = 2 sqrt(k/(2m)) sin((2j - 1) pi / (2(2N + 1)))
# to 1e-8 relative plus 1e-11 absolute: both eigensolvers stop at a relative residual of 1e-12
# (tests/frequency/check_modes.py), but the factorization of K - sigma M is backward stable only
# to round-off of its entries, which perturbs each eigenvalue by some ulps of the largest,
# lambda_max < 4 (k/2) / m = 1000, so 1e-11 = 1e-14 lambda_max (about 45 ulps; 1.3e-13 measured
# at N = 20000, where lambda_1 = 1.5e-6). Printed: each variant's median over the runs.
# Usage: scripts/bench_frequency_chain.sh [CLINCH]   Environment: CHAIN_MASSES (20000), CHAIN_RUNS (3)
set -euo pipefail
cd "$(dirname "$0")/.."
clinch=$(realpath "${1:-build/clinch}")
masses=${CHAIN_MASSES:-20000}
runs=${CHAIN_RUNS:-3}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
python3 - "$masses" > "$dir/chain.inp" <<'PY'
import sys
n = int(sys.argv[1])
print("*HEADING\nspring-mass chain (scripts/bench_frequency_chain.sh)\n*NODE, NSET=ALL")
for i in range(1, 2 * n + 2):
    print(f"{i}, {i - 1}., 0., 0.")
print("*ELEMENT, TYPE=SPRING2, ELSET=SPRINGS")
for i in range(1, 2 * n + 1):
    print(f"{i}, {i}, {i + 1}")
print("*SPRING, ELSET=SPRINGS\n1, 1\n1000.\n*ELEMENT, TYPE=MASS, ELSET=MASSES")
for i in range(1, n + 1):
    print(f"{2 * n + i}, {2 * i + 1}")
print("*MASS, ELSET=MASSES\n2.\n*BOUNDARY\n1, 1, 1\n*STEP, NAME=Lowest\n*FREQUENCY\n10\n*END STEP")
PY
check() {  # OUT EIGENSOLVER: the log names it, the eigenvalues match the closed form
  grep -q "eigenvalues nearest the shift .* by $2" "$1/chain.log" ||
    { echo "$1: the log does not name '$2'" >&2; exit 1; }
  python3 - "$masses" "$1/chain.modes.csv" <<'PY'
import csv, math, sys
n = int(sys.argv[1])
rows = list(csv.DictReader(open(sys.argv[2], newline="")))
assert len(rows) == 10, f"{len(rows)} modes, expected 10"
for j, row in enumerate(rows, start=1):
    omega = 2 * math.sqrt(1000 / (2 * 2)) * math.sin((2 * j - 1) * math.pi / (2 * (2 * n + 1)))
    lam = float(row["eigenvalue"])
    assert abs(lam - omega ** 2) <= 1e-8 * omega ** 2 + 1e-11, f"mode {j}: {lam}, expected {omega ** 2}"
PY
}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
variants=(spectra slepc_1 slepc_2)
declare -A commands=(
  [spectra]="$clinch run --quiet"
  [slepc_1]="$clinch run --quiet --solver petsc"
  [slepc_2]="mpirun --oversubscribe -n 2 $clinch run --quiet --solver petsc")
declare -A names=([spectra]="Spectra Lanczos" [slepc_1]="SLEPc .* on 1 rank"
                  [slepc_2]="SLEPc .* on 2 ranks")
declare -A times
for ((i = 0; i < runs; ++i)); do
  for v in "${variants[@]}"; do
    rm -rf "$dir/$v"
    /usr/bin/time -f %e -o "$dir/time" ${commands[$v]} --out "$dir/$v" "$dir/chain.inp" > /dev/null
    check "$dir/$v" "${names[$v]}"
    times[$v]+="$(cat "$dir/time") "
  done
done
median() { tr ' ' '\n' <<< "$1" | grep . | sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
echo "chain of $masses masses ($((2 * masses)) equations), 10 lowest modes match the closed form"
for v in "${variants[@]}"; do
  printf '%-8s median %.2f s over %d runs (%s)\n' "$v" "$(median "${times[$v]}")" "$runs" "${times[$v]% }"
done
