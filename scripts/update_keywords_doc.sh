#!/bin/sh
# Regenerates docs/keywords.md from the keyword registry: `clinch keywords --format markdown`.
# Run it after a change to parser/keywords/ or src/cli/keyword_notes.cpp; the CTest test
# docs_keywords_current fails while the file differs from the command's output.
#   scripts/update_keywords_doc.sh [CLINCH]     (default: build/clinch)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
clinch=${1:-$root/build/clinch}
"$clinch" keywords --format markdown > "$root/docs/keywords.md.new"
mv "$root/docs/keywords.md.new" "$root/docs/keywords.md"
echo "wrote $root/docs/keywords.md"
