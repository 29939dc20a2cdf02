#include "parser/lexer.hpp"

#include <cstring>

#include <fmt/format.h>

namespace clinch {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t'; }
bool is_high(char c) { return static_cast<unsigned char>(c) >= 0x80; }

std::string_view trim(std::string_view s) {
  std::size_t b = 0, e = s.size();
  while (b < e && is_blank(s[b])) ++b;
  while (e > b && is_blank(s[e - 1])) --e;
  return s.substr(b, e - b);
}

// One field with quotes, inner blanks or non-ASCII bytes, from `i` (first non-blank) to `end`
// (the comma or the end of the line; a comma inside quotes moves `end` on). Returns false after
// an error (E0101, E0103).
bool slow_field(std::string_view text, SourceLoc loc, std::size_t i, std::size_t& end,
                Field& field, DiagnosticSink& sink) {
  const std::size_t n = text.size();
  bool clean = true;
  bool seen_content = false;
  std::size_t pending_blanks = 0;
  while (i < n && text[i] != ',') {
    const char c = text[i];
    if (c == '"') {
      const std::size_t close = text.find('"', i + 1);
      if (close == std::string_view::npos) {
        sink.report(DiagCode::unterminated_quote, loc.shifted(static_cast<std::uint32_t>(i)),
                    fmt::format("missing closing '\"' in {}", text.substr(i)));
        field.text.append(text.substr(i + 1));
        field.quoted = true;
        end = n;
        return false;
      }
      std::string_view inside = text.substr(i + 1, close - i - 1);
      for (std::size_t k = 0; k < inside.size(); ++k) {
        if (is_high(inside[k])) {
          sink.report(DiagCode::non_ascii_text, loc.shifted(static_cast<std::uint32_t>(i + 1 + k)),
                      "non-ASCII character in quoted name (Abaqus accepts ASCII only)");
          break;
        }
      }
      if (pending_blanks && seen_content) field.had_inner_blank = true;
      pending_blanks = 0;
      field.text.append(inside);
      field.quoted = true;
      seen_content = true;
      i = close + 1;
      continue;
    }
    if (is_blank(c)) {
      ++pending_blanks;
      ++i;
      continue;
    }
    if (is_high(c) && clean) {
      clean = false;
      sink.report(DiagCode::non_ascii, loc.shifted(static_cast<std::uint32_t>(i)),
                  fmt::format("non-ASCII character (0x{:02X}) in a data line",
                              static_cast<unsigned char>(c)));
    }
    if (pending_blanks && seen_content) field.had_inner_blank = true;
    pending_blanks = 0;
    field.text.push_back(c);
    seen_content = true;
    ++i;
  }
  end = i;
  return clean;
}

}  // namespace

bool split_fields(std::string_view text, SourceLoc loc, std::vector<Field>& fields,
                  DiagnosticSink& sink) {
  // Field objects (and their string buffers) are reused from line to line: no allocation per
  // field in the bulk of a deck (ARCHITECTURE.md, performance by design).
  std::size_t used = 0;
  bool clean = true;
  const std::size_t n = text.size();
  const char* data = text.data();
  std::size_t i = 0;
  while (true) {
    if (used == fields.size()) fields.emplace_back();
    Field& field = fields[used++];
    field.text.clear();
    field.quoted = false;
    field.had_inner_blank = false;
    field.parameter = nullptr;
    while (i < n && is_blank(data[i])) ++i;
    field.loc = loc.shifted(static_cast<std::uint32_t>(i));
    // Fast path: a field without quotes, inner blanks or high bytes is copied in one piece.
    // One pass finds the comma and notes blanks that stand between non-blank characters.
    std::size_t end = i;
    std::size_t last = i;  // one past the last non-blank character
    bool simple = true;
    while (end < n) {
      const char c = data[end];
      if (c == ',') break;
      if (!is_blank(c)) {
        if (last != end && last != i) simple = false;  // blanks inside the field
        if (c == '"' || is_high(c)) simple = false;
        last = end + 1;
      }
      ++end;
    }
    if (simple) {
      field.text.assign(data + i, last - i);
    } else {
      clean = slow_field(text, loc, i, end, field, sink) && clean;
      // A quoted comma may have moved the end on: the span ends at its last non-blank.
      last = end;
      while (last > i && is_blank(data[last - 1])) --last;
    }
    field.loc.length = static_cast<std::uint32_t>(last - i);
    if (end >= n) break;
    i = end + 1;  // past the comma
  }
  // Trailing empty fields are dropped (input-syntax.md §3.1: "12," is "12").
  while (used > 0 && fields[used - 1].empty()) --used;
  fields.resize(used);
  return clean;
}

bool parse_keyword_line(const std::vector<KeywordSegment>& segments, KeywordLine& out,
                        DiagnosticSink& sink) {
  out = KeywordLine{};
  // Flatten segments into (char, location) pieces; commas split parameters across segments.
  struct Piece {
    std::string_view text;
    SourceLoc loc;
  };
  std::vector<Piece> items;  // one per comma-separated item
  for (const KeywordSegment& segment : segments) {
    std::string_view text = segment.text;
    std::size_t start = 0;
    bool in_quote = false;
    for (std::size_t i = 0; i <= text.size(); ++i) {
      if (i < text.size() && text[i] == '"') in_quote = !in_quote;
      if (i == text.size() || (text[i] == ',' && !in_quote)) {
        if (i == text.size() && in_quote) {
          std::size_t q = text.rfind('"');
          sink.report(DiagCode::unterminated_quote,
                      segment.loc.shifted(static_cast<std::uint32_t>(q)),
                      fmt::format("missing closing '\"' in {}", text.substr(q)));
          return false;
        }
        // A trailing comma at the end of a segment is the continuation mark, not an item.
        if (!(i == text.size() && start == text.size() && start > 0)) {
          items.push_back({text.substr(start, i - start),
                           segment.loc.shifted(static_cast<std::uint32_t>(start))});
        }
        start = i + 1;
      }
    }
  }
  // Item 0: '*' + keyword name.
  {
    Piece first = items.front();
    std::size_t star = first.text.find('*');
    std::string_view name = trim(first.text.substr(star + 1));
    // The span runs from the '*' to the end of the name.
    out.loc = first.loc.shifted(static_cast<std::uint32_t>(star))
                  .spanning(static_cast<std::uint32_t>(name.data() + name.size() -
                                                       (first.text.data() + star)));
    for (std::size_t k = 0; k < name.size(); ++k) {
      if (is_high(name[k])) {
        sink.report(DiagCode::non_ascii, out.loc, "non-ASCII character in a keyword name");
        return false;
      }
    }
    out.spelled = std::string(name);
    out.name = fold_name(name);
    if (out.name.empty()) {
      sink.report(DiagCode::keyword_missing_name, out.loc, "keyword line has no keyword name");
      return false;
    }
  }
  bool any_malformed = false;
  for (std::size_t k = 1; k < items.size(); ++k) {
    const Piece& item = items[k];
    std::size_t lead = 0;
    while (lead < item.text.size() && is_blank(item.text[lead])) ++lead;
    std::string_view body = trim(item.text);
    SourceLoc item_loc = item.loc.shifted(static_cast<std::uint32_t>(lead));
    if (body.empty()) {
      // A trailing empty item only marks a continuation or a final comma.
      if (k + 1 < items.size()) {
        sink.report(DiagCode::empty_parameter, item_loc,
                    "empty parameter between commas ignored");
      }
      continue;
    }
    std::size_t eq = std::string_view::npos;
    for (std::size_t i = 0; i < body.size(); ++i) {
      if (body[i] == '"') {
        std::size_t close = body.find('"', i + 1);
        if (close == std::string_view::npos) break;
        i = close;
        continue;
      }
      if (body[i] == '=') {
        eq = i;
        break;
      }
    }
    KeywordParam param;
    std::string_view name = eq == std::string_view::npos ? body : trim(body.substr(0, eq));
    param.loc = item_loc.spanning(static_cast<std::uint32_t>(name.size()));
    bool malformed = name.empty();
    for (char c : name) {
      if (c == '"' || is_high(c)) malformed = true;
    }
    if (eq != std::string_view::npos) {
      std::string_view rest = body.substr(eq + 1);
      // "NAME==x" and "NAME=a=b" (outside quotes) are malformed (E0104).
      bool in_quote = false;
      for (char c : rest) {
        if (c == '"') in_quote = !in_quote;
        if (c == '=' && !in_quote) malformed = true;
      }
    }
    if (malformed) {
      any_malformed = true;
      sink.report(DiagCode::malformed_parameter,
                  item_loc.spanning(static_cast<std::uint32_t>(body.size())),
                  fmt::format("malformed parameter '{}' (expected NAME or NAME=VALUE)", body));
      continue;
    }
    param.spelled = std::string(name);
    param.name = fold_name(name);
    if (eq != std::string_view::npos) {
      param.has_value = true;
      std::size_t value_start = eq + 1;
      while (value_start < body.size() && is_blank(body[value_start])) ++value_start;
      std::string_view value_text = body.substr(value_start);
      SourceLoc value_loc = item_loc.shifted(static_cast<std::uint32_t>(value_start));
      std::vector<Field> fields;
      DiagnosticSink local;
      split_fields(value_text, value_loc, fields, local);
      for (const Diagnostic& d : local.diagnostics()) {
        Diagnostic& copy = sink.report(d.code, d.severity, d.loc, d.message);
        copy.notes = d.notes;
      }
      if (!fields.empty()) {
        param.value = std::move(fields.front());
      } else {
        param.value.loc = value_loc;
      }
    }
    out.params.push_back(std::move(param));
  }
  // A keyword line with a malformed parameter is skipped whole: its other checks would only
  // repeat the fault (input-syntax.md §10).
  return !any_malformed;
}

LineScanner::LineScanner(std::string_view text, std::uint32_t file_index, DiagnosticSink& sink,
                         bool checks)
    : text_(text), file_(file_index), checks_(checks), sink_(sink) {}

LineScanner::LineScanner(std::unique_ptr<FileWindow> window, std::uint32_t file_index,
                         DiagnosticSink& sink, bool checks)
    : window_(std::move(window)), file_(file_index), checks_(checks), sink_(sink) {}

bool LineScanner::find_line_end(std::size_t& end) {
  std::size_t searched = offset_;
  while (true) {
    if (searched < text_.size()) {
      const void* nl = std::memchr(text_.data() + searched, '\n', text_.size() - searched);
      if (nl) {
        end = static_cast<std::size_t>(static_cast<const char*>(nl) - text_.data());
        return true;
      }
    }
    if (!window_) break;
    const std::size_t pending = offset_ < text_.size() ? text_.size() - offset_ : 0;
    if (!window_->refill(offset_)) break;
    text_ = window_->contents();
    offset_ = 0;
    searched = pending;  // the kept start of the line has no line end
  }
  if (offset_ >= text_.size()) return false;
  end = text_.size();
  return true;
}

LineScanner::Kind LineScanner::next() {
  std::size_t end;
  if (!find_line_end(end)) return Kind::End;
  std::size_t line_end = end;
  if (line_end > offset_ && text_[line_end - 1] == '\r') --line_end;
  line_ = text_.substr(offset_, line_end - offset_);
  offset_ = end + 1;
  ++line_number_;

  // Control characters (E0107): one report per line. TAB, CR (dropped above) and LF are fine.
  // The branch-free scan lets the compiler vectorise the common, clean case.
  rejected_ = false;
  unsigned bad = 0;
  if (checks_) for (char ch : line_) {
    const auto c = static_cast<unsigned char>(ch);
    bad |= static_cast<unsigned>((c < 0x20) & (c != '\t')) | static_cast<unsigned>(c == 0x7f);
  }
  if (bad) {
    for (std::size_t i = 0; i < line_.size(); ++i) {
      const auto c = static_cast<unsigned char>(line_[i]);
      if ((c < 0x20 && c != '\t') || c == 0x7f) {
        sink_.report(DiagCode::control_character,
                     {file_, line_number_, static_cast<std::uint32_t>(i + 1)},
                     fmt::format("control character 0x{:02X} in input", c));
        rejected_ = true;
        break;
      }
    }
  }
  if (checks_ && line_.size() > 256 && !long_line_reported_) {
    long_line_reported_ = true;
    sink_.report(DiagCode::long_line, {file_, line_number_, 257},
                 "line is longer than 256 characters (Abaqus limit)");
  }
  first_non_blank_ = 0;
  while (first_non_blank_ < line_.size() && is_blank(line_[first_non_blank_])) ++first_non_blank_;
  if (first_non_blank_ == line_.size()) return Kind::Blank;
  if (line_[first_non_blank_] == '*') {
    if (first_non_blank_ + 1 < line_.size() && line_[first_non_blank_ + 1] == '*') {
      return Kind::Comment;
    }
    return Kind::Keyword;
  }
  return Kind::Data;
}

}  // namespace clinch
