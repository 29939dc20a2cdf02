#!/usr/bin/env bash
# Whole-run wall time of two clinch binaries, before against after, on three runs:
#   lattice     `clinch run` of the nonlinear SPRINGA lattice, by default with N = 30
#               (generate_lattice, as in scripts/bench_lattice.sh; 327 236 springs, 75 600 free
#               DOFs)
#   spot_welds  `clinch run` of 2000 spot welds loaded past first yield in 20 fixed increments
#               (decks/bench/generate_spot_welds.py; 24 000 DOFs)
#   check_1e6   `clinch check` of the 10^6-connector deck of generate_connector_deck
# Each case is generated once; then the two binaries run in turn (before, after, before, after,
# ...), so a drift of the machine's speed falls on both alike. One pair of warm-up runs is not
# counted. The wall time is bash's EPOCHREALTIME around the process, start-up included. Printed:
# the median of each binary, the ratio of the medians after/before, and the median and spread of
# the ratios pair by pair. A run that fails (exit status, or a `.sta` that does not end in
# COMPLETED) stops the script. For the two runs, the last history row of the two binaries is
# compared: the largest difference over the column's largest |value|.
# Usage: scripts/bench_whole_runs.sh BEFORE_CLINCH AFTER_CLINCH
# Environment: CLINCH_BUILD_DIR (default build) for generate_lattice and generate_connector_deck,
# WHOLE_RUNS (5 per binary), WHOLE_CASES (default "lattice spot_welds check_1e6"), WHOLE_LATTICE
# (generate_lattice's size and shape, default "--n 30"; e.g. "--n 20 --jitter 0.2 --patch 0.5
# --seed 1" for the irregular lattice), WHOLE_KEEP=DIR to keep decks and outputs.
set -euo pipefail
if (($# != 2)); then
  echo "usage: $0 BEFORE_CLINCH AFTER_CLINCH" >&2
  exit 2
fi
before=$(realpath "$1")
after=$(realpath "$2")
cd "$(dirname "$0")/.."
bin=${CLINCH_BUILD_DIR:-build}
runs=${WHOLE_RUNS:-5}
read -r -a cases <<< "${WHOLE_CASES:-lattice spot_welds check_1e6}"
for tool in generate_lattice generate_connector_deck; do
  if [ ! -x "$bin/$tool" ]; then
    echo "bench_whole_runs: $bin/$tool is missing (build it, or set CLINCH_BUILD_DIR)" >&2
    exit 3
  fi
done
if [ -n "${WHOLE_KEEP:-}" ]; then
  dir=$WHOLE_KEEP
  mkdir -p "$dir"
else
  dir=$(mktemp -d)
  trap 'rm -rf "$dir"' EXIT
fi
dir=$(cd "$dir" && pwd)

median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }

# The deck and the subcommand of a case.
prepare() {
  case $1 in
    lattice)
      # shellcheck disable=SC2086
      "$bin/generate_lattice" ${WHOLE_LATTICE:---n 30} --element springa --law nonlinear \
        --out "$dir/lattice.inp" ;;
    spot_welds)
      python3 decks/bench/generate_spot_welds.py --welds 2000 --increments 20 \
        --out "$dir/spot_welds.inp" ;;
    check_1e6)
      "$bin/generate_connector_deck" 1000000 > "$dir/check_1e6.inp" ;;
    *)
      echo "bench_whole_runs: unknown case '$1'" >&2
      exit 2 ;;
  esac
}

# One run of binary $2 (label $1) on case $3; prints its wall time in seconds.
timed_run() {
  local label=$1 clinch=$2 name=$3 out=$dir/out-$1-$3 status=0 start end
  rm -rf "$out"
  start=$EPOCHREALTIME
  if [ "$name" = check_1e6 ]; then
    "$clinch" check "$dir/$name.inp" > "$dir/$label-$name.stdout" 2>&1 || status=$?
  else
    "$clinch" run "$dir/$name.inp" --out "$out" --job job > "$dir/$label-$name.stdout" 2>&1 ||
      status=$?
  fi
  end=$EPOCHREALTIME
  if ((status != 0)) ||
    { [ "$name" != check_1e6 ] && [ "$(tail -n 1 "$out/job.sta" 2>/dev/null)" != COMPLETED ]; }; then
    echo "bench_whole_runs: $label ($clinch) failed on $name (exit $status):" >&2
    tail -n 5 "$dir/$label-$name.stdout" >&2
    exit 1
  fi
  awk -v a="$start" -v b="$end" 'BEGIN {printf "%.4f\n", b - a}'
}

# Largest difference between the last history rows of the two runs of a case, each column over
# its largest |value| in the before run.
history_difference() {
  python3 - "$dir/out-before-$1/job.history.csv" "$dir/out-after-$1/job.history.csv" <<'EOF'
import csv, sys
a, b = (list(csv.reader(open(p))) for p in sys.argv[1:3])
if a[0] != b[0] or len(a) != len(b):
    print("differ")
    sys.exit()
worst = 0.0
for c in range(4, len(a[0])):
    scale = max(abs(float(r[c])) for r in a[1:]) or 1.0
    worst = max(worst, abs(float(a[-1][c]) - float(b[-1][c])) / scale)
print(f"{worst:.1e}")
EOF
}

echo "whole runs: $(nproc) cores, load average $(cut -d ' ' -f 1-3 /proc/loadavg);" \
  "before $before, after $after; $runs runs each, interleaved, after 1 warm-up pair"
printf "%-11s %10s %10s %12s %14s %16s %9s\n" case before_s after_s after/before \
  pair_ratio_med pair_ratio_range hist_diff
for name in "${cases[@]}"; do
  prepare "$name"
  timed_run before "$before" "$name" > /dev/null
  timed_run after "$after" "$name" > /dev/null
  : > "$dir/$name.times"
  for ((run = 1; run <= runs; ++run)); do
    b=$(timed_run before "$before" "$name")
    a=$(timed_run after "$after" "$name")
    echo "$b $a" >> "$dir/$name.times"
  done
  bs=$(awk '{print $1}' "$dir/$name.times" | median)
  as=$(awk '{print $2}' "$dir/$name.times" | median)
  ratios=$(awk '{printf "%.4f\n", $2 / $1}' "$dir/$name.times" | sort -g)
  diff=-
  [ "$name" = check_1e6 ] || diff=$(history_difference "$name")
  printf "%-11s %10.4f %10.4f %12.3f %14.3f %16s %9s\n" "$name" "$bs" "$as" \
    "$(awk -v a="$as" -v b="$bs" 'BEGIN {print a / b}')" "$(median <<< "$ratios")" \
    "$(head -n 1 <<< "$ratios")-$(tail -n 1 <<< "$ratios")" "$diff"
done
echo "before_s, after_s: median wall time (start-up included); after/before: ratio of the"
echo "medians; pair_ratio: after/before run by run (median, min-max); hist_diff: largest difference"
echo "of the last history row over each column's largest |value| (- for check)."
