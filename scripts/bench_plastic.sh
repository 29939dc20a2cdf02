#!/usr/bin/env bash
# Coupled-plasticity benchmarks: the spot-weld behaviour-update throughput (Google Benchmark,
# medians of 5 repetitions, with the ratio of each batched case to the same motions one update
# at a time) and the work-precision table of the spot-weld hard case
# (decks/bench/spot_weld_work_precision.py). CLINCH_BUILD_DIR selects the build (default build/).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${CLINCH_BUILD_DIR:-build}
"$build/bench_plastic_update" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_filter='SpotWeld' --benchmark_format=json | python3 scripts/benchmark_medians.py
python3 -O decks/bench/spot_weld_work_precision.py "$build/clinch" "$@"
