// The prose of `clinch keywords` that the keyword registry does not hold: per keyword, what it
// does in clinch, the layout of its data lines, the options that are read and ignored with a
// warning, and those that are read but refused (each with its reason; the handlers in parser/keywords/ and the check stage report them as
// unsupported-option, E0210). Keyed by the canonical keyword name of the registry;
// test_keyword_notes.cpp checks that every supported keyword has notes and that every note names
// a registered keyword.
#pragma once

#include <string_view>
#include <vector>

namespace clinch {

struct KeywordRefusal {
  std::string_view what;  // the option or value, as a deck writes it
  std::string_view why;
};

struct KeywordNotes {
  std::string_view name;        // canonical keyword name, e.g. "CONNECTOR SECTION"
  std::string_view summary;     // one sentence: what the keyword does in clinch
  std::string_view data_lines;  // the layout of the data lines; empty when there are none
  std::vector<KeywordRefusal> refused = {};
  // Options read and ignored with a warning (they cannot change a static analysis), and why.
  std::vector<KeywordRefusal> ignored = {};
};

// The notes of a keyword by canonical name, or nullptr.
const KeywordNotes* find_keyword_notes(std::string_view canonical_name);
// Every note, in the order they are written.
const std::vector<KeywordNotes>& all_keyword_notes();

}  // namespace clinch
