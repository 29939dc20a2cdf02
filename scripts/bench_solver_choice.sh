#!/usr/bin/env bash
# Is the automatic linear solver never far from the best backend? (docs/parallel.md "The
# automatic choice"). Runs every verification case (decks/verification/<case>/<case>.inp) and a
# deck of N elastic hinges (decks/examples/elastic_hinge.inp repeated, N = HINGES, default 10⁴)
# with `--solver auto` (the default) and with each backend chosen by hand (cholmod, umfpack,
# petsc; a backend that cannot run a deck, such as CHOLMOD on an unsymmetric step, is left out),
# medians of RUNS whole runs (default 3) of the wall time, interleaved. A deck passes when the
# automatic run takes at most 10 % or 0.05 s longer than the fastest backend.
# Usage: scripts/bench_solver_choice.sh [case-name-pattern]   (a grep -E pattern on case names)
# Environment: CLINCH_BUILD_DIR (default build), RUNS (3), HINGES (10000).
set -euo pipefail
cd "$(dirname "$0")/.."
pattern=${1:-.}
runs=${RUNS:-3}
hinges=${HINGES:-10000}
bin=${CLINCH_BUILD_DIR:-build}
if [ ! -x "$bin/clinch" ]; then
  echo "bench_solver_choice: $bin/clinch is missing (build it first: scripts/setup.sh)" >&2
  exit 3
fi
bin=$(cd "$bin" && pwd)
. scripts/bench_workdir.sh
bench_workdir ""
backends=(auto cholmod umfpack petsc)

# The example hinge N times over: hinge i joins the held node 2i − 1 to the door node 2i.
python3 - "$hinges" > "$dir/hinges.inp" <<'EOF'
import sys
n = int(sys.argv[1])
out = sys.stdout.write
out("** decks/examples/elastic_hinge.inp repeated (scripts/bench_solver_choice.sh)\n*NODE\n")
for i in range(1, n + 1):
    out(f"{2 * i - 1}, {i}., 0., 0.\n{2 * i}, {i}., 0., 0.\n")
out(f"*NSET, NSET=FRAME, GENERATE\n1, {2 * n - 1}, 2\n*NSET, NSET=DOORS, GENERATE\n2, {2 * n}, 2\n")
out("*ELEMENT, TYPE=CONN3D2, ELSET=HINGE\n")
for i in range(1, n + 1):
    out(f"{i}, {2 * i - 1}, {2 * i}\n")
out("""*ELSET, ELSET=FIRST
1
*ORIENTATION, NAME=AXIS_Z
0., 0., 1., 1., 0., 0.
*CONNECTOR SECTION, ELSET=HINGE, BEHAVIOR=SPRING_STOP
HINGE,
AXIS_Z
*CONNECTOR BEHAVIOR, NAME=SPRING_STOP
*CONNECTOR ELASTICITY, COMPONENT=4
250.
*CONNECTOR STOP, COMPONENT=4
, 1.2
*BOUNDARY
FRAME, ENCASTRE
*STEP, NLGEOM, NAME=open
*STATIC
0.1, 1.
*CLOAD
DOORS, 2, -100.
*CONNECTOR LOAD
HINGE, 4, 400.
*OUTPUT, HISTORY
*ELEMENT OUTPUT, ELSET=FIRST
CU4, CTF
*END STEP
""")
EOF

decks=()
for case_dir in "$PWD"/decks/verification/*/; do
  name=$(basename "$case_dir")
  [ -f "$case_dir$name.inp" ] && echo "$name" | grep -Eq "$pattern" && decks+=("$case_dir$name.inp")
done
echo "hinges" | grep -Eq "$pattern" && decks+=("$dir/hinges.inp")

median() { sort -g | awk '{a[NR]=$1} END {if (NR) print a[int((NR+1)/2)]; else print "nan"}'; }
# One whole run: its wall time in s, or "-" when it did not complete.
run_once() {
  local deck=$1 backend=$2 wd=$dir/out start end
  rm -rf "$wd" && mkdir -p "$wd"
  start=$EPOCHREALTIME
  if (cd "$(dirname "$deck")" && "$bin/clinch" run "$deck" --solver "$backend" --quiet \
        --out "$wd" --job job >/dev/null 2>&1); then
    end=$EPOCHREALTIME
    awk -v a="$start" -v b="$end" 'BEGIN {printf "%.4f\n", b - a}'
  else
    echo -
  fi
}

echo "automatic solver against the backends: $(nproc) cores, load average" \
  "$(cut -d ' ' -f 1-3 /proc/loadavg), medians of $runs runs, $(date -u +%F)"
printf "\n| deck | auto s | cholmod s | umfpack s | petsc s | best | auto / best | verdict |\n"
printf "|---|---|---|---|---|---|---|---|\n"
passed=0 failed=0
for deck in "${decks[@]}"; do
  declare -A times=()
  for backend in "${backends[@]}"; do times[$backend]=""; done
  for ((run = 1; run <= runs; ++run)); do
    for backend in "${backends[@]}"; do times[$backend]+="$(run_once "$deck" "$backend") "; done
  done
  declare -A med=()
  best=nan best_name=-
  for backend in "${backends[@]}"; do
    med[$backend]=$(tr ' ' '\n' <<< "${times[$backend]}" | { grep -v -e '^-$' -e '^$' || true; } |
                    median)
    # A backend counts only when every run of it completed.
    [[ " ${times[$backend]} " == *" - "* ]] && med[$backend]=nan
    if [ "$backend" != auto ] && [ "${med[$backend]}" != nan ] && { [ "$best" = nan ] ||
        awk -v a="${med[$backend]}" -v b="$best" 'BEGIN {exit !(a < b)}'; }; then
      best=${med[$backend]} best_name=$backend
    fi
  done
  verdict=$(awk -v a="${med[auto]}" -v b="$best" 'BEGIN {
    if (a == "nan") {print "auto failed"; exit}
    print (a <= 1.1 * b || a <= b + 0.05) ? "pass" : "SLOWER"}')
  [ "$verdict" = pass ] && passed=$((passed + 1)) || failed=$((failed + 1))
  ratio=$(awk -v a="${med[auto]}" -v b="$best" 'BEGIN {printf (a == "nan" ? "-" : "%.2f"), a / b}')
  printf "| %s | %s | %s | %s | %s | %s | %s | %s |\n" "$(basename "$deck" .inp)" "${med[auto]}" \
    "${med[cholmod]}" "${med[umfpack]}" "${med[petsc]}" "$best_name" "$ratio" "$verdict"
  unset times med
done
echo
echo "$passed decks pass, $failed do not (auto within 10 % or 0.05 s of the fastest backend)."
echo "Load average at the end: $(cut -d ' ' -f 1-3 /proc/loadavg)."
