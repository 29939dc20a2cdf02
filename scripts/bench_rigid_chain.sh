#!/usr/bin/env bash
# Whole-run wall time of a chain of N rigid bodies joined by connectors against the same chain
# with each body replaced by its reference node (decks/bench/generate_rigid_chain.py): the cost of
# the rigid bodies' elimination at scale. The two decks run in turn (bodies, nodes, bodies, ...),
# so that a drift of the machine's speed falls on both alike; one warm-up pair is not counted.
# Printed: each variant's median wall time (bash's EPOCHREALTIME around the process), Newton
# iterations, and the ratio of the medians bodies/nodes.
# Usage: scripts/bench_rigid_chain.sh [CLINCH]   Environment: CHAIN_BODIES (10000), CHAIN_RUNS (3)
set -euo pipefail
cd "$(dirname "$0")/.."
clinch=$(realpath "${1:-build/clinch}")
bodies=${CHAIN_BODIES:-10000}
runs=${CHAIN_RUNS:-3}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
python3 decks/bench/generate_rigid_chain.py --bodies "$bodies" --out "$dir/bodies.inp"
python3 decks/bench/generate_rigid_chain.py --bodies "$bodies" --nodes-only --out "$dir/nodes.inp"
declare -A times
run() {
  local start end
  start=$EPOCHREALTIME
  "$clinch" run "$dir/$1.inp" --out "$dir/$1" --quiet
  end=$EPOCHREALTIME
  tail -n 1 "$dir/$1/$1.sta" | grep -q COMPLETED || { echo "$1: the run did not complete" >&2; exit 1; }
  echo "$end - $start" | bc -l
}
run bodies > /dev/null
run nodes > /dev/null
for ((i = 0; i < runs; ++i)); do
  for v in bodies nodes; do times[$v]+="$(run $v) "; done
done
median() { tr ' ' '\n' <<< "$1" | grep . | sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
for v in bodies nodes; do
  printf '%-7s median %.3f s over %d runs (%s), %s Newton iterations\n' "$v" "$(median "${times[$v]}")" \
    "$runs" "${times[$v]% }" "$(grep -c 'iteration [1-9]' "$dir/$v/$v.log")"
done
printf 'ratio bodies/nodes of the medians: %.3f\n' \
  "$(echo "$(median "${times[bodies]}") / $(median "${times[nodes]}")" | bc -l)"
