#!/usr/bin/env bash
# Longer stress runs of connector damage: random softening paths through `clinch run`
# (tests/stress/damage_paths.py). Usage: scripts/stress_damage.sh [paths] [seed]
# (CLINCH_BUILD_DIR selects the build, default build/). Exits non-zero when a run crashes, stops
# other than cleanly, or an invariant fails; clean stops past limit points only lower the rate.
# --riks: the load-driven decks run again as *STATIC, RIKS steps (docs/riks.md).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${CLINCH_BUILD_DIR:-build}
paths=${1:-3000}
seed=${2:-1}
python3 tests/stress/damage_paths.py "$build/clinch" --paths "$paths" --seed "$seed" --per-deck 5 --riks
