// Recovery after an unknown keyword that stands for a keyword opening or closing a block
// (*CONNECTOR BEHAVIOR, *STEP, *END STEP, …): the reader enters or leaves that block without
// defining anything, so that what follows is judged where the deck's author meant it to stand.
// Otherwise every sub-option of a misspelt *CONNECTOR BEHAVIOR is "out of place", every block of
// a misspelt *STEP "history data outside a step", and a second typo among them goes unseen
// (input-syntax.md §10: one error for the cause, no follow-ups). The blocks read that way are
// still checked; a note on the error counts them, since none of them is used.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "base/diagnostic.hpp"
#include "parser/keyword_spec.hpp"
#include "parser/lexer.hpp"

namespace clinch {

class MisspeltBlock {
 public:
  // Whether reading an unknown keyword as `meant` changes where later keywords stand.
  static bool changes_structure(const KeywordSpec& meant);

  // The unknown keyword `line`, reported as diagnostic `error_index`, is read as `meant`.
  void begin(std::size_t error_index, const KeywordSpec& meant, const KeywordLine& line);
  // A keyword line after it: `inside` when it still stands in the block `meant` opened. The
  // first one outside ends the count and adds the note.
  void keyword(const KeywordLine& line, bool inside, DiagnosticSink& sink);
  // End of the deck.
  void finish(DiagnosticSink& sink);

  bool open() const { return open_; }
  // The block it opened: a behaviour block (sub-options) or a step (history data).
  bool opened_behavior() const { return behavior_; }

 private:
  bool open_ = false;
  bool behavior_ = false;
  std::size_t error_index_ = 0;
  SourceLoc loc_;
  std::string meant_, name_;
  int blocks_ = 0;
  std::uint32_t first_line_ = 0, last_line_ = 0;
};

}  // namespace clinch
