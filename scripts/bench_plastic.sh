#!/usr/bin/env bash
# Coupled-plasticity benchmarks: the spot-weld behaviour-update throughput (Google Benchmark,
# median of 5 repetitions) and the work-precision table of the spot-weld hard case
# (decks/bench/spot_weld_work_precision.py). CLINCH_BUILD_DIR selects the build (default build/).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${CLINCH_BUILD_DIR:-build}
"$build/bench_plastic_update" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_filter='SpotWeld'
python3 -O decks/bench/spot_weld_work_precision.py "$build/clinch" "$@"
