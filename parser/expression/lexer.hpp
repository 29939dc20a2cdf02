// The lexer of *PARAMETER expressions (input-syntax.md §6.2–§6.3): Python 3 numbers, strings,
// names and operators. A lexical fault becomes an Error token, reported when the parser reaches
// it, so that the first fault in text order is the one reported.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.hpp"
#include "parser/expression.hpp"

namespace clinch::expression_detail {

enum class Tok { End, Number, String, Name, Op, Error };

struct Token {
  Tok kind = Tok::End;
  std::uint32_t pos = 0;
  std::uint32_t len = 0;
  ParamValue value;          // Number, String
  bool digits_only = false;  // a plain decimal int literal (for the W0403 suggestion "7.0/2")
  // Number: the literal does not fit (int > 64 bits, float overflows). Reported as E0406 at
  // evaluation, so that a syntax error later in the text still wins (Python compiles first).
  std::string overflow;
  // Error: a lexical fault, reported when the parser reaches this token (so that the first
  // fault in text order is the one reported).
  DiagCode code = DiagCode::expression_syntax;
  std::string message;
};

// The tokens of text, ending with an End token (or an Error token and then End).
std::vector<Token> lex_expression(std::string_view text);

}  // namespace clinch::expression_detail
