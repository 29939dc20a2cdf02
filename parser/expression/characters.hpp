// Character classes of the *PARAMETER expression language (input-syntax.md §6.3): Python's
// ASCII identifiers, digits and blanks.
#pragma once

namespace clinch::expression_detail {

inline bool is_ident_start(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
inline bool is_ident_char(char c) { return is_ident_start(c) || (c >= '0' && c <= '9'); }
inline bool is_digit(char c) { return c >= '0' && c <= '9'; }
inline bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\f' || c == '\v' || c == '\r' || c == '\n';
}

}  // namespace clinch::expression_detail
