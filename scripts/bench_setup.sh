#!/usr/bin/env bash
# Setup time of `clinch run` with the default history output (every connector's CTF and CU
# columns, output-variables.md §4) on chain decks of 10^4 to 10^6 connectors
# (generate_connector_deck N --default-output: no output request, one increment). The setup is
# what the run's .log reports before the first increment: reading (parse and check), plan
# (analysis plan and connector system) and columns (history columns and the table's header). Each
# size runs REPEAT times (default 3) after one unmeasured run of the largest deck, which has the
# host back the memory the runs will touch (on a virtual machine the first touch of memory the
# host took back costs several times the run, docs/benchmarks.md). For each size: the
# medians of the three times and of their sum, the sum's ratio to the previous size's (10 for a
# linear setup), the median whole run's wall time and peak RSS per connector (GNU time %M).
# Usage: scripts/bench_setup.sh [sizes...]   (default: 10000 100000 1000000). CLINCH_BUILD_DIR
#        (default build) holds clinch and generate_connector_deck; REPEAT the runs per size.
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
repeat=${REPEAT:-3}
# One run: "reading plan columns run_s peak_kB" on stdout.
run_once() {
  local start end
  start=$EPOCHREALTIME
  if ! /usr/bin/time -f "%M" -o "$dir/time" "$bin/clinch" run --quiet --out "$dir/out" \
       --job setup "$dir/deck.inp" >/dev/null 2>"$dir/stderr"; then
    echo "bench_setup: the run of $1 connectors failed:" >&2
    tail -n 5 "$dir/stderr" >&2
    exit 1
  fi
  end=$EPOCHREALTIME
  grep -m 1 "time: reading" "$dir/out/setup.log" |
    sed -E 's/.*reading ([0-9.]+) s, plan ([0-9.]+) s, columns ([0-9.]+) s.*/\1 \2 \3/' |
    tr '\n' ' '
  echo "$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }') $(tail -n 1 "$dir/time")"
  rm -rf "$dir/out"
}
largest=$(printf "%s\n" "${sizes[@]}" | sort -n | tail -n 1)
"$bin/generate_connector_deck" "$largest" --default-output > "$dir/deck.inp"
run_once "$largest" >/dev/null
previous=
for n in "${sizes[@]}"; do
  "$bin/generate_connector_deck" "$n" --default-output > "$dir/deck.inp"
  for ((i = 0; i < repeat; ++i)); do run_once "$n"; done > "$dir/runs"
  # Medians column by column (the middle value; the lower middle for an even count).
  read -r reading plan columns setup run kb < <(awk '{ print $1, $2, $3, $1 + $2 + $3, $4, $5 }' \
    "$dir/runs" | awk -v k="$repeat" '{ for (c = 1; c <= NF; ++c) v[c, NR] = $c }
      END { for (c = 1; c <= 6; ++c) {
              for (i = 1; i <= NR; ++i) a[i] = v[c, i]
              for (i = 2; i <= NR; ++i) for (j = i; j > 1 && a[j - 1] > a[j]; --j) {
                t = a[j]; a[j] = a[j - 1]; a[j - 1] = t }
              printf "%s%s", a[int((NR + 1) / 2)], (c < 6 ? " " : "\n") } }')
  awk -v n="$n" -v r="$reading" -v p="$plan" -v c="$columns" -v s="$setup" -v prev="$previous" \
      -v run="$run" -v kb="$kb" 'BEGIN {
    printf "%10d %10.3f %10.3f %10.3f %10.3f %12s %10.2f %14.0f\n", n, r, p, c, s,
           (prev > 0 ? sprintf("%.1f", s / prev) : "-"), run, kb * 1024 / n }'
  previous=$setup
done
