# Sourced by the bench_*.sh scripts. `bench_workdir KEEP` sets $dir, as an absolute path, to KEEP
# (created if need be; the runs' decks and outputs stay there) or, when KEEP is empty, to a scratch
# directory removed when the script exits.
bench_workdir() {
  if [ -n "$1" ]; then
    dir=$1
    mkdir -p "$dir"
  else
    dir=$(mktemp -d)
    trap 'rm -rf "$dir"' EXIT
  fi
  dir=$(cd "$dir" && pwd)
}
