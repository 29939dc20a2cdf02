// The lexer: physical lines → keyword lines (with their parameters, continuations merged) and
// data lines (raw text, split into fields on request). It knows the line kinds of
// input-syntax.md §1.1, the keyword-line grammar of §2 and the field rules of §3.1. It does not
// know any keyword: *INCLUDE splicing and INPUT= files are handled by the deck reader above it
// (parser/reader/).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.hpp"
#include "base/fold_name.hpp"
#include "parser/file_window.hpp"

namespace clinch {

struct ParamValue;

// One comma-separated field of a data line or a keyword parameter value.
struct Field {
  std::string text;           // trimmed; unquoted: inner blanks removed; quoted: without quotes
  SourceLoc loc;              // from the first to the last non-blank character (quotes included)
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
  SourceLoc loc;              // the name
  bool has_value = false;
  Field value;
};

struct KeywordLine {
  std::string name;           // folded: upper case, no blanks
  std::string spelled;        // as written after '*', trimmed
  SourceLoc loc;              // from the '*' to the end of the name
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


// Iterates the physical lines of one file: classification of §1.1, line-level checks (control
// characters E0107, long lines W0101 once per file). The file is either text in memory or read
// through a FileWindow; text() is valid until the next call of next().
class LineScanner {
 public:
  enum class Kind { Comment, Keyword, Blank, Data, End };
  // `checks` = false skips the line-level checks (the reader's pre-pass looks only for
  // *PARAMETER and *INCLUDE lines and reports nothing).
  LineScanner(std::string_view text, std::uint32_t file_index, DiagnosticSink& sink,
              bool checks = true);
  LineScanner(std::unique_ptr<FileWindow> window, std::uint32_t file_index, DiagnosticSink& sink,
              bool checks = true);
  // Advances to the next line; returns its kind. text()/loc() describe the current line.
  Kind next();
  std::string_view text() const { return line_; }
  SourceLoc loc() const { return {file_, line_number_, 1}; }
  std::uint32_t line_number() const { return line_number_; }
  // Column (1-based) of the first non-blank character of the current line.
  std::uint32_t first_non_blank_column() const { return first_non_blank_ + 1; }
  // The current line had a line-level error (E0107): callers skip it.
  bool line_rejected() const { return rejected_; }
  // Bytes of the file seen so far, and whether reading it failed: at End, a file read from disk
  // is complete only if it still has the size it had when it was opened.
  std::uint64_t bytes_read() const { return window_ ? window_->bytes_read() : text_.size(); }
  bool read_failed() const { return window_ && window_->read_failed(); }
  // The system's reason for a read error ("" when none).
  std::string_view read_error() const {
    return read_failed() ? std::string_view(window_->error()) : std::string_view();
  }
  // Why the file could not be opened ("" when it was, or is in memory).
  std::string_view open_error() const {
    return window_ && !window_->ok() ? std::string_view(window_->error()) : std::string_view();
  }

 private:
  // Offset of the '\n' that ends the line starting at offset_ (text_.size() for a last line
  // without one), refilling the window as needed; false at the end of the file.
  bool find_line_end(std::size_t& end);

  std::string_view text_;
  std::unique_ptr<FileWindow> window_;
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
