// A deck copy written elsewhere than the deck (`clinch study`, `clinch fit`): the deck file's
// lines, edits that replace a column range of one line, and the edits that make the deck's relative
// *INCLUDE and INPUT= paths absolute so that the copy reads the same files from another directory.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "parser/source_manager.hpp"

namespace clinch {

struct DeckLineEdit {
  std::size_t line = 0;     // 1-based
  std::size_t begin = 0;    // 1-based column of the first replaced character
  std::size_t end = 0;      // 1-based column past the last one (begin == end: insertion)
  std::string replacement;  // may hold a line break: it then adds lines
};

// `text` split at '\n' (a '\r' before it stays in the line).
std::vector<std::string> split_deck_lines(std::string_view text);

// Length of a line without its carriage return.
std::size_t line_content_length(const std::string& line);

// One edit per file that the deck file (file 0) includes with a relative or absolute path: the
// path as written, replaced by the absolute path of the file read.
std::vector<DeckLineEdit> absolute_include_edits(const SourceManager& sources);

// A real as the deck reader takes it back exactly (shortest round trip: "0.25", "1e-05", "3.0").
std::string deck_real(double value);

// The lines with the edits applied (edits on one line must not overlap), joined with '\n'.
std::string apply_line_edits(std::vector<std::string> lines, std::vector<DeckLineEdit> edits);

}  // namespace clinch
