#!/usr/bin/env bash
# Connector-damage work-precision tables (decks/bench/damage_work_precision.py): exponential
# softening (errors of CTF1 and CDMG against the closed form, at the rows and along the curve the
# rows resolve) and energy-based evolution (dissipated energy against G_f), both in series with a
# stiffer connector, per increment count. Usage: scripts/bench_damage.sh [sizes] (default
# 10,20,40,80,160,320). Environment: CLINCH_BUILD_DIR (default build), DAMAGE_RUNS (runs per
# size for the median wall time, default 3).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${CLINCH_BUILD_DIR:-build}
if [ ! -x "$bin/clinch" ]; then
  echo "bench_damage: $bin/clinch is missing (build it first)" >&2
  exit 3
fi
echo "connector damage work-precision: $(nproc) cores, load average $(cut -d ' ' -f 1-3 /proc/loadavg), $(date -u +%F)"
python3 decks/bench/damage_work_precision.py "$bin/clinch" --sizes "${1:-10,20,40,80,160,320}" \
  --repeat "${DAMAGE_RUNS:-3}"
