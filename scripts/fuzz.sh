#!/usr/bin/env bash
# Builds the libFuzzer targets with clang and ASan/UBSan and runs each for a bounded time.
# Usage: scripts/fuzz.sh [SECONDS] [TARGET[=SECONDS]...]
#   SECONDS          time per target unless a target gives its own (default 600)
#   TARGET[=SECONDS] run only the named targets (deck_reader, expression, compare, csv_table,
#                    report_data), each for its own time or SECONDS; e.g.
#                    scripts/fuzz.sh deck_reader=1800 compare=600, scripts/fuzz.sh 60 csv_table
# Seeds: decks/ and tests/diagnostics/ (deck_reader, expression), the golden tables of
# decks/verification/ and tests/compare/ (compare, csv_table, report_data), and tables with
# quoted names. The corpus grows in fuzz-out/<target>/corpus;
# crashing inputs are kept in fuzz-out/<target>/ (crash-*, leak-*, timeout-*) and the whole
# libFuzzer log in fuzz-out/<target>/fuzz.log.
set -euo pipefail
cd "$(dirname "$0")/.."
default_seconds=600
declare -a targets=()
declare -A seconds=()
for arg in "$@"; do
  case "$arg" in
    [0-9]*) default_seconds=$arg ;;
    deck_reader* | expression* | compare* | csv_table* | report_data*)
      name=${arg%%=*}
      targets+=("$name")
      [ "$name" = "$arg" ] || seconds[$name]=${arg#*=}
      ;;
    *) echo "fuzz.sh: unknown argument '$arg'" >&2; exit 2 ;;
  esac
done
[ ${#targets[@]} -gt 0 ] || targets=(deck_reader expression compare csv_table report_data)

command -v clang++ >/dev/null || { apt-get install -y -qq clang >/dev/null; }
# libFuzzer's runtime comes with Debian's libclang-rt-dev.
dpkg-query -W libclang-rt-14-dev >/dev/null 2>&1 || apt-get install -y -qq libclang-rt-14-dev >/dev/null
CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCLINCH_BUILD_FUZZERS=ON -DCLINCH_BUILD_TESTS=OFF -DCLINCH_BUILD_BENCHMARKS=OFF \
  -DCLINCH_SANITIZE=ON >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target "${targets[@]/#/fuzz_}"

seed() {
  local target=$1 corpus=$2
  case "$target" in
    deck_reader)
      find decks tests/diagnostics ../shared/external-decks -name '*.inp' -exec cp {} "$corpus"/ \; \
        2>/dev/null || true
      ;;
    expression)
      for f in $(find decks tests/diagnostics -name '*.inp'); do
        awk '/^\*PARAMETER/{p=1;next} /^\*/{p=0} p' "$f" > "$corpus/$(basename "$f").par"
      done
      printf 'a = 1\nb = -2**2 + a//3 %% 2\nc = sqrt(a)*pi\ns = "x" + "y"\n' > "$corpus/basic.par"
      ;;
    compare)
      # fuzz_compare.cpp's input: the --columns pattern, the result table, '%%', the golden one.
      for golden in tests/compare/*.csv; do
        { echo; cat tests/compare/result.csv; echo '%%'; cat "$golden"; } \
          > "$corpus/$(basename "$golden" .csv).cmp"
      done
      { echo 'CU.*'; cat tests/compare/result.csv; echo '%%'; cat tests/compare/golden_off.csv; } \
        > "$corpus/columns.cmp"
      for golden in decks/verification/*/golden.csv; do
        { echo; cat "$golden"; echo '%%'; cat "$golden"; } \
          > "$corpus/$(basename "$(dirname "$golden")").cmp"
      done
      ;;
    csv_table)
      cp tests/compare/*.csv "$corpus"/
      for golden in decks/verification/*/golden.csv; do
        cp "$golden" "$corpus/$(basename "$(dirname "$golden")").csv"
      done
      # Names quoted as the history writer quotes them (docs/history-table.md).
      printf 'step,increment,step_time,total_time,"CTF1@Weld, left","a ""b""","two\nlines"\n1,0,0,0,0,nan,-inf\n' \
        > "$corpus/quoted.csv"
      ;;
    report_data)
      # fuzz_report_data.cpp's input: the job name, how the run ended, the history, '%%', the
      # golden table.
      for golden in tests/compare/golden_*.csv; do
        { echo 'job'; echo 'COMPLETED'; cat tests/compare/result.csv; echo '%%'; cat "$golden"; } \
          > "$corpus/$(basename "$golden" .csv).rep"
      done
      { printf 'weld\377\n'; echo 'FAILED: interrupted by SIGTERM'; cat tests/compare/result.csv; } \
        > "$corpus/latin1.rep"
      { echo 'w$_$'; echo 'COMPLETED'
        printf 'step,increment,step_time,total_time,"CTF1@Weld, left"\n1,0,0,0,nan\n1,1,1,1,inf\n'; } \
        > "$corpus/quoted.rep"
      ;;
  esac
}

status=0
for target in "${targets[@]}"; do
  corpus=fuzz-out/${target}/corpus
  mkdir -p "$corpus"
  seed "$target" "$corpus"
  time=${seconds[$target]:-$default_seconds}
  echo "fuzz: ${target} for ${time}s"
  if ! (cd fuzz-out/${target} && UBSAN_OPTIONS=halt_on_error=1 \
    ../../build-fuzz/tests/fuzz/fuzz_${target} -max_total_time="$time" -max_len=65536 \
      -timeout=10 -rss_limit_mb=4096 -print_final_stats=1 corpus > fuzz.log 2>&1); then
    status=1
  fi
  tail -n 25 fuzz-out/${target}/fuzz.log
done
exit $status
