// Source locations: every token the reader produces carries one, so that a diagnostic can name
// the file, line and column of the text at fault (input-syntax.md §10).
#pragma once

#include <cstdint>

namespace clinch {

// 1-based line and byte column (a TAB counts as one column, input-syntax.md §1). file indexes
// the SourceManager's file table; kNoFile marks "no location" (run-time or command-line faults).
struct SourceLoc {
  static constexpr std::uint32_t kNoFile = 0xffffffffu;
  std::uint32_t file = kNoFile;
  std::uint32_t line = 0;
  std::uint32_t column = 0;

  bool valid() const { return file != kNoFile; }
  SourceLoc shifted(std::uint32_t columns) const { return {file, line, column + columns}; }
  friend bool operator==(const SourceLoc&, const SourceLoc&) = default;
};

}  // namespace clinch
