// Source locations: every token the reader produces carries one, so that a diagnostic can name
// the file, line and column of the text at fault (input-syntax.md §10).
#pragma once

#include <cstdint>

namespace clinch {

// 1-based line and byte column (a TAB counts as one column, input-syntax.md §1). file indexes
// the SourceManager's file table; kNoFile marks "no location" (run-time or command-line faults).
// A location may have an extent on its line: `length` columns from `column`, so that a
// diagnostic can underline the whole field at fault (ARCHITECTURE.md principle 7); 0 means a
// point (the caret only). Two locations are equal when they denote the same span.
struct SourceLoc {
  static constexpr std::uint32_t kNoFile = 0xffffffffu;
  std::uint32_t file = kNoFile;
  std::uint32_t line = 0;
  std::uint32_t column = 0;
  std::uint32_t length = 0;

  bool valid() const { return file != kNoFile; }
  // The point `columns` to the right: a position inside a span has no extent of its own.
  SourceLoc shifted(std::uint32_t columns) const { return {file, line, column + columns, 0}; }
  // The same start with an extent of `columns`.
  SourceLoc spanning(std::uint32_t columns) const { return {file, line, column, columns}; }
  // Last column of the span (the column itself for a point).
  std::uint32_t end_column() const { return length > 0 ? column + length - 1 : column; }
  friend bool operator==(const SourceLoc&, const SourceLoc&) = default;
};

}  // namespace clinch
