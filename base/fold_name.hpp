// Case-insensitive identity of keyword, parameter and unquoted names (input-syntax.md §2, §4):
// blanks removed, ASCII upper case. The lexer folds keyword and parameter names with it, and the
// check stage uses it to tell a suggestion that differs only in case.
#pragma once

#include <string>
#include <string_view>

namespace clinch {

inline std::string fold_name(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    if (c == ' ' || c == '\t') continue;
    out.push_back(c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c);
  }
  return out;
}

}  // namespace clinch
