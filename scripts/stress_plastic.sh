#!/usr/bin/env bash
# Longer stress runs of coupled plasticity: random load paths through `clinch run`
# (tests/stress/plastic_paths.py). Usage: scripts/stress_plastic.sh [paths] [seed]
# (CLINCH_BUILD_DIR selects the build, default build/).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${CLINCH_BUILD_DIR:-build}
python3 tests/stress/plastic_paths.py "$build/clinch" --paths "${1:-5000}" --seed "${2:-1}"
