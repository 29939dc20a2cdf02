#!/usr/bin/env bash
# A distributed model (docs/parallel.md): one deck on 1, 2, 4, ... MPI ranks with `--solver
# petsc`, each run's wall time, the peak memory of every rank (GNU time, one per rank), the ratio
# of the largest rank's peak to the one-rank peak, and the largest difference of the history from
# the one-rank run (`clinch compare --rtol 1e-8 --atol 1e-12`: exit 0 when every column agrees to
# 1e-8 of its scale). With CLINCH_BASELINE=path/to/other/clinch the same runs of that build are
# interleaved with these, run for run, and reported beside them (on the rank counts of
# DIST_BASELINE_RANKS only, when set: a build that holds the whole model on every rank may not
# fit in memory on many).
# Usage: scripts/bench_distributed.sh DECK.inp [ranks...]   (default ranks: 1 2 4)
# Environment: CLINCH_BUILD_DIR (default build), DIST_RUNS (runs per count, default 1; the
# median is reported), DIST_KEEP=DIR to keep the outputs in DIR, DIST_COMPARE="--rtol R --atol
# A" for other tolerances of the comparison.
set -euo pipefail
deck=$(realpath "$1")
shift
baseline=${CLINCH_BASELINE:+$(realpath "$CLINCH_BASELINE")}
cd "$(dirname "$0")/.."

counts=("$@")
((${#counts[@]})) || counts=(1 2 4)
runs=${DIST_RUNS:-1}
bin=$(cd "${CLINCH_BUILD_DIR:-build}" && pwd)
. scripts/bench_workdir.sh
bench_workdir "${DIST_KEEP:-}"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1 \
  OPENBLAS_NUM_THREADS=1
builds=("new|$bin/clinch")
[ -n "$baseline" ] && builds+=("baseline|$baseline")
compare=${DIST_COMPARE:---rtol 1e-8 --atol 1e-12}
median() { sort -g | awk '{a[NR]=$1} END {if (NR) print a[int((NR+1)/2)]; else print "nan"}'; }

# One run of build $2 on $1 ranks into $dir/$3: "<wall s> <largest rank's peak kB>".
run_once() {
  local ranks=$1 clinch=$2 out=$dir/$3
  rm -rf "$out"
  mkdir -p "$out"
  local start end
  start=$(date +%s.%N)
  if [ "$ranks" -eq 1 ]; then
    /usr/bin/time -f "%M" -o "$out/rss.0" "$clinch" run "$deck" --solver petsc --out "$out" \
      --job job --quiet
  else
    mpirun --oversubscribe -n "$ranks" sh -c \
      '/usr/bin/time -f "%M" -o "$0/rss.$OMPI_COMM_WORLD_RANK" "$1" run "$2" --solver petsc --out "$0" --job job --quiet' \
      "$out" "$clinch" "$deck"
  fi
  end=$(date +%s.%N)
  local peak
  peak=$(cat "$out"/rss.* | sort -n | tail -n 1)
  echo "$(awk -v a="$start" -v b="$end" 'BEGIN {printf "%.2f", b - a}') $peak"
}

declare -A wall peak one_rank
for ((k = 1; k <= runs; ++k)); do
  for ranks in "${counts[@]}"; do
    for build in "${builds[@]}"; do
      name=${build%%|*}
      if [ "$name" = baseline ] && [ -n "${DIST_BASELINE_RANKS:-}" ] &&
        [[ " $DIST_BASELINE_RANKS " != *" $ranks "* ]]; then
        continue
      fi
      read -r w p < <(run_once "$ranks" "${build#*|}" "$name-$ranks-$k")
      wall[$name-$ranks]+="$w "
      peak[$name-$ranks]+="$p "
    done
  done
done
printf '%-9s %5s %9s %12s %11s  %s\n' build ranks "wall s" "peak MB/rank" "of 1 rank" "history against 1 rank"
for build in "${builds[@]}"; do
  name=${build%%|*}
  for ranks in "${counts[@]}"; do
    [ -z "${wall[$name-$ranks]:-}" ] && continue
    w=$(echo "${wall[$name-$ranks]}" | tr ' ' '\n' | grep . | median)
    p=$(echo "${peak[$name-$ranks]}" | tr ' ' '\n' | grep . | median)
    [ "$ranks" -eq "${counts[0]}" ] && one_rank[$name]=$p
    verdict="(reference)"
    if [ "$ranks" -ne "${counts[0]}" ]; then
      if "${build#*|}" compare "$dir/$name-$ranks-1/job.history.csv" \
        "$dir/$name-${counts[0]}-1/job.history.csv" $compare >"$dir/compare-$name-$ranks.txt"; then
        verdict="equal ($compare)"
      else
        verdict="DIFFERS ($compare; $dir/compare-$name-$ranks.txt)"
      fi
    fi
    awk -v n="$name" -v r="$ranks" -v w="$w" -v p="$p" -v one="${one_rank[$name]}" -v v="$verdict" \
      'BEGIN {printf "%-9s %5s %9s %12.0f %11.3f  %s\n", n, r, w, p / 1024, p / one, v}'
  done
done
