// The lexer: physical lines → keyword lines (with their parameters, continuations merged) and
// data lines (raw text, split into fields on request). It knows the line kinds of
// input-syntax.md §1.1, the keyword-line grammar of §2 and the field rules of §3.1. It does not
// know any keyword: *INCLUDE splicing and INPUT= files are handled by the DeckReader above it.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "parser/diagnostic.hpp"

namespace clinch {

struct ParamValue;

// One comma-separated field of a data line or a keyword parameter value.
struct Field {
  std::string text;           // trimmed; unquoted: inner blanks removed; quoted: without quotes
  SourceLoc loc;              // first non-blank character (or where the field would start)
  bool quoted = false;
  bool had_inner_blank = false;  // an unquoted field lost blanks (W0102 for numbers and names)
  bool empty() const { return text.empty() && !quoted; }
  // Set by substitution when the whole field was <name> (input-syntax.md §3.3, §6.4).
  const ParamValue* parameter = nullptr;
  SourceLoc parameter_loc;    // where that parameter was defined (for the "value comes from" note)
  std::string parameter_name;
};

struct KeywordParam {
  std::string name;           // folded: upper case, no blanks (input-syntax.md §2)
  std::string spelled;        // as written, trimmed
  SourceLoc loc;              // first character of the name
  bool has_value = false;
  Field value;
};

struct KeywordLine {
  std::string name;           // folded: upper case, no blanks
  std::string spelled;        // as written after '*', trimmed
  SourceLoc loc;              // the '*'
  std::vector<KeywordParam> params;
};

struct DataLine {
  std::string_view text;      // the physical line without line end
  SourceLoc loc;              // column 1
  bool blank = false;
};

// Splits a data line into fields (input-syntax.md §3.1): commas outside quotes split; blanks
// trimmed; unquoted inner blanks removed; trailing empty fields dropped. Reports unterminated
// quotes (E0101), non-ASCII bytes outside quotes (E0103) and, in quotes, W0103. Returns false
// after an error: the caller skips the line rather than report its fields again.
bool split_fields(std::string_view text, SourceLoc loc, std::vector<Field>& fields,
                  DiagnosticSink& sink);

// Parses the text of a keyword line (continuation lines already appended, each with its own
// location) into name and parameters. Reports E0101, E0102, E0103, E0104, W0204.
struct KeywordSegment {
  std::string_view text;
  SourceLoc loc;
};
bool parse_keyword_line(const std::vector<KeywordSegment>& segments, KeywordLine& out,
                        DiagnosticSink& sink);

// Folds a keyword or parameter name: blanks removed, upper case.
std::string fold_name(std::string_view text);

// Iterates the physical lines of one file buffer: classification of §1.1, line-level checks
// (control characters E0107, long lines W0101 once per file).
class LineScanner {
 public:
  enum class Kind { Comment, Keyword, Blank, Data, End };
  // `checks` = false skips the line-level checks (the reader's pre-pass looks only for
  // *PARAMETER and *INCLUDE lines and reports nothing).
  LineScanner(std::string_view text, std::uint32_t file_index, DiagnosticSink& sink,
              bool checks = true);
  // Advances to the next line; returns its kind. text()/loc() describe the current line.
  Kind next();
  std::string_view text() const { return line_; }
  SourceLoc loc() const { return {file_, line_number_, 1}; }
  // Column (1-based) of the first non-blank character of the current line.
  std::uint32_t first_non_blank_column() const { return first_non_blank_ + 1; }
  // The current line had a line-level error (E0107): callers skip it.
  bool line_rejected() const { return rejected_; }
  // Lines after the current one up to the next keyword line or the end of the file (comment
  // lines included): a bound on the data lines of the block that starts here, so that a handler
  // can size its storage once (a 10⁶-node block would otherwise grow its array 20 times).
  std::size_t lines_before_next_keyword() const;

 private:
  std::string_view text_;
  std::size_t offset_ = 0;
  std::uint32_t file_;
  std::uint32_t line_number_ = 0;
  std::string_view line_;
  std::uint32_t first_non_blank_ = 0;
  bool long_line_reported_ = false;
  bool rejected_ = false;
  bool checks_ = true;
  DiagnosticSink& sink_;
};

}  // namespace clinch
