#!/usr/bin/env bash
# Coupled-plasticity benchmarks: the time of one spot-weld behaviour update (Google Benchmark,
# medians of 5 repetitions, each case's time over the plastic update's at 2-20 x first yield)
# and the work-precision table of the spot-weld hard case
# (decks/bench/spot_weld_work_precision.py). Whole runs are timed by scripts/bench_whole_runs.sh.
# CLINCH_BUILD_DIR selects the build (default build/).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${CLINCH_BUILD_DIR:-build}
"$build/bench_plastic_update" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_filter='SpotWeld' --benchmark_format=json | python3 scripts/benchmark_medians.py
python3 -O decks/bench/spot_weld_work_precision.py "$build/clinch" "$@"
