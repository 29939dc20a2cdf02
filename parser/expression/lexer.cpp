#include "parser/expression/lexer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <system_error>
#include <utility>

#include "parser/expression/characters.hpp"

namespace clinch {

using expression_detail::is_digit;
using expression_detail::is_ident_char;
using expression_detail::is_ident_start;

namespace {

// Python string prefixes (case-insensitive): r, u, b, f and the two-letter raw combinations.
bool is_string_prefix(std::string_view ident) {
  if (ident.empty() || ident.size() > 2) return false;
  std::string lower;
  for (char c : ident) lower.push_back(static_cast<char>(c | 0x20));
  return lower == "r" || lower == "u" || lower == "b" || lower == "f" || lower == "br" ||
         lower == "rb" || lower == "fr" || lower == "rf";
}

// The offset just after the closing quote of the string literal whose opening quote is at
// quote_pos, or nullopt when it is not closed on this line.
std::optional<std::size_t> string_end(std::string_view text, std::size_t quote_pos) {
  const char quote = text[quote_pos];
  const bool triple =
      quote_pos + 2 < text.size() && text[quote_pos + 1] == quote && text[quote_pos + 2] == quote;
  std::size_t k = quote_pos + (triple ? 3 : 1);
  while (k < text.size()) {
    // A backslash keeps the next character inside the string, in raw strings too (Python).
    if (text[k] == '\\') {
      k += 2;
      continue;
    }
    if (text[k] == quote) {
      if (!triple) return k + 1;
      if (k + 2 < text.size() && text[k + 1] == quote && text[k + 2] == quote) return k + 3;
    }
    ++k;
  }
  return std::nullopt;
}

}  // namespace

std::size_t skip_string_literal(std::string_view text, std::size_t pos) {
  std::size_t q = pos;
  while (q < text.size() && is_ident_char(text[q])) ++q;  // prefix
  if (q >= text.size() || (text[q] != '\'' && text[q] != '"')) return text.size();
  return string_end(text, q).value_or(text.size());
}

std::size_t find_comment(std::string_view text) {
  std::size_t k = 0;
  while (k < text.size()) {
    const char c = text[k];
    if (c == '#') return k;
    if (c == '\'' || c == '"') {
      k = skip_string_literal(text, k);
    } else if (is_ident_start(c)) {
      std::size_t end = k;
      while (end < text.size() && is_ident_char(text[end])) ++end;
      if (end < text.size() && (text[end] == '\'' || text[end] == '"') &&
          is_string_prefix(text.substr(k, end - k))) {
        k = skip_string_literal(text, k);
      } else {
        k = end;
      }
    } else {
      ++k;
    }
  }
  return std::string_view::npos;
}

}  // namespace clinch

namespace clinch::expression_detail {

namespace {

// Operators, longest first so that the first match is the longest.
constexpr std::array<std::string_view, 40> kOperators = {
    "**=", "//=", ">>=", "<<=", "...", "**", "//", "==", "!=", "<=", ">=", "<<", ">>", ":=",
    "->",  "+=",  "-=",  "*=",  "/=",  "%=", "&=", "|=", "^=", "@=", "<>", "+",  "-",  "*",
    "/",   "%",   "(",   ")",   ",",   "=",  "<",  ">",  "&",  "|",  "^",  "~"};
constexpr std::string_view kSingleOperators = "[]{}.:@!";

class Lexer {
 public:
  explicit Lexer(std::string_view text) : text_(text) {}

  std::vector<Token> run() {
    std::size_t k = 0;
    while (k < text_.size()) {
      const char c = text_[k];
      if (is_blank(c)) {
        ++k;
        continue;
      }
      if (c == '#') break;  // comment (input-syntax.md §6.2)
      if (is_digit(c) || (c == '.' && k + 1 < text_.size() && is_digit(text_[k + 1]))) {
        if (!lex_number(k)) return finish();
        k = tokens_.back().pos + tokens_.back().len;
        continue;
      }
      if (is_ident_start(c)) {
        std::size_t end = k;
        while (end < text_.size() && is_ident_char(text_[end])) ++end;
        if (end < text_.size() && (text_[end] == '\'' || text_[end] == '"') &&
            is_string_prefix(text_.substr(k, end - k))) {
          if (!lex_string(k, end)) return finish();
          k = tokens_.back().pos + tokens_.back().len;
        } else {
          push(Tok::Name, k, end - k);
          k = end;
        }
        continue;
      }
      if (c == '\'' || c == '"') {
        if (!lex_string(k, k)) return finish();
        k = tokens_.back().pos + tokens_.back().len;
        continue;
      }
      if (c == '\\') {
        error(k, 1, DiagCode::unsupported_expression,
              "line continuation ('\\') is not supported: write each definition on one line");
        return finish();
      }
      if (c == ';') {
        error(k, 1, DiagCode::unsupported_expression,
              "';'-separated statements are not supported: write one definition per line");
        return finish();
      }
      bool matched = false;
      for (std::string_view op : kOperators) {
        if (text_.substr(k, op.size()) == op) {
          push(Tok::Op, k, op.size());
          k += op.size();
          matched = true;
          break;
        }
      }
      if (matched) continue;
      if (kSingleOperators.find(c) != std::string_view::npos) {
        push(Tok::Op, k, 1);
        ++k;
        continue;
      }
      const auto u = static_cast<unsigned char>(c);
      if (u >= 0x80 || u < 0x20 || u == 0x7f) {
        error(k, 1, DiagCode::expression_syntax,
              fmt::format("unexpected byte 0x{:02X} outside a string", u));
      } else {
        error(k, 1, DiagCode::expression_syntax, fmt::format("unexpected character '{}'", c));
      }
      return finish();
    }
    return finish();
  }

 private:
  std::vector<Token> finish() {
    Token end;
    end.kind = Tok::End;
    // At the end of the text there is no offending character: point just after the last token.
    std::size_t pos = 0;
    if (!tokens_.empty()) pos = tokens_.back().pos + tokens_.back().len;
    end.pos = static_cast<std::uint32_t>(pos);
    tokens_.push_back(std::move(end));
    return std::move(tokens_);
  }

  Token& push(Tok kind, std::size_t pos, std::size_t len) {
    Token t;
    t.kind = kind;
    t.pos = static_cast<std::uint32_t>(pos);
    t.len = static_cast<std::uint32_t>(len);
    tokens_.push_back(std::move(t));
    return tokens_.back();
  }

  void error(std::size_t pos, std::size_t len, DiagCode code, std::string message) {
    Token& t = push(Tok::Error, pos, len);
    t.code = code;
    t.message = std::move(message);
  }

  // Python 3 numeric literals: decimal ints (no leading zeros), 0x/0o/0b ints, floats with an
  // optional exponent, '_' between digits. A Fortran D exponent is not valid here (§6.3).
  bool lex_number(std::size_t start) {
    std::size_t k = start;
    std::string clean;  // the literal without '_'
    // Reads a run of digits of the given kind with single '_' between digits.
    auto digits = [&](auto is_ok) -> bool {
      bool any = false;
      while (k < text_.size()) {
        if (is_ok(text_[k])) {
          clean.push_back(text_[k]);
          ++k;
          any = true;
        } else if (text_[k] == '_' && any && k + 1 < text_.size() && is_ok(text_[k + 1])) {
          ++k;
        } else {
          break;
        }
      }
      return any;
    };
    auto bad_tail = [&](std::size_t at) -> bool {
      // A letter, digit or '_' right after a number: the number cannot be parsed from here on.
      const char c = text_[at];
      std::size_t end = at;
      while (end < text_.size() && is_ident_char(text_[end])) ++end;
      const std::string_view literal = text_.substr(start, end - start);
      if ((c == 'j' || c == 'J') && end == at + 1) {
        error(at, 1, DiagCode::unsupported_expression,
              "complex numbers are not supported in parameter expressions");
      } else if ((c == 'd' || c == 'D') && at + 1 < text_.size() &&
                 (is_digit(text_[at + 1]) || ((text_[at + 1] == '+' || text_[at + 1] == '-') &&
                                              at + 2 < text_.size() && is_digit(text_[at + 2])))) {
        std::string fixed(text_.substr(start, at - start));
        std::size_t exp_end = at + 1;
        if (text_[exp_end] == '+' || text_[exp_end] == '-') ++exp_end;
        while (exp_end < text_.size() && is_digit(text_[exp_end])) ++exp_end;
        fixed += 'E';
        fixed += text_.substr(at + 1, exp_end - at - 1);
        error(at, 1, DiagCode::expression_syntax,
              fmt::format("Fortran 'D' exponents are not valid in parameter expressions; write {}",
                          fixed));
      } else if (c == '_') {
        error(at, 1, DiagCode::expression_syntax,
              fmt::format("invalid number '{}': '_' must separate two digits", literal));
      } else {
        error(at, 1, DiagCode::expression_syntax, fmt::format("invalid number '{}'", literal));
      }
      return false;
    };

    if (text_[k] == '0' && k + 1 < text_.size() &&
        std::string_view("xXoObB").find(text_[k + 1]) != std::string_view::npos) {
      const char kind = static_cast<char>(text_[k + 1] | 0x20);
      const int base = kind == 'x' ? 16 : kind == 'o' ? 8 : 2;
      k += 2;
      if (k < text_.size() && text_[k] == '_') ++k;  // Python allows 0x_1F
      auto ok = [base](char c) {
        if (base == 16) return is_digit(c) || ((c | 0x20) >= 'a' && (c | 0x20) <= 'f');
        return c >= '0' && c < static_cast<char>('0' + base);
      };
      if (!digits(ok)) {
        if (k < text_.size() && is_ident_char(text_[k])) return bad_tail(k);
        error(k < text_.size() ? k : start, 1, DiagCode::expression_syntax,
              fmt::format("invalid number '{}': no digits after the prefix",
                          text_.substr(start, k - start)));
        return false;
      }
      if (k < text_.size() && is_ident_char(text_[k])) return bad_tail(k);
      std::uint64_t value = 0;
      bool overflow = false;
      for (char c : clean) {
        const int d = is_digit(c) ? c - '0' : (c | 0x20) - 'a' + 10;
        if (value > (std::numeric_limits<std::uint64_t>::max() - static_cast<unsigned>(d)) /
                        static_cast<unsigned>(base)) {
          overflow = true;
          break;
        }
        value = value * static_cast<unsigned>(base) + static_cast<unsigned>(d);
      }
      Token& t = push(Tok::Number, start, k - start);
      if (overflow ||
          value > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
        t.overflow =
            fmt::format("integer {} does not fit in 64 bits", text_.substr(start, k - start));
      } else {
        t.value = ParamValue::make_int(static_cast<std::int64_t>(value));
      }
      return true;
    }

    bool is_float = false;
    digits(is_digit);
    if (k < text_.size() && text_[k] == '.') {
      if (k + 1 < text_.size() && text_[k + 1] == '_') return bad_tail(k + 1);
      is_float = true;
      clean.push_back('.');
      ++k;
      digits(is_digit);
    }
    if (k < text_.size() && (text_[k] == 'e' || text_[k] == 'E')) {
      std::size_t e = k + 1;
      if (e < text_.size() && (text_[e] == '+' || text_[e] == '-')) ++e;
      if (e >= text_.size() || !is_digit(text_[e])) {
        const std::size_t end = std::min(e, text_.size());
        error(k, 1, DiagCode::expression_syntax,
              fmt::format("invalid number '{}': the exponent has no digits",
                          text_.substr(start, end - start)));
        return false;
      }
      is_float = true;
      clean.push_back('e');
      clean.append(text_.substr(k + 1, e - k - 1));
      k = e;
      digits(is_digit);
    }
    if (k < text_.size() && is_ident_char(text_[k])) return bad_tail(k);
    const std::string_view literal = text_.substr(start, k - start);

    if (!is_float) {
      // Python 3 rejects leading zeros; Python 2 read them as octal (010 == 8).
      if (clean.size() > 1 && clean[0] == '0' &&
          clean.find_first_not_of('0') != std::string::npos) {
        error(start, literal.size(), DiagCode::expression_syntax,
              fmt::format("leading zeros are not allowed in the integer '{}' (Python 2 would read "
                          "it as octal)",
                          literal));
        return false;
      }
      Token& t = push(Tok::Number, start, literal.size());
      t.digits_only = literal.find('_') == std::string_view::npos;
      std::int64_t value = 0;
      const auto res = std::from_chars(clean.data(), clean.data() + clean.size(), value);
      if (res.ec != std::errc()) {
        t.overflow = fmt::format("integer {} does not fit in 64 bits", literal);
      } else {
        t.value = ParamValue::make_int(value);
      }
      return true;
    }

    Token& t = push(Tok::Number, start, literal.size());
    double value = 0.0;
    const auto res = std::from_chars(clean.data(), clean.data() + clean.size(), value,
                                     std::chars_format::general);
    if (res.ec == std::errc::result_out_of_range) {
      // from_chars does not say whether it overflowed or underflowed: strtod does. An underflow
      // is fine (Python gives 0.0 or a subnormal); an overflow gives inf, which is an error.
      value = std::strtod(clean.c_str(), nullptr);
    }
    if (!std::isfinite(value)) {
      t.overflow = fmt::format("number {} is too large: the result is not finite", literal);
    } else {
      t.value = ParamValue::make_float(value);
    }
    return true;
  }

  // Decodes the escapes of a non-raw Python string: \\ \' \" \n \t \r \a \b \f \v \xhh \ooo.
  // Other escapes (\u, \N{...}) are kept as written, as Python does with unknown escapes.
  static std::string decode(std::string_view body) {
    std::string out;
    for (std::size_t k = 0; k < body.size(); ++k) {
      if (body[k] != '\\' || k + 1 >= body.size()) {
        out.push_back(body[k]);
        continue;
      }
      const char c = body[k + 1];
      auto hex = [](char h) -> int {
        if (is_digit(h)) return h - '0';
        const char l = static_cast<char>(h | 0x20);
        return (l >= 'a' && l <= 'f') ? l - 'a' + 10 : -1;
      };
      // One-character escapes: the character after the backslash, and what it stands for.
      constexpr std::string_view kEscaped = "\\'\"ntrabfv";
      constexpr std::string_view kMeaning = "\\'\"\n\t\r\a\b\f\v";
      if (const std::size_t e = kEscaped.find(c); e != std::string_view::npos) {
        out.push_back(kMeaning[e]);
        ++k;
      } else if (c == 'x' && k + 3 < body.size() && hex(body[k + 2]) >= 0 &&
                 hex(body[k + 3]) >= 0) {
        out.push_back(static_cast<char>(hex(body[k + 2]) * 16 + hex(body[k + 3])));
        k += 3;
      } else if (c >= '0' && c <= '7') {
        int value = 0;
        std::size_t n = 0;
        while (n < 3 && k + 1 + n < body.size() && body[k + 1 + n] >= '0' &&
               body[k + 1 + n] <= '7') {
          value = value * 8 + (body[k + 1 + n] - '0');
          ++n;
        }
        out.push_back(static_cast<char>(value & 0xff));
        k += n;
      } else {
        out.push_back('\\');
      }
    }
    return out;
  }

  // A string literal whose prefix starts at `start` and whose quote is at `quote_pos`.
  bool lex_string(std::size_t start, std::size_t quote_pos) {
    std::string prefix;
    for (std::size_t k = start; k < quote_pos; ++k) {
      prefix.push_back(static_cast<char>(text_[k] | 0x20));
    }
    if (prefix.find('f') != std::string::npos) {
      error(start, quote_pos - start + 1, DiagCode::unsupported_expression,
            "f-strings are not supported in parameter expressions");
      return false;
    }
    if (prefix.find('b') != std::string::npos) {
      error(start, quote_pos - start + 1, DiagCode::unsupported_expression,
            "byte strings are not supported in parameter expressions");
      return false;
    }
    const char quote = text_[quote_pos];
    const bool triple = quote_pos + 2 < text_.size() && text_[quote_pos + 1] == quote &&
                        text_[quote_pos + 2] == quote;
    const std::optional<std::size_t> end = string_end(text_, quote_pos);
    if (!end) {
      error(quote_pos, 1, DiagCode::expression_syntax,
            fmt::format("unterminated string: missing closing {}",
                        triple ? std::string(3, quote) : std::string(1, quote)));
      return false;
    }
    const std::size_t open_len = triple ? 3 : 1;
    const std::string_view body =
        text_.substr(quote_pos + open_len, *end - quote_pos - 2 * open_len);
    Token& t = push(Tok::String, start, *end - start);
    t.value = ParamValue::make_string(prefix.find('r') != std::string::npos ? std::string(body)
                                                                            : decode(body));
    return true;
  }

  std::string_view text_;
  std::vector<Token> tokens_;
};

}  // namespace

std::vector<Token> lex_expression(std::string_view text) { return Lexer(text).run(); }

}  // namespace clinch::expression_detail
