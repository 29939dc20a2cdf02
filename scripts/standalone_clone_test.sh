#!/usr/bin/env bash
# Checks that the repository stands alone: clones it (the committed state of the current branch)
# into an empty temporary directory with nothing beside it, runs the README's test command there
# (the line `bash scripts/setup.sh && ctest ...`), and prints the test summary and the time taken.
#   scripts/standalone_clone_test.sh [--keep] [REPOSITORY]   (default: this checkout)
# Exit status: that of the README's command (0 when every test passed).
# CMAKE_CXX_COMPILER_LAUNCHER / CMAKE_C_COMPILER_LAUNCHER (e.g. ccache) pass through the
# environment to CMake; CCACHE_BASEDIR is set to the temporary directory so that a second clone
# reuses the first one's objects.
set -euo pipefail

keep=0
if [ "${1:-}" = "--keep" ]; then
  keep=1
  shift
fi
source_repo=${1:-$(cd "$(dirname "$0")/.." && pwd)}

work=$(mktemp -d /tmp/clinch-clone.XXXXXX)
log=$(mktemp /tmp/clinch-clone-log.XXXXXX)
cleanup() {
  if [ "$keep" = 0 ]; then rm -rf "$work"; else echo "kept $work"; fi
}
trap cleanup EXIT

git clone --quiet "$source_repo" "$work/clinch"
cd "$work/clinch"
echo "clone: $(git log -1 --format='%h %s') into $work/clinch (nothing beside it: $(ls -A "$work"))"

command=$(grep -m1 -E '^bash scripts/setup\.sh && ctest ' README.md) || {
  echo "standalone_clone_test: no 'bash scripts/setup.sh && ctest ...' line in README.md" >&2
  exit 1
}
echo "README's test command: $command"
if [ -n "${CMAKE_CXX_COMPILER_LAUNCHER:-}" ]; then
  export CMAKE_CXX_COMPILER_LAUNCHER CMAKE_C_COMPILER_LAUNCHER="${CMAKE_C_COMPILER_LAUNCHER:-$CMAKE_CXX_COMPILER_LAUNCHER}"
  export CCACHE_BASEDIR=$work
  echo "compiler launcher: $CMAKE_CXX_COMPILER_LAUNCHER"
fi

start=$(date +%s)
set +e
bash -c "$command" > "$log" 2>&1
status=$?
set -e
elapsed=$(( $(date +%s) - start ))

echo "--- last lines of the output (full log: $log)"
grep -E '^The following tests FAILED|^[[:space:]]+[0-9]+ - ' "$log" || true
grep -E 'tests passed|Total Test time' "$log" || tail -20 "$log"
echo "exit status $status; setup, build and tests took ${elapsed} s"
exit "$status"
