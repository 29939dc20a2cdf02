#!/usr/bin/env bash
# clinch against CalculiX (Debian calculix-ccx 2.20) on the lattice decks of
# decks/bench/generate_lattice.cpp (docs/benchmarks.md): for each size and law, median wall time
# and peak RSS of 3 runs (1 run when a run takes longer than LATTICE_SLOW_S seconds), Newton
# iterations, the reaction's relative error against the closed form, and the clinch/CalculiX
# ratios; then clinch's time per Newton iteration against one factorization plus solve.
# Usage: scripts/bench_lattice.sh [sizes...]   (default: 10 15 20 30 40)
# Environment: CLINCH_BUILD_DIR (default build), LATTICE_LAWS (default "linear nonlinear"),
# LATTICE_AXIAL=0 to skip the clinch-only CONN3D2 rows, LATTICE_RUNS (3), LATTICE_SLOW_S (60),
# LATTICE_KEEP=DIR to keep decks and outputs in DIR, LATTICE_CCX_MAX_N=N to run CalculiX only up
# to size N (its nonlinear N = 40 run takes about 45 minutes here). LATTICE_IRREGULAR="F P S"
# runs the irregular lattice instead (generate_lattice --jitter F --patch P --seed S: nodes moved
# by up to F·h, only the centred patch P of the face pulled): it has no closed form, so clinch's
# err column is its difference from CalculiX's reaction. CLINCH_RUN_FLAGS are added to clinch's
# command line, CLINCH_LAUNCHER goes before it ("mpirun -n 2": its MB is then the largest rank's).
set -euo pipefail
cd "$(dirname "$0")/.."
sizes=("$@")
((${#sizes[@]})) || sizes=(10 15 20 30 40)
read -r -a laws <<< "${LATTICE_LAWS:-linear nonlinear}"
runs=${LATTICE_RUNS:-3}
slow=${LATTICE_SLOW_S:-60}
bin=${CLINCH_BUILD_DIR:-build}
if [ ! -x "$bin/generate_lattice" ]; then
  echo "bench_lattice: $bin/generate_lattice is missing (build it first: scripts/setup.sh)" >&2
  exit 3
fi
if ! command -v ccx >/dev/null; then
  echo "bench_lattice: installing calculix-ccx" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get install -y -qq calculix-ccx >/dev/null 2>&1 ||
    { apt-get update -qq && apt-get install -y -qq calculix-ccx >/dev/null; }
fi
. scripts/bench_workdir.sh
bench_workdir "${LATTICE_KEEP:-}"
bin=$(cd "$bin" && pwd)

median() { sort -g | awk '{a[NR]=$1} END {if (NR) print a[int((NR+1)/2)]; else print "nan"}'; }
field() { sed -n "s/^ *\"$2\": *\"\{0,1\}\([^\",]*\).*/\1/p" "$1"; }  # flat JSON → value
relative_error() { awk -v r="$1" -v ref="$2" 'BEGIN {
  if (r == "" || r == "nan") { print "nan"; exit }
  d = (r - ref) / ref; printf "%.2e\n", (d < 0 ? -d : d) }'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.3f", (b > 0 ? a / b : 0)}'; }

# One timed run in directory $1: "<wall s> <peak kB> <user s> <system s> <exit status>".
timed() {
  local wd=$1
  shift
  local status=0
  (cd "$wd" && /usr/bin/time -f "%e %M %U %S" -o time.txt "$@" >stdout.txt 2>stderr.txt) ||
    status=$?
  echo "$(tail -n 1 "$wd/time.txt") $status"
}

# CalculiX prints " iteration N" once per equilibrium iteration (cut-back attempts included) and
# the reaction total as the line after "total force (fx,fy,fz) for set XMAX", at every increment.
ccx_iterations() { grep -c '^ iteration' "$1/stdout.txt" || true; }
ccx_reaction() { awk -v set="$reaction_set" '$0 ~ "total force \\(fx,fy,fz\\) for set " set " " {take = 1; next}
                      take && NF {value = $1; take = 0} END {print (value == "" ? "nan" : value)}' \
                     "$1/job.dat" 2>/dev/null || echo nan; }

# clinch's <job>.sta (cli-contract.md): one line per attempt; the last three fields are times and
# the one before them is "total iterations" (the cut-back flag column may be blank).
clinch_iterations() { awk '$1 ~ /^[0-9]+$/ {sum += $(NF - 3)} END {print sum + 0}' "$1/job.sta"; }
clinch_completed() { [ "$(tail -n 1 "$1/job.sta" 2>/dev/null)" = COMPLETED ]; }
clinch_reaction() {
  awk -F, -v column="RF1@$reaction_set" \
    'NR == 1 {for (i = 1; i <= NF; ++i) if (toupper($i) == column) c = i; next}
           {last = $c} END {print (c && last != "" ? last : "nan")}' "$1/job.history.csv" \
    2>/dev/null || echo nan
}
# `clinch run` logs "factorize+solve: X s per iteration" (the mean wall time of one
# factorization plus solve of the run's tangents) in <job>.log.
clinch_factorize_solve() {
  sed -n 's/.*factorize+solve: *\([0-9.eE+-]*\) *s.*/\1/p' "$1/job.log" 2>/dev/null | tail -n 1
}
# ... and "Newton: Y s per iteration" (Newton's wall time, evaluation and assembly included, over
# its factorizations).
clinch_newton() {
  sed -n 's/.*Newton: *\([0-9.eE+-]*\) *s per iteration.*/\1/p' "$1/job.log" 2>/dev/null | tail -n 1
}

# Runs one code on one deck up to $runs times and prints "<median wall s> <median CPU s>
# <median MB> <iterations> <reaction> <factorize+solve s or -> <Newton s per iteration or ->", or
# "failed".
measure() {
  local code=$1 deck=$2 wd=$3
  local times=() cpus=() rss=() ok=1 run secs kb user sys status
  for ((run = 1; run <= runs; ++run)); do
    rm -rf "$wd" && mkdir -p "$wd"
    if [ "$code" = ccx ]; then
      cp "$deck" "$wd/job.inp"
      read -r secs kb user sys status < <(timed "$wd" ccx -i job)
      grep -q 'total force' "$wd/job.dat" 2>/dev/null || ok=0
    else
      # shellcheck disable=SC2086
      read -r secs kb user sys status < <(timed "$wd" ${CLINCH_LAUNCHER:-} "$bin/clinch" run \
                                             "$deck" --out "$wd" --job job ${CLINCH_RUN_FLAGS:-})
      { [ "$status" = 0 ] && clinch_completed "$wd"; } || ok=0
    fi
    ((ok)) || break
    times+=("$secs")
    cpus+=("$(awk -v u="$user" -v s="$sys" 'BEGIN {print u + s}')")
    rss+=("$kb")
    awk -v s="$secs" -v slow="$slow" 'BEGIN {exit !(s > slow)}' && break
  done
  if ((!ok)); then
    echo failed
    return
  fi
  local its reaction fs=- nw=-
  if [ "$code" = ccx ]; then
    its=$(ccx_iterations "$wd")
    reaction=$(ccx_reaction "$wd")
  else
    its=$(clinch_iterations "$wd")
    reaction=$(clinch_reaction "$wd")
    fs=$(clinch_factorize_solve "$wd")
    fs=${fs:--}
    nw=$(clinch_newton "$wd")
    nw=${nw:--}
  fi
  echo "$(printf '%s\n' "${times[@]}" | median) $(printf '%s\n' "${cpus[@]}" | median)" \
    "$(printf '%s\n' "${rss[@]}" | median | awk '{printf "%.1f", $1 / 1024}') $its $reaction $fs $nw"
}

ccx_version=$(ccx -v 2>/dev/null | grep -o 'Version [0-9.]*' | head -n 1) || true
echo "lattice benchmark: $(nproc) cores, load average $(cut -d ' ' -f 1-3 /proc/loadavg)," \
  "CalculiX ${ccx_version:-?}, medians of $runs runs (1 run above ${slow} s)"
results=$dir/results.txt
: > "$results"
for law in "${laws[@]}"; do
  for n in "${sizes[@]}"; do
    elements=(springa)
    [ "${LATTICE_AXIAL:-1}" = 0 ] || elements+=(axial)
    for element in "${elements[@]}"; do
      deck=$dir/lattice-$element-$law-$n.inp
      ref=$dir/lattice-$element-$law-$n.json
      irregular=()
      [ -z "${LATTICE_IRREGULAR:-}" ] ||
        read -r -a irregular < <(echo "$LATTICE_IRREGULAR" | awk '{print "--jitter", $1, "--patch", $2, "--seed", $3}')
      "$bin/generate_lattice" --n "$n" --element "$element" --law "$law" --out "$deck" \
        --reference "$ref" "${irregular[@]}"
      exact=$(field "$ref" reaction)
      reaction_set=$(field "$ref" reaction_set)
      dofs=$(field "$ref" free_dofs)
      ccx_row="n/a"
      if [ "$element" = springa ] && ((n <= ${LATTICE_CCX_MAX_N:-1000})); then
        ccx_row=$(measure ccx "$deck" "$dir/ccx-$element-$law-$n")
      fi
      clinch_row=$(measure clinch "$deck" "$dir/clinch-$element-$law-$n")
      echo "$law $element $n $dofs $exact | $ccx_row | $clinch_row" >> "$results"
      echo "  done: $law $element N=$n (ccx: $ccx_row; clinch: $clinch_row)" >&2
    done
  done
done

row_format="%-9s %-7s %3s %6s | %8s %8s %7s %4s %8s | %8s %8s %7s %4s %8s | %6s %6s %6s\n"
# shellcheck disable=SC2059
printf "\n$row_format" law element N dofs ccx_s ccx_cpu ccx_MB it err clinch_s cl_cpu cl_MB it \
  err t_rat cpu_r m_rat
while IFS='|' read -r head ccx clinch; do
  read -r law element n dofs exact <<< "$head"
  read -r x_s x_cpu x_mb x_it x_r _ <<< "$ccx"
  read -r c_s c_cpu c_mb c_it c_r _ <<< "$clinch"
  x_err=-; c_err=-; t_rat=-; cpu_rat=-; m_rat=-
  if [ "$x_s" = failed ]; then x_s="CalculiX failed"; x_cpu=""; x_mb=""; x_it=""; x_r=""; fi
  if [ "$x_s" = n/a ]; then x_s=-; x_cpu=-; x_mb=-; x_it=-; fi
  # Irregular lattice: no closed form; clinch is compared with CalculiX.
  [ "$exact" = null ] || [ -z "${x_r:-}" ] || x_err=$(relative_error "$x_r" "$exact")
  if [ "$c_s" = failed ]; then
    c_s="clinch run failed"; c_cpu=""; c_mb=""; c_it=""
  else
    if [ "$exact" != null ]; then c_err=$(relative_error "$c_r" "$exact")
    elif [[ "${x_r:-}" =~ ^-?[0-9] ]]; then c_err=$(relative_error "$c_r" "$x_r"); fi
    if [[ "$x_s" =~ ^[0-9.]+$ ]]; then
      t_rat=$(ratio "$c_s" "$x_s")
      cpu_rat=$(ratio "$c_cpu" "$x_cpu")
      m_rat=$(ratio "$c_mb" "$x_mb")
    fi
  fi
  # shellcheck disable=SC2059
  printf "$row_format" "$law" "$element" "$n" "$dofs" "$x_s" "${x_cpu:-}" "${x_mb:-}" "${x_it:-}" \
    "$x_err" "$c_s" "${c_cpu:-}" "${c_mb:-}" "${c_it:-}" "$c_err" "$t_rat" "$cpu_rat" "$m_rat"
done < "$results"
echo "s: median wall time, cpu: median user+system time, MB: median peak RSS, it: Newton"
echo "iterations, err: |R - R_exact|/|R_exact| against the closed form (CalculiX prints 7 digits,"
echo "so it resolves errors down to about 5e-7); on the irregular lattice clinch's err is"
echo "|R - R_CalculiX|/|R_CalculiX|. Ratios: clinch/CalculiX (target: t_rat <= 0.2)."
threads=$(grep -m 1 -o 'Using up to [0-9]* cpu(s) for spooles' "$dir"/ccx-*/stdout.txt 2>/dev/null |
  head -n 1 | grep -o '[0-9]* cpu(s)') || true
echo "CalculiX used ${threads:-? cpu(s)} for SPOOLES; load average at the end:" \
  "$(cut -d ' ' -f 1-3 /proc/loadavg)."

printf "\n%-9s %-7s %3s | %12s %12s %16s %8s %8s\n" law element N run_s/it newton_s/it \
  factorize+solve run_rat newt_rat
while IFS='|' read -r head _ clinch; do
  read -r law element n _ <<< "$head"
  read -r ls _ _ li _ fs nw <<< "$clinch"
  [ "$ls" = failed ] && continue
  awk -v l="$law" -v e="$element" -v n="$n" -v s="$ls" -v i="$li" -v f="${fs:--}" \
      -v w="${nw:--}" 'BEGIN {
    per = i > 0 ? s / i : 0
    if (f == "-" || w == "-") printf "%-9s %-7s %3s | %12.4f %12s %16s %8s %8s\n", l, e, n, per, "-",
                                     "not reported", "-", "-"
    else printf "%-9s %-7s %3s | %12.4f %12.4f %16.4f %8.2f %8.2f\n", l, e, n, per, w, f,
                (f > 0 ? per / f : 0), (f > 0 ? w / f : 0) }'
done < "$results"
echo "run_s/it: the whole run's median wall time (reading, plan, symbolic analysis, output"
echo "included) over its Newton iterations; newton_s/it: the time inside Newton (evaluation,"
echo "assembly, factorization, solve) per iteration of the last run; factorize+solve: one"
echo "CHOLMOD factorization plus solve of the run's tangents (target: newt_rat <= 1.5)."
