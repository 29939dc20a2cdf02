#!/usr/bin/env bash
# `clinch check` throughput and peak memory on generated connector decks (10^4 to 10^6
# connectors). For each size: deck size, median wall time of 5 runs (GNU time), throughput in
# MB/s, median peak RSS, and RSS / deck size. A 1-connector deck gives the process baseline
# (start-up, shared libraries): net_MB_s is the deck over the time above it, and
# (RSS-base)/deck the memory above it per byte of deck.
# Two kinds of deck, one table each: `chain` (generate_connector_deck N: one AXIAL section) and
# `mix` (generate_connector_deck N --mix: sections of every connection type with orientations,
# six-component BUSHINGs, stops and plasticity, as users' decks have them).
# Usage: scripts/bench_check.sh [--decks chain|mix|both] [sizes...]
#        (default: both, 10000 100000 1000000). CLINCH_BUILD_DIR (default build) holds clinch and
#        generate_connector_deck.
set -euo pipefail
cd "$(dirname "$0")/.."
kinds=(chain mix)
if [ "${1:-}" = --decks ]; then
  case "${2:-}" in
    chain | mix) kinds=("$2") ;;
    both) ;;
    *) echo "usage: $0 [--decks chain|mix|both] [sizes...]" >&2; exit 2 ;;
  esac
  shift 2
fi
sizes=("$@")
((${#sizes[@]})) || sizes=(10000 100000 1000000)
bin=${CLINCH_BUILD_DIR:-build}
[ -x "$bin/clinch" ] && [ -x "$bin/generate_connector_deck" ] || bash scripts/setup.sh >/dev/null
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
measure() {  # deck → "seconds kilobytes" per run, 5 runs (GNU time gives 10 ms steps: the
             # wall time is bash's EPOCHREALTIME around the run, which forks nothing)
  for run in 1 2 3 4 5; do
    local start end
    start=$EPOCHREALTIME
    /usr/bin/time -f "%M" -o "$dir/time" "$bin/clinch" check "$1" >/dev/null 2>&1 || true
    end=$EPOCHREALTIME
    echo "$(awk -v a="$start" -v b="$end" 'BEGIN {printf "%.4f", b - a}') $(tail -n 1 "$dir/time")"
  done
}
"$bin/generate_connector_deck" 1 > "$dir/base.inp"
measure "$dir/base.inp" > "$dir/base_runs"
base_s=$(awk '{print $1}' "$dir/base_runs" | median)
base_kb=$(awk '{print $2}' "$dir/base_runs" | median)
awk -v kb="$base_kb" -v s="$base_s" 'BEGIN {
  printf "baseline (1 connector: process start, libraries): %.4f s, peak RSS %.1f MB\n", s, kb / 1024 }'
for kind in "${kinds[@]}"; do
  flag=()
  [ "$kind" = mix ] && flag=(--mix)
  echo
  echo "$kind decks (generate_connector_deck N${flag[*]:+ ${flag[*]}}), medians of 5 runs:"
  printf "%10s %10s %10s %10s %10s %12s %10s %12s\n" connectors deck_MB median_s MB_per_s \
    net_MB_s peak_RSS_MB RSS/deck "(RSS-base)/deck"
  for n in "${sizes[@]}"; do
    "$bin/generate_connector_deck" "$n" "${flag[@]}" > "$dir/deck.inp"
    # A deck with errors would measure a check that stops early.
    if ! "$bin/clinch" check "$dir/deck.inp" >/dev/null 2>&1; then
      echo "bench_check: $kind deck of $n connectors does not pass clinch check" >&2
      exit 1
    fi
    bytes=$(stat -c %s "$dir/deck.inp")
    measure "$dir/deck.inp" > "$dir/runs"
    secs=$(awk '{print $1}' "$dir/runs" | median)
    kb=$(awk '{print $2}' "$dir/runs" | median)
    awk -v n="$n" -v b="$bytes" -v s="$secs" -v kb="$kb" -v base="$base_kb" -v t0="$base_s" 'BEGIN {
      mb = b / 1e6; rss = kb * 1024 / 1e6;
      printf "%10d %10.1f %10.4f %10.1f %10.1f %12.1f %10.2f %12.2f\n", n, mb, s, (s > 0 ? mb / s : 0),
             (s > t0 ? mb / (s - t0) : 0), rss, rss / mb, (kb - base) * 1024 / 1e6 / mb }'
  done
done
echo "Targets at 10^6 connectors: MB_per_s >= 100 and RSS/deck < 3 (process start included)."
