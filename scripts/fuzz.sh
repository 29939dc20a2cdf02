#!/usr/bin/env bash
# Builds the libFuzzer targets with clang and ASan/UBSan and runs each for a bounded time,
# seeded from decks/ and tests/diagnostics/. Usage: scripts/fuzz.sh [seconds per target=600]
# Crashing inputs are kept in fuzz-out/<target>/ (artifact files crash-*, leak-*, timeout-*).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
command -v clang++ >/dev/null || { apt-get install -y -qq clang >/dev/null; }
# libFuzzer's runtime comes with Debian's libclang-rt-dev.
dpkg-query -W libclang-rt-14-dev >/dev/null 2>&1 || apt-get install -y -qq libclang-rt-14-dev >/dev/null
CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCLINCH_BUILD_FUZZERS=ON -DCLINCH_BUILD_TESTS=OFF -DCLINCH_BUILD_BENCHMARKS=OFF \
  -DCLINCH_SANITIZE=ON >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target fuzz_deck_reader fuzz_expression
for target in deck_reader expression; do
  corpus=fuzz-out/${target}/corpus
  mkdir -p "$corpus"
  if [ "$target" = deck_reader ]; then
    find decks tests/diagnostics ../shared/external-decks -name '*.inp' -exec cp {} "$corpus"/ \; 2>/dev/null || true
  else
    for f in $(find decks tests/diagnostics -name '*.inp'); do
      awk '/^\*PARAMETER/{p=1;next} /^\*/{p=0} p' "$f" > "$corpus/$(basename "$f").par"
    done
    printf 'a = 1\nb = -2**2 + a//3 %% 2\nc = sqrt(a)*pi\ns = "x" + "y"\n' > "$corpus/basic.par"
  fi
  echo "fuzz: ${target} for ${seconds}s"
  (cd fuzz-out/${target} && UBSAN_OPTIONS=halt_on_error=1 \
    ../../build-fuzz/tests/fuzz/fuzz_${target} -max_total_time="$seconds" -max_len=65536 \
      -timeout=10 -rss_limit_mb=4096 -print_final_stats=1 corpus 2>&1 | tail -n 25)
done
