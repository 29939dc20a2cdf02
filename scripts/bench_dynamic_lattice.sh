#!/usr/bin/env bash
# clinch against CalculiX (Debian calculix-ccx 2.20) on *DYNAMIC, DIRECT: the N x N spring-mass
# lattice of decks/bench/generate_dynamic_lattice.py (SPRINGA, MASS, the same deck for both
# codes) in free vibration in its lowest mode, HHT with ALPHA=-0.05 written out
# (docs/benchmarks.md "Implicit dynamics on a spring-mass lattice"). For each increment: median
# wall time of runs (default 3), and the error of each code against the exact motion of the
# lattice (max |u - u_exact| over three probe nodes and every increment, over the amplitude);
# then the ratio of wall times.
# Usage: scripts/bench_dynamic_lattice.sh [N [PERIOD [DT...]]]   (default: 100 1.0 0.01 0.005)
# Environment: CLINCH_BUILD_DIR (default build), DYNAMIC_LATTICE_RUNS (3),
# DYNAMIC_LATTICE_NLGEOM=1 to run the step under NLGEOM, DYNAMIC_LATTICE_KEEP=DIR to keep decks
# and outputs in DIR.
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-100}
period=${2:-1.0}
shift $(($# > 2 ? 2 : $#))
increments=("$@")
((${#increments[@]})) || increments=(0.01 0.005)
runs=${DYNAMIC_LATTICE_RUNS:-3}
bin=${CLINCH_BUILD_DIR:-build}
lattice="python3 $PWD/decks/bench/generate_dynamic_lattice.py"
nlgeom=()
[ "${DYNAMIC_LATTICE_NLGEOM:-0}" = 0 ] || nlgeom=(nlgeom)
[ -x "$bin/clinch" ] || { echo "bench_dynamic_lattice: $bin/clinch is missing" >&2; exit 3; }
command -v ccx >/dev/null ||
  { echo "bench_dynamic_lattice: ccx is missing (apt-get install calculix-ccx)" >&2; exit 3; }
. scripts/bench_workdir.sh
bench_workdir "${DYNAMIC_LATTICE_KEEP:-}"
bin=$(cd "$bin" && pwd)

median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }

# Probe rows "t node u1 u2" of one run. CalculiX: the *NODE PRINT blocks of job.dat (7 digits);
# clinch: the U1@node, U2@node columns of job.history.csv, increment 0 left out.
ccx_rows() {
  awk '/displacements .* for set PROBES and time/ {t = $NF; next}
       NF == 4 && t != "" {print t, $1, $2, $3}' "$1/job.dat"
}
clinch_rows() {
  awk -F, 'NR == 1 {for (i = 5; i <= NF; ++i)
                      if ($i ~ /^U[12]@/) {split($i, p, "@"); col[i] = p[1]; node[i] = p[2]}
                    next}
           $2 > 0 {delete u1; delete u2
                   for (i in col) if (col[i] == "U1") u1[node[i]] = $i; else u2[node[i]] = $i
                   for (k in u1) print $3, k, u1[k], u2[k]}' "$1/job.history.csv"
}

# Runs one code $runs times on deck $2 in directory $3: "<median wall s> <error> <rows>".
measure() {
  local code=$1 deck=$2 wd=$3 times=() run
  for ((run = 1; run <= runs; ++run)); do
    rm -rf "$wd" && mkdir -p "$wd"
    if [ "$code" = ccx ]; then
      cp "$deck" "$wd/job.inp"
      (cd "$wd" && /usr/bin/time -f %e -o time.txt ccx -i job >stdout.txt 2>&1) ||
        { echo "failed"; return; }
    else
      (cd "$wd" && /usr/bin/time -f %e -o time.txt "$bin/clinch" run "$deck" --out . --job job \
                     >stdout.txt 2>&1) || { echo "failed"; return; }
    fi
    times+=("$(tail -n 1 "$wd/time.txt")")
  done
  "${code}_rows" "$wd" > "$wd/probes.txt"
  echo "$(printf '%s\n' "${times[@]}" | median) $($lattice error "$n" "$wd/probes.txt")"
}

echo "dynamic lattice benchmark: ${n}x${n} masses${nlgeom:+ under NLGEOM}, period $period," \
  "$(nproc) cores, load average $(cut -d ' ' -f 1-3 /proc/loadavg)," \
  "CalculiX $(ccx -v 2>/dev/null | grep -o 'Version [0-9.]*' | head -n 1), medians of $runs runs"
printf "%8s %6s | %8s %10s | %8s %10s | %6s\n" dt incs ccx_s ccx_err clinch_s cl_err t_rat
for dt in "${increments[@]}"; do
  deck=$dir/lattice-$n-$dt.inp
  $lattice deck "$n" "$dt" "$period" "$deck" "${nlgeom[@]}"
  read -r x_s x_err x_rows < <(measure ccx "$deck" "$dir/ccx-$dt")
  read -r c_s c_err c_rows < <(measure clinch "$deck" "$dir/clinch-$dt")
  expected=$(awk -v p="$period" -v d="$dt" 'BEGIN {printf "%d", 3 * int(p / d + 0.5)}')
  [ "${x_rows:-0}" = "$expected" ] || x_err="rows:${x_rows:-none}"
  [ "${c_rows:-0}" = "$expected" ] || c_err="rows:${c_rows:-none}"
  t_rat=$(awk -v a="$c_s" -v b="$x_s" 'BEGIN {printf "%.3f", (b > 0 ? a / b : 0)}' 2>/dev/null ||
            echo -)
  printf "%8s %6s | %8s %10s | %8s %10s | %6s\n" "$dt" "$((expected / 3))" "$x_s" "$x_err" \
    "$c_s" "$c_err" "$t_rat"
done
echo "s: median wall time; err: max over 3 probes and all increments of |u - u_exact|, over the"
echo "amplitude (CalculiX prints 7 digits: it resolves about 1e-6); t_rat: clinch/CalculiX (target"
echo "<= 0.2 at equal or smaller error). Load average at the end:" \
  "$(cut -d ' ' -f 1-3 /proc/loadavg)."
