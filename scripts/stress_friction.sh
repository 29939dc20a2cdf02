#!/usr/bin/env bash
# Longer stress runs of connector friction: random in-plane paths through `clinch run`
# (tests/stress/friction_paths.py). Usage: scripts/stress_friction.sh [paths] [seed]
# (CLINCH_BUILD_DIR selects the build, default build/). Three passes with the same seed (the
# increment controls are drawn per deck, so the paths differ between the passes):
# 50 connectors per deck with clinch's defaults (a line search in steps with friction), which
# checks the invariants on every path, then one connector per deck with the line search turned off
# (N_ls = 0 in the deck), whose convergence rate per drive shows why clinch turns it on; then
# every increment fixed (DIRECT) with inclined CONN2D2 slots, whose contact force is zero only to
# round-off during a lift-off. Exits non-zero when a run crashes or an invariant
# fails in any pass; a clean stop (exit 2) only lowers the rate (--min-rate 0 in every pass).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${CLINCH_BUILD_DIR:-build}
paths=${1:-5000}
seed=${2:-1}
status=0
echo "== $paths paths, 50 per deck, clinch's defaults (line search N_ls = 5 with friction)"
python3 tests/stress/friction_paths.py "$build/clinch" --paths "$paths" --seed "$seed" \
  --per-deck 50 --min-rate 0 || status=1
echo "== $paths paths of the same seed, one per deck, line search off (N_ls = 0)"
python3 tests/stress/friction_paths.py "$build/clinch" --paths "$paths" --seed "$seed" \
  --per-deck 1 --line-search 0 --min-rate 0 | grep -v '^note: ' || status=1
echo "== $paths paths of the same seed, DIRECT increments, SLOT CONN2D2 in turned slots"
python3 tests/stress/friction_paths.py "$build/clinch" --paths "$paths" --seed "$seed" \
  --per-deck 50 --direct 0.005,0.01,0.0137,0.02 --inclined --min-rate 0 || status=1
exit $status
