#!/usr/bin/env bash
# Setup time of `clinch run` with the default history output (every connector's CTF and CU
# columns, output-variables.md §4) on chain decks of 10^4 to 10^6 connectors
# (generate_connector_deck N --default-output: no output request, one increment). The setup is
# what the run's .log reports before the first increment: reading (parse and check), plan
# (analysis plan and connector system) and columns (history columns and the table's header). For
# each size: the three times and their sum, the sum's ratio to the previous size (10 for a
# linear setup), the whole run's wall time and its peak RSS per connector (GNU time %M).
# Usage: scripts/bench_setup.sh [sizes...]   (default: 10000 100000 1000000). CLINCH_BUILD_DIR
#        (default build) holds clinch and generate_connector_deck.
set -euo pipefail
cd "$(dirname "$0")/.."
sizes=("$@")
((${#sizes[@]})) || sizes=(10000 100000 1000000)
bin=${CLINCH_BUILD_DIR:-build}
[ -x "$bin/clinch" ] && [ -x "$bin/generate_connector_deck" ] || bash scripts/setup.sh >/dev/null
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
printf "%10s %10s %10s %10s %10s %12s %10s %14s\n" connectors reading_s plan_s columns_s \
  setup_s setup_ratio run_s peak_B_per_conn
previous=
for n in "${sizes[@]}"; do
  "$bin/generate_connector_deck" "$n" --default-output > "$dir/deck.inp"
  start=$EPOCHREALTIME
  if ! /usr/bin/time -f "%M" -o "$dir/time" "$bin/clinch" run --quiet --out "$dir/out" \
       --job setup "$dir/deck.inp" >/dev/null 2>"$dir/stderr"; then
    echo "bench_setup: the run of $n connectors failed:" >&2
    tail -n 5 "$dir/stderr" >&2
    exit 1
  fi
  end=$EPOCHREALTIME
  line=$(grep -m 1 "time: reading" "$dir/out/setup.log")
  read -r reading plan columns < <(echo "$line" |
    sed -E 's/.*reading ([0-9.]+) s, plan ([0-9.]+) s, columns ([0-9.]+) s.*/\1 \2 \3/')
  awk -v n="$n" -v r="$reading" -v p="$plan" -v c="$columns" -v prev="$previous" \
      -v a="$start" -v b="$end" -v kb="$(tail -n 1 "$dir/time")" 'BEGIN {
    s = r + p + c
    printf "%10d %10.3f %10.3f %10.3f %10.3f %12s %10.2f %14.0f\n", n, r, p, c, s,
           (prev > 0 ? sprintf("%.1f", s / prev) : "-"), b - a, kb * 1024 / n }'
  previous=$(awk -v r="$reading" -v p="$plan" -v c="$columns" 'BEGIN { print r + p + c }')
  rm -rf "$dir/out"
done
