#!/usr/bin/env bash
# Connector-friction benchmarks (docs/benchmarks.md):
# 1. time per Newton iteration on a lattice of friction connectors, and the whole run with one
#    ground node shared by every floor connector (--shared-ground) against own ground nodes
#    (decks/bench/generate_friction_lattice.py: an n x n grid of sliders, each on the floor through a
#    CARTESIAN connector with a stiff normal spring and CONTACT FORCE=1 friction, neighbours joined
#    by elastic CARTESIAN springs, the top row sheared), with friction (clinch picks UMFPACK on the
#    full pattern: the tangent is unsymmetric) against the same lattice without friction (CHOLMOD
#    on the upper triangle). Per size and variant: medians over FRICTION_RUNS runs (default 5) of
#    the wall time, of "factorize+solve: X s per iteration" and of "Newton: Y s per iteration" from
#    <job>.log, the Newton iterations, and the friction/no-friction ratios of the medians;
# 2. the work-precision table of a SLIDE-PLANE driven around a square
#    (decks/bench/friction_work_precision.py; its errors are against the closed-form solution).
# Usage: scripts/bench_friction.sh [connectors...]   (friction connectors, default 10000 100000;
#        the grid side is the rounded square root)
# Environment: CLINCH_BUILD_DIR (default build), FRICTION_RUNS (5), FRICTION_TYPE (cartesian or
# slide-plane), FRICTION_FRONT (rows the slip front reaches, default 4), FRICTION_KEEP=DIR to keep
# decks and outputs, FRICTION_WP=0 to skip the work-precision table, FRICTION_WP_SIZES
# (default 4,8,16,32,64,128).
set -euo pipefail
cd "$(dirname "$0")/.."
counts=("$@")
((${#counts[@]})) || counts=(10000 100000)
runs=${FRICTION_RUNS:-5}
type=${FRICTION_TYPE:-cartesian}
front=${FRICTION_FRONT:-4}
bin=${CLINCH_BUILD_DIR:-build}
if [ ! -x "$bin/clinch" ]; then
  echo "bench_friction: $bin/clinch is missing (build it first: scripts/setup.sh)" >&2
  exit 3
fi
bin=$(cd "$bin" && pwd)
if [ -n "${FRICTION_KEEP:-}" ]; then
  dir=$FRICTION_KEEP
  mkdir -p "$dir"
else
  dir=$(mktemp -d)
  trap 'rm -rf "$dir"' EXIT
fi
dir=$(cd "$dir" && pwd)

median() { sort -g | awk '{a[NR]=$1} END {if (NR) print a[int((NR+1)/2)]; else print "nan"}'; }
log_value() { sed -n "s/.*$2: *\([0-9.eE+-]*\) *s per iteration.*/\1/p" "$1" | tail -n 1; }

# Runs one deck $runs times; prints "<wall s> <factorize+solve s/it> <Newton s/it> <iterations>
# <equations> <solver>" (medians), or "failed".
measure() {
  local deck=$1 wd=$2 walls=() fss=() nws=() start end run
  for ((run = 1; run <= runs; ++run)); do
    rm -rf "$wd" && mkdir -p "$wd"
    start=$EPOCHREALTIME
    if ! "$bin/clinch" run "$deck" --out "$wd" --job job --quiet >"$wd/stdout.txt" \
        2>"$wd/stderr.txt" || [ "$(tail -n 1 "$wd/job.sta")" != COMPLETED ]; then
      echo failed
      return
    fi
    end=$EPOCHREALTIME
    walls+=("$(awk -v a="$start" -v b="$end" 'BEGIN {print b - a}')")
    fss+=("$(log_value "$wd/job.log" factorize+solve)")
    nws+=("$(log_value "$wd/job.log" Newton)")
  done
  local its equations solver
  its=$(sed -n 's/.* \([0-9]*\) iterations, .*/\1/p' "$wd/job.log" | tail -n 1)
  # "step 2: umfpack on the full pattern (N equations, ...)"
  solver=$(sed -n 's/^step 2: \([a-z]*\) on the \([a-z ]*\) (\([0-9]*\) equations.*/\1 on the \2 \3/p' \
    "$wd/job.log" | head -n 1)
  equations=${solver##* }
  solver=${solver% *}
  echo "$(printf '%s\n' "${walls[@]}" | median) $(printf '%s\n' "${fss[@]}" | median)" \
    "$(printf '%s\n' "${nws[@]}" | median) $its $equations ${solver// /_}"
}

echo "friction lattice ($type floor connectors, slip front about $front rows): $(nproc) cores," \
  "load average $(cut -d ' ' -f 1-3 /proc/loadavg), medians of $runs runs, $(date -u +%F)"
results=$dir/results.txt
: > "$results"
for count in "${counts[@]}"; do
  n=$(awk -v c="$count" 'BEGIN {printf "%d", sqrt(c) + 0.5}')
  for variant in friction plain shared; do
    deck=$dir/lattice-$variant-$n.inp
    flag=()
    [ "$variant" = friction ] && flag=(--friction)
    [ "$variant" = shared ] && flag=(--friction --shared-ground)
    python3 decks/bench/generate_friction_lattice.py --n "$n" --type "$type" "${flag[@]}" \
      --front "$front" --increment 1 --out "$deck"
    row=$(measure "$deck" "$dir/out-$variant-$n")
    echo "$n $variant $row" >> "$results"
    echo "  done: n = $n $variant: $row" >&2
  done
done

printf "\n| friction connectors | variant | equations | solver | Newton iterations | wall s |"
printf " factorize+solve s/it | Newton s/it |\n|---|---|---|---|---|---|---|---|\n"
while read -r n variant wall fs nw its eq solver; do
  if [ "$wall" = failed ]; then
    printf "| %d | %s | run failed | | | | | |\n" $((n * n)) "$variant"
    continue
  fi
  printf "| %d | %s | %s | %s | %s | %.3f | %.4g | %.4g |\n" $((n * n)) "$variant" "$eq" \
    "${solver//_/ }" "$its" "$wall" "$fs" "$nw"
done < "$results"
printf "\n| friction connectors | Newton s/it, friction / without | factorize+solve s/it, friction / without | wall s, one shared ground node / own ground nodes |\n|---|---|---|---|\n"
awk '{key = $1; if ($3 == "failed") next
      if ($2 == "friction") {fw[key] = $5; ff[key] = $4; fwall[key] = $3}
      else if ($2 == "plain") {pw[key] = $5; pf[key] = $4}
      else {swall[key] = $3}
      order[key] = NR}
     END {for (k in order) if ((k in fw) && (k in pw))
            printf "| %d | %.2f | %.2f | %s |\n", k * k, fw[k] / pw[k], ff[k] / pf[k],
                   (k in swall) ? sprintf("%.2f", swall[k] / fwall[k]) : "failed"}' "$results" |
  sort -t '|' -k 2 -n
echo "Wall s: the whole run (start, reading, plan, both steps, output). s/it: the .log's figures,"
echo "Newton's time (evaluation, assembly, factorization, solve) and one factorization plus solve,"
echo "per iteration of the run. Load average at the end: $(cut -d ' ' -f 1-3 /proc/loadavg)."

if [ "${FRICTION_WP:-1}" != 0 ]; then
  echo
  python3 decks/bench/friction_work_precision.py "$bin/clinch" --repeat "$runs" \
    --sizes "${FRICTION_WP_SIZES:-4,8,16,32,64,128}" --work "$dir/work-precision"
fi
