#include "parser/expression.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <span>
#include <system_error>
#include <utility>
#include <vector>

#include "base/suggest.hpp"

namespace clinch {

// ---------------------------------------------------------------------------------------------
// ParamValue

ParamValue ParamValue::make_int(std::int64_t value) {
  ParamValue v;
  v.kind = Kind::Int;
  v.i = value;
  return v;
}

ParamValue ParamValue::make_float(double value) {
  ParamValue v;
  v.kind = Kind::Float;
  v.f = value;
  return v;
}

ParamValue ParamValue::make_string(std::string value) {
  ParamValue v;
  v.kind = Kind::String;
  v.s = std::move(value);
  return v;
}

double ParamValue::as_double() const {
  switch (kind) {
    case Kind::Int:
      return static_cast<double>(i);
    case Kind::Float:
      return f;
    case Kind::String:
      return 0.0;
  }
  return 0.0;
}

namespace {

// Python repr of a float ("short" repr style): the shortest digits that round-trip, in fixed
// notation when the decimal exponent is in [-4, 16), else in exponent notation with a sign and at
// least two exponent digits (1e-05, 1e+16). Fixed notation always shows a fractional part (3.0).
std::string float_repr(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x < 0 ? "-inf" : "inf";
  std::array<char, 64> buf{};
  // Without a precision, to_chars gives the shortest representation that round-trips.
  const auto res =
      std::to_chars(buf.data(), buf.data() + buf.size(), x, std::chars_format::scientific);
  std::string s(buf.data(), res.ptr);
  std::string out;
  if (!s.empty() && s[0] == '-') {
    out = "-";
    s.erase(0, 1);
  }
  const std::size_t epos = s.find('e');
  if (epos == std::string::npos) return out + s;  // cannot happen with chars_format::scientific
  int exponent = std::atoi(s.c_str() + epos + 1);
  std::string digits;
  for (std::size_t k = 0; k < epos; ++k) {
    if (s[k] != '.') digits.push_back(s[k]);
  }
  if (exponent < -4 || exponent >= 16) {
    out += digits[0];
    if (digits.size() > 1) {
      out += '.';
      out.append(digits, 1, std::string::npos);
    }
    out += exponent < 0 ? "e-" : "e+";
    const int magnitude = exponent < 0 ? -exponent : exponent;
    if (magnitude < 10) out += '0';
    out += std::to_string(magnitude);
    return out;
  }
  if (exponent >= 0) {
    const auto int_digits = static_cast<std::size_t>(exponent) + 1;
    if (digits.size() <= int_digits) {
      out += digits;
      out.append(int_digits - digits.size(), '0');
      out += ".0";
    } else {
      out.append(digits, 0, int_digits);
      out += '.';
      out.append(digits, int_digits, std::string::npos);
    }
    return out;
  }
  out += "0.";
  out.append(static_cast<std::size_t>(-exponent - 1), '0');
  out += digits;
  return out;
}

// Python repr of a str: single quotes unless the text contains ' and no ".
std::string string_repr(std::string_view s) {
  const bool use_double =
      s.find('\'') != std::string_view::npos && s.find('"') == std::string_view::npos;
  const char quote = use_double ? '"' : '\'';
  std::string out(1, quote);
  for (char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\\') {
      out += "\\\\";
    } else if (c == quote) {
      out += '\\';
      out += c;
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\r') {
      out += "\\r";
    } else if (u < 0x20 || u == 0x7f) {
      out += fmt::format("\\x{:02x}", u);
    } else {
      out += c;
    }
  }
  out += quote;
  return out;
}

}  // namespace

std::string ParamValue::to_display() const {
  switch (kind) {
    case Kind::Int:
      return std::to_string(i);
    case Kind::Float:
      return float_repr(f);
    case Kind::String:
      return string_repr(s);
  }
  return {};
}

// ---------------------------------------------------------------------------------------------
// Names: built-ins and keywords

namespace {

// clang-format off
enum class Fn {
  Abs, Min, Max, Int, Float, Round, Sqrt, Exp, Log, Log10, Pow, Sin, Cos, Tan, Asin, Acos, Atan,
  Atan2, Sinh, Cosh, Tanh, Degrees, Radians, Floor, Ceil, Fabs, Fmod, Hypot
};
// clang-format on

struct FnInfo {
  std::string_view name;
  Fn fn;
  int min_args;
  int max_args;  // -1: no upper limit
};

// input-syntax.md §6.3. pow is math.pow (Abaqus evaluates with the math module's names in scope,
// which hide the built-in pow), so it always returns a float. hypot takes exactly two arguments,
// as in Python 2 (Python ≥ 3.8 accepts any number; two is the portable form).
constexpr std::array<FnInfo, 28> kFunctions = {{
    {"abs", Fn::Abs, 1, 1},         {"min", Fn::Min, 2, -1},        {"max", Fn::Max, 2, -1},
    {"int", Fn::Int, 1, 1},         {"float", Fn::Float, 1, 1},     {"round", Fn::Round, 1, 2},
    {"sqrt", Fn::Sqrt, 1, 1},       {"exp", Fn::Exp, 1, 1},         {"log", Fn::Log, 1, 2},
    {"log10", Fn::Log10, 1, 1},     {"pow", Fn::Pow, 2, 2},         {"sin", Fn::Sin, 1, 1},
    {"cos", Fn::Cos, 1, 1},         {"tan", Fn::Tan, 1, 1},         {"asin", Fn::Asin, 1, 1},
    {"acos", Fn::Acos, 1, 1},       {"atan", Fn::Atan, 1, 1},       {"atan2", Fn::Atan2, 2, 2},
    {"sinh", Fn::Sinh, 1, 1},       {"cosh", Fn::Cosh, 1, 1},       {"tanh", Fn::Tanh, 1, 1},
    {"degrees", Fn::Degrees, 1, 1}, {"radians", Fn::Radians, 1, 1}, {"floor", Fn::Floor, 1, 1},
    {"ceil", Fn::Ceil, 1, 1},       {"fabs", Fn::Fabs, 1, 1},       {"fmod", Fn::Fmod, 2, 2},
    {"hypot", Fn::Hypot, 2, 2},
}};

const FnInfo* find_function(std::string_view name) {
  for (const FnInfo& info : kFunctions) {
    if (info.name == name) return &info;
  }
  return nullptr;
}

// Python's math.pi and math.e.
std::optional<double> builtin_constant(std::string_view name) {
  if (name == "pi") return 3.141592653589793;
  if (name == "e") return 2.718281828459045;
  return std::nullopt;
}

constexpr std::array<std::string_view, 35> kKeywords = {
    "and",  "as",     "assert", "async",  "await",  "break",   "class",    "continue", "def",
    "del",  "elif",   "else",   "except", "False",  "finally", "for",      "from",     "global",
    "if",   "import", "in",     "is",     "lambda", "None",    "nonlocal", "not",      "or",
    "pass", "raise",  "return", "True",   "try",    "while",   "with",     "yield"};

}  // namespace

bool is_builtin_function(std::string_view name) { return find_function(name) != nullptr; }
bool is_builtin_constant(std::string_view name) { return builtin_constant(name).has_value(); }
bool is_python_keyword(std::string_view name) {
  return std::find(kKeywords.begin(), kKeywords.end(), name) != kKeywords.end();
}

// ---------------------------------------------------------------------------------------------
// Lexical helpers

namespace {

bool is_ident_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_ident_char(char c) { return is_ident_start(c) || (c >= '0' && c <= '9'); }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\f' || c == '\v' || c == '\r' || c == '\n';
}

// Python string prefixes (case-insensitive): r, u, b, f and the two-letter raw combinations.
bool is_string_prefix(std::string_view ident) {
  if (ident.empty() || ident.size() > 2) return false;
  std::string lower;
  for (char c : ident) lower.push_back(static_cast<char>(c | 0x20));
  return lower == "r" || lower == "u" || lower == "b" || lower == "f" || lower == "br" ||
         lower == "rb" || lower == "fr" || lower == "rf";
}

}  // namespace

namespace {

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

namespace {

// ---------------------------------------------------------------------------------------------
// Lexer

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

// ---------------------------------------------------------------------------------------------
// Parser: tokens → tree. The grammar of input-syntax.md §6.3; additive and multiplicative runs are
// kept as one n-ary node each, so that a long `1+1+...+1` does not make a deep tree.

enum class NodeKind { Literal, Name, Call, Negate, Plus, Chain, Power };
enum class BinOp { Add, Sub, Mul, Div, FloorDiv, Mod };

struct OpAt {
  BinOp op;
  std::uint32_t pos;
};

struct Node {
  NodeKind kind = NodeKind::Literal;
  std::uint32_t begin = 0;  // source span [begin, end)
  std::uint32_t end = 0;
  std::uint32_t pos = 0;  // operator, name or literal position (where diagnostics point)
  ParamValue value;       // Literal
  std::string overflow;   // Literal that does not fit (E0406 when evaluated)
  bool digits_only = false;
  std::string_view name;  // Name, Call
  std::vector<int> kids;  // Call: arguments; Chain: operands; Negate/Plus: 1; Power: 2
  std::vector<OpAt> ops;  // Chain: ops[i] joins the result so far with kids[i + 1]
};

// Python itself stops at 200 nested parentheses; the same cap keeps recursion (parse and
// evaluation) far from any stack limit whatever the input.
constexpr int kMaxDepth = 200;

class Parser {
 public:
  Parser(std::string_view text, SourceLoc loc, const std::vector<Token>& tokens,
         DiagnosticSink& sink)
      : text_(text), loc_(loc), toks_(tokens), sink_(sink) {}

  // Returns the root node, or -1 after reporting an error.
  int parse() {
    const int root = parse_expr();
    if (root < 0) return -1;
    if (cur().kind == Tok::End) return root;
    return unexpected_after_operand("an operator or the end of the expression");
  }

  std::vector<Node>& nodes() { return nodes_; }

 private:
  const Token& cur() const { return toks_[k_]; }
  void advance() {
    if (toks_[k_].kind != Tok::End) ++k_;
  }
  bool is_op(std::string_view op) const { return cur().kind == Tok::Op && tok_text(cur()) == op; }
  bool is_name(std::string_view name) const {
    return cur().kind == Tok::Name && tok_text(cur()) == name;
  }
  std::string_view tok_text(const Token& t) const { return text_.substr(t.pos, t.len); }
  // The token as quoted in a message (long tokens are shortened).
  std::string shown(const Token& t) const {
    std::string_view s = tok_text(t);
    if (s.size() > 24) return std::string(s.substr(0, 21)) + "...";
    return std::string(s);
  }

  int fail(DiagCode code, std::uint32_t pos, std::string message) {
    sink_.report(code, loc_.shifted(pos), std::move(message));
    return -1;
  }

  int add(Node node) {
    nodes_.push_back(std::move(node));
    return static_cast<int>(nodes_.size() - 1);
  }

  int parse_expr() { return parse_chain(/*additive=*/true); }

  int parse_chain(bool additive) {
    const int first = additive ? parse_chain(false) : parse_unary();
    if (first < 0) return -1;
    Node chain;
    chain.kind = NodeKind::Chain;
    chain.kids.push_back(first);
    for (;;) {
      std::optional<BinOp> op;
      if (cur().kind == Tok::Op) {
        const std::string_view t = tok_text(cur());
        if (additive) {
          if (t == "+") op = BinOp::Add;
          if (t == "-") op = BinOp::Sub;
        } else {
          if (t == "*") op = BinOp::Mul;
          if (t == "/") op = BinOp::Div;
          if (t == "//") op = BinOp::FloorDiv;
          if (t == "%") op = BinOp::Mod;
        }
      }
      if (!op) break;
      chain.ops.push_back({*op, cur().pos});
      advance();
      const int next = additive ? parse_chain(false) : parse_unary();
      if (next < 0) return -1;
      chain.kids.push_back(next);
    }
    if (chain.kids.size() == 1) return first;
    chain.begin = nodes_[static_cast<std::size_t>(chain.kids.front())].begin;
    chain.end = nodes_[static_cast<std::size_t>(chain.kids.back())].end;
    chain.pos = chain.ops.front().pos;
    return add(std::move(chain));
  }

  int parse_unary() {
    // Every recursive path (parentheses, arguments, prefix operators, '**') passes through here.
    struct DepthGuard {
      int& depth;
      explicit DepthGuard(int& d) : depth(d) { ++depth; }
      ~DepthGuard() { --depth; }
    } guard(depth_);
    if (depth_ > kMaxDepth) {
      return fail(DiagCode::expression_syntax, cur().pos,
                  fmt::format("expression is nested too deeply (more than {} levels)", kMaxDepth));
    }
    if (is_op("-") || is_op("+")) {
      Node node;
      node.kind = is_op("-") ? NodeKind::Negate : NodeKind::Plus;
      node.pos = node.begin = cur().pos;
      advance();
      const int operand = parse_unary();
      if (operand < 0) return -1;
      node.kids.push_back(operand);
      node.end = nodes_[static_cast<std::size_t>(operand)].end;
      return add(std::move(node));
    }
    if (is_op("~")) {
      return fail(DiagCode::unsupported_expression, cur().pos,
                  "bitwise operators are not supported in parameter expressions");
    }
    if (is_name("not")) {
      return fail(DiagCode::unsupported_expression, cur().pos,
                  "boolean operators ('and', 'or', 'not') are not supported in parameter "
                  "expressions");
    }
    return parse_power();
  }

  // power := primary ('**' unary)?  (right-associative; binds tighter than a unary minus on its
  // left: -2**2 == -4, 2**-1 == 0.5, 2**3**2 == 512)
  int parse_power() {
    const int base = parse_primary();
    if (base < 0) return -1;
    if (!is_op("**")) return base;
    Node node;
    node.kind = NodeKind::Power;
    node.pos = cur().pos;
    advance();
    const int exponent = parse_unary();
    if (exponent < 0) return -1;
    node.kids = {base, exponent};
    node.begin = nodes_[static_cast<std::size_t>(base)].begin;
    node.end = nodes_[static_cast<std::size_t>(exponent)].end;
    return add(std::move(node));
  }

  int parse_primary() {
    const Token& t = cur();
    int result = -1;
    switch (t.kind) {
      case Tok::Number: {
        Node node;
        node.kind = NodeKind::Literal;
        node.pos = node.begin = t.pos;
        node.end = t.pos + t.len;
        node.value = t.value;
        node.overflow = t.overflow;
        node.digits_only = t.digits_only;
        advance();
        result = add(std::move(node));
        break;
      }
      case Tok::String: {
        // Adjacent string literals are one string, as in Python ('a' "b" == 'ab').
        Node node;
        node.kind = NodeKind::Literal;
        node.pos = node.begin = t.pos;
        node.value = ParamValue::make_string({});
        while (cur().kind == Tok::String) {
          node.value.s += cur().value.s;
          node.end = cur().pos + cur().len;
          advance();
        }
        result = add(std::move(node));
        break;
      }
      case Tok::Name: {
        const std::string_view name = tok_text(t);
        if (is_python_keyword(name)) return keyword_as_operand(t);
        Node node;
        node.pos = node.begin = t.pos;
        node.end = t.pos + t.len;
        node.name = name;
        advance();
        if (is_op("(")) {
          node.kind = NodeKind::Call;
          if (!parse_arguments(node)) return -1;
        } else {
          node.kind = NodeKind::Name;
        }
        result = add(std::move(node));
        break;
      }
      case Tok::Op: {
        const std::string_view op = tok_text(t);
        if (op == "(") {
          const std::uint32_t open = t.pos;
          open_parens_.push_back(open);
          advance();
          if (is_op(")")) {
            return fail(DiagCode::unsupported_expression, open,
                        "tuples are not supported in parameter expressions");
          }
          const int inner = parse_expr();
          if (inner < 0) return -1;
          if (!is_op(")")) return unexpected_after_operand("')'");
          open_parens_.pop_back();
          // The span includes the parentheses (used to quote operands in W0403).
          nodes_[static_cast<std::size_t>(inner)].begin = open;
          nodes_[static_cast<std::size_t>(inner)].end = cur().pos + 1;
          advance();
          result = inner;
          break;
        }
        if (op == "[") {
          return fail(DiagCode::unsupported_expression, t.pos,
                      "lists are not supported in parameter expressions");
        }
        if (op == "{") {
          return fail(DiagCode::unsupported_expression, t.pos,
                      "dictionaries and sets are not supported in parameter expressions");
        }
        return missing_operand();
      }
      case Tok::Error:
        return fail(t.code, t.pos, t.message);
      case Tok::End:
        return missing_operand();
    }
    // Trailers: a call of anything but a function name, attribute access and indexing.
    for (;;) {
      if (is_op("(")) {
        return fail(DiagCode::unsupported_expression, cur().pos,
                    "only built-in functions can be called in parameter expressions");
      }
      if (is_op(".")) return attribute_access(result);
      if (is_op("[")) {
        return fail(DiagCode::unsupported_expression, cur().pos,
                    "indexing is not supported in parameter expressions");
      }
      break;
    }
    return result;
  }

  // '(' [expr (',' expr)* [',']] ')' after a function name.
  bool parse_arguments(Node& call) {
    open_parens_.push_back(cur().pos);
    advance();
    for (;;) {
      if (is_op(")")) break;
      if (cur().kind == Tok::Name && k_ + 1 < toks_.size() && toks_[k_ + 1].kind == Tok::Op &&
          tok_text(toks_[k_ + 1]) == "=") {
        fail(DiagCode::unsupported_expression, cur().pos,
             "keyword arguments are not supported in parameter expressions");
        return false;
      }
      if (is_op("*") || is_op("**")) {
        fail(DiagCode::unsupported_expression, cur().pos,
             "argument unpacking is not supported in parameter expressions");
        return false;
      }
      const int arg = parse_expr();
      if (arg < 0) return false;
      call.kids.push_back(arg);
      if (is_op(",")) {
        advance();
        continue;
      }
      if (is_op(")")) break;
      unexpected_after_operand(fmt::format("',' or ')' in the arguments of '{}'", call.name));
      return false;
    }
    open_parens_.pop_back();
    call.end = cur().pos + 1;
    advance();
    return true;
  }

  int attribute_access(int object) {
    const std::uint32_t dot = cur().pos;
    const Node& obj = nodes_[static_cast<std::size_t>(object)];
    if (obj.kind == NodeKind::Name && k_ + 1 < toks_.size() && toks_[k_ + 1].kind == Tok::Name) {
      const std::string_view attr = tok_text(toks_[k_ + 1]);
      if (obj.name == "math" && (is_builtin_function(attr) || is_builtin_constant(attr))) {
        return fail(DiagCode::unsupported_expression, dot,
                    fmt::format("attribute access ('math.{0}') is not supported in parameter "
                                "expressions; write {0}",
                                attr));
      }
    }
    return fail(DiagCode::unsupported_expression, dot,
                "attribute access is not supported in parameter expressions");
  }

  int keyword_as_operand(const Token& t) {
    const std::string_view word = tok_text(t);
    if (word == "lambda") {
      return fail(DiagCode::unsupported_expression, t.pos,
                  "lambda expressions are not supported in parameter expressions");
    }
    if (word == "True" || word == "False") {
      return fail(DiagCode::unsupported_expression, t.pos,
                  fmt::format("booleans ('{}') are not supported in parameter expressions", word));
    }
    if (word == "None") {
      return fail(DiagCode::unsupported_expression, t.pos,
                  "'None' is not supported in parameter expressions");
    }
    if (word == "import" || word == "from") {
      return fail(DiagCode::unsupported_expression, t.pos,
                  "'import' is not supported in parameter expressions");
    }
    if (word == "yield" || word == "await") {
      return fail(DiagCode::unsupported_expression, t.pos,
                  fmt::format("'{}' is not supported in parameter expressions", word));
    }
    if (word == "not") {
      return fail(DiagCode::unsupported_expression, t.pos,
                  "boolean operators ('and', 'or', 'not') are not supported in parameter "
                  "expressions");
    }
    return fail(DiagCode::expression_syntax, t.pos,
                fmt::format("expected an expression, got the reserved word '{}'", word));
  }

  // An operand was expected at cur().
  int missing_operand() {
    const Token& t = cur();
    if (t.kind == Tok::Error) return fail(t.code, t.pos, t.message);
    if (t.kind == Tok::End && !open_parens_.empty()) return unclosed_paren();
    if (k_ == 0) {
      if (t.kind == Tok::End)
        return fail(DiagCode::expression_syntax, t.pos, "expected an expression");
      return fail(DiagCode::expression_syntax, t.pos,
                  fmt::format("expected an expression, got '{}'", shown(t)));
    }
    return fail(DiagCode::expression_syntax, t.pos,
                fmt::format("expected an expression after '{}'", shown(toks_[k_ - 1])));
  }

  int unclosed_paren() {
    // input-syntax.md §6.2: an open parenthesis would continue the definition on the next line
    // in Python; continuation is not supported.
    return fail(DiagCode::unsupported_expression, open_parens_.back(),
                "'(' is never closed: a definition cannot continue on the next line");
  }

  // A complete operand was parsed and cur() is neither an operator of the grammar nor what the
  // context expects. Names the unsupported construct when there is one (E0407), else E0401.
  int unexpected_after_operand(const std::string& expected) {
    const Token& t = cur();
    const std::uint32_t pos = t.pos;
    auto unsupported = [&](std::string message) {
      return fail(DiagCode::unsupported_expression, pos, std::move(message));
    };
    switch (t.kind) {
      case Tok::Error:
        return fail(t.code, t.pos, t.message);
      case Tok::End:
        if (!open_parens_.empty()) return unclosed_paren();
        return fail(DiagCode::expression_syntax, pos, fmt::format("expected {}", expected));
      case Tok::Op: {
        const std::string_view op = tok_text(t);
        if (op == "==" || op == "!=" || op == "<" || op == ">" || op == "<=" || op == ">=" ||
            op == "<>") {
          return unsupported("comparisons are not supported in parameter expressions");
        }
        if (op == ",") return unsupported("tuples are not supported in parameter expressions");
        if (op == "=") {
          return unsupported(
              "'=' is not allowed inside an expression: one assignment per definition");
        }
        if (op == ":=") {
          return unsupported(
              "assignment expressions (':=') are not supported in parameter "
              "expressions");
        }
        if (op == "&" || op == "|" || op == "^" || op == "<<" || op == ">>" || op == "~") {
          return unsupported("bitwise operators are not supported in parameter expressions");
        }
        if (op == "@") {
          return unsupported("the '@' operator is not supported in parameter expressions");
        }
        if (op.size() >= 2 && op.back() == '=' && op != "!=") {
          return unsupported(fmt::format(
              "augmented assignment ('{}') is not supported: write 'name = name {} ...'", op,
              op.substr(0, op.size() - 1)));
        }
        if (op == "[") return unsupported("indexing is not supported in parameter expressions");
        if (op == ".")
          return unsupported("attribute access is not supported in parameter expressions");
        if (op == ")" && open_parens_.empty()) {
          return fail(DiagCode::expression_syntax, pos, "unmatched ')'");
        }
        break;
      }
      case Tok::Name: {
        const std::string_view word = tok_text(t);
        if (word == "and" || word == "or") {
          return unsupported(
              "boolean operators ('and', 'or', 'not') are not supported in "
              "parameter expressions");
        }
        if (word == "not" || word == "in" || word == "is") {
          return unsupported("comparisons are not supported in parameter expressions");
        }
        if (word == "if" || word == "else") {
          return unsupported(
              "conditional expressions ('... if ... else ...') are not supported "
              "in parameter expressions");
        }
        if (word == "for" || word == "async") {
          return unsupported("comprehensions are not supported in parameter expressions");
        }
        break;
      }
      default:
        break;
    }
    return fail(DiagCode::expression_syntax, pos,
                fmt::format("expected {}, got '{}'", expected, shown(t)));
  }

  std::string_view text_;
  SourceLoc loc_;
  const std::vector<Token>& toks_;
  DiagnosticSink& sink_;
  std::vector<Node> nodes_;
  std::size_t k_ = 0;
  int depth_ = 0;
  std::vector<std::uint32_t> open_parens_;
};

// ---------------------------------------------------------------------------------------------
// Arithmetic helpers (Python semantics)

__extension__ typedef __int128 Int128;  // exact intermediate for round(int, -n)

constexpr double kTwo63 = 9223372036854775808.0;  // 2**63

bool fits_int64(double x) { return x >= -kTwo63 && x < kTwo63; }

// a % b truncated toward zero, for b != 0. INT64_MIN % -1 is undefined behaviour (C++
// [expr.mul]/4: the quotient is not representable) and traps on x86; the remainder by -1 is 0.
std::int64_t truncated_remainder(std::int64_t a, std::int64_t b) { return b == -1 ? 0 : a % b; }

// Python's a // b (rounded toward minus infinity) for b != 0 and (a, b) != (INT64_MIN, -1).
std::int64_t floor_divide(std::int64_t a, std::int64_t b) {
  std::int64_t q = a / b;
  if (truncated_remainder(a, b) != 0 && ((a < 0) != (b < 0))) --q;
  return q;
}

// Python's a % b (the sign of the divisor) for b != 0.
std::int64_t floor_remainder(std::int64_t a, std::int64_t b) {
  std::int64_t r = truncated_remainder(a, b);
  if (r != 0 && ((r < 0) != (b < 0))) r += b;
  return r;
}

// Exact comparison of an int and a float (Python compares them exactly, not via a double).
int compare_int_float(std::int64_t i, double d) {
  if (d >= kTwo63) return -1;
  if (d < -kTwo63) return 1;
  const double t = std::trunc(d);
  const auto ti = static_cast<std::int64_t>(t);
  if (i < ti) return -1;
  if (i > ti) return 1;
  const double frac = d - t;
  return frac > 0 ? -1 : (frac < 0 ? 1 : 0);
}

int compare_numbers(const ParamValue& a, const ParamValue& b) {
  using K = ParamValue::Kind;
  if (a.kind == K::Int && b.kind == K::Int) return a.i < b.i ? -1 : (a.i > b.i ? 1 : 0);
  if (a.kind == K::Int) return compare_int_float(a.i, b.f);
  if (b.kind == K::Int) return -compare_int_float(b.i, a.f);
  return a.f < b.f ? -1 : (a.f > b.f ? 1 : 0);
}

// Python 3 round(x) for a float: nearest integer, ties to even (Python 2 rounded ties away from
// zero and returned a float; §6.3 follows Python 3).
double round_half_even(double x) {
  const double lower = std::floor(x);
  const double diff = x - lower;  // exact for every finite double
  if (diff > 0.5) return lower + 1.0;
  if (diff < 0.5) return lower;
  return std::fmod(lower, 2.0) == 0.0 ? lower : lower + 1.0;
}

// Python 3 round(x, n) for a float: the double nearest to x rounded to n decimal places, ties to
// even on the exact binary value of x (CPython's double_round: round(2.675, 2) == 2.67 because
// 2.675 is stored as 2.67499999...). Works on the exact decimal expansion of x, which printf
// gives in full with 1100 fractional digits (a double has at most 1074).
double round_decimal(double x, std::int64_t n) {
  if (x == 0.0 || n > 323) return x;           // CPython: more digits than a double holds
  if (n < -308) return std::copysign(0.0, x);  // CPython: rounds to zero
  std::array<char, 1500> buf{};
  const int len = std::snprintf(buf.data(), buf.size(), "%.1100f", std::fabs(x));
  if (len <= 0 || static_cast<std::size_t>(len) >= buf.size()) return x;
  const std::string_view s(buf.data(), static_cast<std::size_t>(len));
  std::size_t point = 0;
  while (point < s.size() && is_digit(s[point])) ++point;
  std::string digits(s.substr(0, point));
  for (std::size_t k = point + 1; k < s.size(); ++k) digits.push_back(s[k]);
  const std::int64_t keep = static_cast<std::int64_t>(point) + n;  // leading digits kept
  if (keep < 0) return std::copysign(0.0, x);
  if (keep >= static_cast<std::int64_t>(digits.size())) return x;
  const auto kept = static_cast<std::size_t>(keep);
  const char next = digits[kept];
  bool up = next > '5';
  if (next == '5') {
    const bool rest_nonzero = digits.find_first_not_of('0', kept + 1) != std::string::npos;
    const char last = kept > 0 ? digits[kept - 1] : '0';
    up = rest_nonzero || ((last - '0') % 2 == 1);
  }
  std::string mantissa = digits.substr(0, kept);
  if (mantissa.empty()) mantissa = "0";
  if (up) {
    std::size_t k = mantissa.size();
    while (k > 0) {
      --k;
      if (mantissa[k] == '9') {
        mantissa[k] = '0';
        if (k == 0) mantissa.insert(mantissa.begin(), '1');
      } else {
        ++mantissa[k];
        break;
      }
    }
  }
  const std::string decimal = mantissa + "e" + std::to_string(-n);
  return std::copysign(std::strtod(decimal.c_str(), nullptr), x);
}

// ---------------------------------------------------------------------------------------------
// Evaluator

class Evaluator {
 public:
  Evaluator(std::string_view text, SourceLoc loc, const std::vector<Node>& nodes,
            const ParamLookup& lookup, const ParamDefinedCheck& is_parameter, DiagnosticSink& sink)
      : text_(text),
        loc_(loc),
        nodes_(nodes),
        lookup_(lookup),
        is_parameter_(is_parameter),
        sink_(sink) {}

  // Tree depth is bounded by the parser's depth cap, so this recursion is bounded too.
  bool eval(int index, ParamValue& out) {
    const Node& node = nodes_[static_cast<std::size_t>(index)];
    switch (node.kind) {
      case NodeKind::Literal:
        if (!node.overflow.empty())
          return fail(DiagCode::arithmetic_error, node.pos, node.overflow);
        if (node.value.kind == ParamValue::Kind::String &&
            node.value.s.size() > kMaxParameterStringLength) {
          return string_too_long(node.pos, "this string literal is", node.value.s.size());
        }
        out = node.value;
        return true;
      case NodeKind::Name:
        return eval_name(node, out);
      case NodeKind::Call:
        return eval_call(node, out);
      case NodeKind::Negate:
      case NodeKind::Plus:
        return eval_unary(node, out);
      case NodeKind::Chain:
        return eval_chain(node, out);
      case NodeKind::Power: {
        ParamValue base;
        ParamValue exponent;
        if (!eval(node.kids[0], base) || !eval(node.kids[1], exponent)) return false;
        return power(node.pos, base, exponent, out);
      }
    }
    return false;
  }

 private:
  bool fail(DiagCode code, std::uint32_t pos, std::string message) {
    sink_.report(code, loc_.shifted(pos), std::move(message));
    return false;
  }

  std::string_view span(std::uint32_t begin, std::uint32_t end) const {
    return text_.substr(begin, end - begin);
  }

  bool shadowed(std::string_view name) const { return is_parameter_ && is_parameter_(name); }

  bool eval_name(const Node& node, ParamValue& out) {
    if (!shadowed(node.name)) {
      if (const auto constant = builtin_constant(node.name)) {
        out = ParamValue::make_float(*constant);
        return true;
      }
      if (is_builtin_function(node.name)) {
        return fail(DiagCode::unsupported_expression, node.pos,
                    fmt::format("'{0}' is a function: call it, as in {0}(x)", node.name));
      }
    }
    if (!lookup_) {
      return fail(DiagCode::undefined_parameter, node.pos,
                  fmt::format("undefined parameter '{}'", node.name));
    }
    // The lookup reports undefined and later-defined names, and stays silent for a parameter
    // whose definition already failed (no cascade).
    const ParamValue* value = lookup_(node.name, loc_.shifted(node.pos));
    if (value == nullptr) return false;
    out = *value;
    return true;
  }

  bool eval_unary(const Node& node, ParamValue& out) {
    ParamValue v;
    if (!eval(node.kids[0], v)) return false;
    const bool negate = node.kind == NodeKind::Negate;
    if (v.kind == ParamValue::Kind::String) {
      return fail(DiagCode::parameter_type_error, node.pos,
                  fmt::format("unary '{}' cannot be applied to a string", negate ? '-' : '+'));
    }
    if (!negate) {
      out = v;
      return true;
    }
    if (v.kind == ParamValue::Kind::Int) {
      if (v.i == std::numeric_limits<std::int64_t>::min()) {
        return fail(DiagCode::arithmetic_error, node.pos,
                    fmt::format("integer overflow: -({}) does not fit in 64 bits", v.i));
      }
      out = ParamValue::make_int(-v.i);
    } else {
      out = ParamValue::make_float(-v.f);
    }
    return true;
  }

  bool eval_chain(const Node& node, ParamValue& out) {
    ParamValue acc;
    if (!eval(node.kids[0], acc)) return false;
    const Node& first = nodes_[static_cast<std::size_t>(node.kids[0])];
    for (std::size_t k = 0; k < node.ops.size(); ++k) {
      ParamValue rhs;
      if (!eval(node.kids[k + 1], rhs)) return false;
      const Node& right = nodes_[static_cast<std::size_t>(node.kids[k + 1])];
      // The left operand of op k is everything from the first operand to operand k.
      const Node& left_last = nodes_[static_cast<std::size_t>(node.kids[k])];
      const bool left_is_literal = k == 0 && first.kind == NodeKind::Literal && first.digits_only;
      ParamValue result;
      if (!binary(node.ops[k], acc, rhs, result, first.begin, left_last.end, right,
                  left_is_literal)) {
        return false;
      }
      acc = std::move(result);
    }
    out = std::move(acc);
    return true;
  }

  static std::string_view op_text(BinOp op) {
    switch (op) {
      case BinOp::Add:
        return "+";
      case BinOp::Sub:
        return "-";
      case BinOp::Mul:
        return "*";
      case BinOp::Div:
        return "/";
      case BinOp::FloorDiv:
        return "//";
      case BinOp::Mod:
        return "%";
    }
    return "?";
  }

  bool finite_or_fail(double value, std::uint32_t pos, std::string_view what, ParamValue& out) {
    if (!std::isfinite(value)) {
      return fail(DiagCode::arithmetic_error, pos,
                  fmt::format("the result of '{}' is not finite (floating-point overflow)", what));
    }
    out = ParamValue::make_float(value);
    return true;
  }

  // `what` says which string: "'a + b' would be" or "this string literal is".
  bool string_too_long(std::uint32_t pos, const std::string& what, std::size_t length) {
    return fail(DiagCode::arithmetic_error, pos,
                fmt::format("{} {} characters long; a parameter string may have at most {} "
                            "characters",
                            what, length, kMaxParameterStringLength));
  }

  bool int_overflow(std::uint32_t pos, std::int64_t a, std::string_view op, std::int64_t b) {
    return fail(DiagCode::arithmetic_error, pos,
                fmt::format("integer overflow: {} {} {} does not fit in 64 bits", a, op, b));
  }

  bool binary(OpAt at, const ParamValue& a, const ParamValue& b, ParamValue& out,
              std::uint32_t left_begin, std::uint32_t left_end, const Node& right,
              bool left_is_digit_literal) {
    using K = ParamValue::Kind;
    const std::string_view op = op_text(at.op);
    // Strings: only '+' between two strings (input-syntax.md §6.3).
    if (a.kind == K::String || b.kind == K::String) {
      if (a.kind == K::String && b.kind == K::String) {
        if (at.op == BinOp::Add) {
          // Checked before the concatenation is built, which could otherwise take gigabytes.
          if (a.s.size() + b.s.size() > kMaxParameterStringLength) {
            const std::string_view sum = span(left_begin, right.end);
            const std::string shown =
                sum.size() > 40 ? std::string(sum.substr(0, 37)) + "..." : std::string(sum);
            return string_too_long(at.pos, fmt::format("'{}' would be", shown),
                                   a.s.size() + b.s.size());
          }
          out = ParamValue::make_string(a.s + b.s);
          return true;
        }
        return fail(DiagCode::parameter_type_error, at.pos,
                    fmt::format("operator '{}' cannot be applied to strings", op));
      }
      if (at.op == BinOp::Add) {
        return fail(DiagCode::parameter_type_error, at.pos, "cannot add a string and a number");
      }
      return fail(DiagCode::parameter_type_error, at.pos,
                  fmt::format("operator '{}' cannot be applied to a string and a number", op));
    }
    const bool ints = a.kind == K::Int && b.kind == K::Int;
    if (ints) {
      std::int64_t r = 0;
      switch (at.op) {
        case BinOp::Add:
          if (__builtin_add_overflow(a.i, b.i, &r)) return int_overflow(at.pos, a.i, op, b.i);
          out = ParamValue::make_int(r);
          return true;
        case BinOp::Sub:
          if (__builtin_sub_overflow(a.i, b.i, &r)) return int_overflow(at.pos, a.i, op, b.i);
          out = ParamValue::make_int(r);
          return true;
        case BinOp::Mul:
          if (__builtin_mul_overflow(a.i, b.i, &r)) return int_overflow(at.pos, a.i, op, b.i);
          out = ParamValue::make_int(r);
          return true;
        case BinOp::FloorDiv:
          if (b.i == 0) return fail(DiagCode::arithmetic_error, at.pos, "division by zero");
          if (a.i == std::numeric_limits<std::int64_t>::min() && b.i == -1) {
            return int_overflow(at.pos, a.i, op, b.i);
          }
          out = ParamValue::make_int(floor_divide(a.i, b.i));
          return true;
        case BinOp::Mod:
          if (b.i == 0) return fail(DiagCode::arithmetic_error, at.pos, "division by zero");
          out = ParamValue::make_int(floor_remainder(a.i, b.i));
          return true;
        case BinOp::Div:
          break;  // true division, below
      }
    }
    const double x = a.as_double();
    const double y = b.as_double();
    switch (at.op) {
      case BinOp::Add:
        return finite_or_fail(x + y, at.pos, op, out);
      case BinOp::Sub:
        return finite_or_fail(x - y, at.pos, op, out);
      case BinOp::Mul:
        return finite_or_fail(x * y, at.pos, op, out);
      case BinOp::Div: {
        if (y == 0.0) return fail(DiagCode::arithmetic_error, at.pos, "division by zero");
        // For ints up to 2**53 the double quotient is the correctly rounded one Python gives.
        if (!finite_or_fail(x / y, at.pos, op, out)) return false;
        if (ints && truncated_remainder(a.i, b.i) != 0)
          warn_integer_division(at, a, b, out, left_begin, left_end, right, left_is_digit_literal);
        return true;
      }
      case BinOp::FloorDiv:
      case BinOp::Mod: {
        if (y == 0.0) return fail(DiagCode::arithmetic_error, at.pos, "division by zero");
        // CPython float_divmod, so that -7.5 // 2 == -4.0 and -7.5 % 2 == 0.5.
        double mod = std::fmod(x, y);
        double div = (x - mod) / y;
        if (mod != 0.0) {
          if ((y < 0) != (mod < 0)) {
            mod += y;
            div -= 1.0;
          }
        } else {
          mod = std::copysign(0.0, y);
        }
        double floordiv = 0.0;
        if (div != 0.0) {
          floordiv = std::floor(div);
          if (div - floordiv > 0.5) floordiv += 1.0;
        } else {
          floordiv = std::copysign(0.0, x / y);
        }
        return finite_or_fail(at.op == BinOp::Mod ? mod : floordiv, at.pos, op, out);
      }
    }
    return false;
  }

  // W0403 (input-syntax.md §6.3): int/int that is not exact; Python 2 truncates (floors) it.
  void warn_integer_division(OpAt at, const ParamValue& a, const ParamValue& b,
                             const ParamValue& quotient, std::uint32_t left_begin,
                             std::uint32_t left_end, const Node& right,
                             bool left_is_digit_literal) {
    const std::int64_t floored = floor_divide(a.i, b.i);
    const std::string_view left = span(left_begin, left_end);
    const std::string fixed_left =
        left_is_digit_literal ? std::string(left) + ".0" : fmt::format("float({})", left);
    sink_.report(DiagCode::integer_division, loc_.shifted(at.pos),
                 fmt::format("'{}' is {} here but {} in Abaqus versions that use Python 2; "
                             "write {}{}",
                             span(left_begin, right.end), quotient.to_display(), floored,
                             fixed_left, span(left_end, right.end)));
  }

  bool power(std::uint32_t pos, const ParamValue& a, const ParamValue& b, ParamValue& out) {
    using K = ParamValue::Kind;
    if (a.kind == K::String || b.kind == K::String) {
      return fail(DiagCode::parameter_type_error, pos,
                  a.kind == K::String && b.kind == K::String
                      ? "operator '**' cannot be applied to strings"
                      : "operator '**' cannot be applied to a string and a number");
    }
    if (a.kind == K::Int && b.kind == K::Int && b.i >= 0) {
      // Exact, by repeated squaring. The base is squared only while exponent bits remain, so
      // an overflow there means the result overflows too (|base| >= 2).
      std::int64_t result = 1;
      std::int64_t base = a.i;
      std::int64_t e = b.i;
      while (e > 0) {
        if ((e & 1) != 0 && __builtin_mul_overflow(result, base, &result)) {
          return int_overflow(pos, a.i, "**", b.i);
        }
        e >>= 1;
        if (e > 0 && __builtin_mul_overflow(base, base, &base)) {
          return int_overflow(pos, a.i, "**", b.i);
        }
      }
      out = ParamValue::make_int(result);
      return true;
    }
    // Float power (also int ** negative int, which is a float in Python 3).
    const double x = a.as_double();
    const double y = b.as_double();
    if (y == 0.0) {
      out = ParamValue::make_float(1.0);
      return true;
    }
    if (x == 0.0 && y < 0.0) {
      return fail(DiagCode::arithmetic_error, pos, "zero cannot be raised to a negative power");
    }
    if (x < 0.0 && std::trunc(y) != y) {
      // Python 3 gives a complex number here, Python 2 a ValueError; neither is a parameter value.
      return fail(DiagCode::arithmetic_error, pos,
                  "a negative number cannot be raised to a fractional power");
    }
    return finite_or_fail(std::pow(x, y), pos, "**", out);
  }

  std::string call_text(std::string_view name, const std::vector<ParamValue>& args) const {
    std::string s = fmt::format("{}(", name);
    for (std::size_t k = 0; k < args.size(); ++k) {
      if (k > 0) s += ", ";
      s += args[k].to_display();
    }
    s += ')';
    return s;
  }

  bool eval_call(const Node& node, ParamValue& out) {
    const std::string_view name = node.name;
    if (shadowed(name)) {
      return fail(DiagCode::parameter_type_error, node.pos,
                  fmt::format("'{}' is a parameter, not a function", name));
    }
    if (is_builtin_constant(name)) {
      return fail(DiagCode::parameter_type_error, node.pos,
                  fmt::format("'{}' is a constant, not a function", name));
    }
    const FnInfo* info = find_function(name);
    if (info == nullptr) {
      Diagnostic& d = sink_.report(DiagCode::unknown_function, loc_.shifted(node.pos),
                                   fmt::format("unknown function '{}'", name));
      std::array<std::string_view, kFunctions.size()> names{};
      for (std::size_t k = 0; k < kFunctions.size(); ++k) names[k] = kFunctions[k].name;
      if (auto match = closest_match(name, std::span<const std::string_view>(names))) {
        d.notes.push_back({SourceLoc{}, fmt::format("did you mean '{}'?", *match)});
      }
      return false;
    }
    const int given = static_cast<int>(node.kids.size());
    if (given < info->min_args || (info->max_args >= 0 && given > info->max_args)) {
      std::string takes;
      if (info->max_args < 0) {
        takes = fmt::format("at least {} arguments", info->min_args);
      } else if (info->min_args == info->max_args) {
        takes = fmt::format("{} argument{}", info->min_args, info->min_args == 1 ? "" : "s");
      } else {
        takes = fmt::format("{} or {} arguments", info->min_args, info->max_args);
      }
      return fail(DiagCode::wrong_argument_count, node.pos,
                  fmt::format("{} takes {}, {} given", name, takes, given));
    }
    std::vector<ParamValue> args(node.kids.size());
    for (std::size_t k = 0; k < node.kids.size(); ++k) {
      if (!eval(node.kids[k], args[k])) return false;
      if (args[k].kind == ParamValue::Kind::String) {
        return fail(DiagCode::parameter_type_error,
                    nodes_[static_cast<std::size_t>(node.kids[k])].begin,
                    fmt::format("{}() expects a number, got a string", name));
      }
    }
    return apply(*info, node, args, out);
  }

  bool domain_error(const Node& node, const std::vector<ParamValue>& args) {
    return fail(DiagCode::arithmetic_error, node.pos,
                fmt::format("math domain error in {}", call_text(node.name, args)));
  }
  bool range_error(const Node& node, const std::vector<ParamValue>& args) {
    return fail(DiagCode::arithmetic_error, node.pos,
                fmt::format("math range error in {}", call_text(node.name, args)));
  }
  // A float result of a math function: non-finite → E0406.
  bool float_result(const Node& node, const std::vector<ParamValue>& args, double value,
                    ParamValue& out) {
    if (!std::isfinite(value)) return range_error(node, args);
    out = ParamValue::make_float(value);
    return true;
  }
  // A float converted to an int (int, round, floor, ceil): must fit in 64 bits.
  bool int_result(const Node& node, const std::vector<ParamValue>& args, double value,
                  ParamValue& out) {
    if (!fits_int64(value)) {
      return fail(
          DiagCode::arithmetic_error, node.pos,
          fmt::format("integer overflow: {} does not fit in 64 bits", call_text(node.name, args)));
    }
    out = ParamValue::make_int(static_cast<std::int64_t>(value));
    return true;
  }

  bool apply(const FnInfo& info, const Node& node, const std::vector<ParamValue>& args,
             ParamValue& out) {
    using K = ParamValue::Kind;
    const ParamValue& a = args[0];
    const double x = a.as_double();
    const double y = args.size() > 1 ? args[1].as_double() : 0.0;
    switch (info.fn) {
      case Fn::Abs:
        if (a.kind == K::Int) {
          if (a.i == std::numeric_limits<std::int64_t>::min()) {
            return fail(DiagCode::arithmetic_error, node.pos,
                        fmt::format("integer overflow: {} does not fit in 64 bits",
                                    call_text(node.name, args)));
          }
          out = ParamValue::make_int(a.i < 0 ? -a.i : a.i);
        } else {
          out = ParamValue::make_float(std::fabs(a.f));
        }
        return true;
      case Fn::Min:
      case Fn::Max: {
        // Python returns the first extreme argument itself, with its type.
        std::size_t best = 0;
        for (std::size_t k = 1; k < args.size(); ++k) {
          const int c = compare_numbers(args[k], args[best]);
          if (info.fn == Fn::Min ? c < 0 : c > 0) best = k;
        }
        out = args[best];
        return true;
      }
      case Fn::Int:
        if (a.kind == K::Int) {
          out = a;
          return true;
        }
        return int_result(node, args, std::trunc(a.f), out);  // toward zero
      case Fn::Float:
        out = ParamValue::make_float(x);
        return true;
      case Fn::Round:
        if (args.size() == 1) {
          if (a.kind == K::Int) {
            out = a;
            return true;
          }
          return int_result(node, args, round_half_even(a.f), out);
        }
        if (args[1].kind != K::Int) {
          return fail(DiagCode::parameter_type_error,
                      nodes_[static_cast<std::size_t>(node.kids[1])].begin,
                      fmt::format("round() needs an integer number of decimal places, got {}",
                                  args[1].to_display()));
        }
        if (a.kind == K::Int) return round_int(node, args, out);
        return float_result(node, args, round_decimal(a.f, args[1].i), out);
      case Fn::Sqrt:
        if (x < 0.0) return domain_error(node, args);
        return float_result(node, args, std::sqrt(x), out);
      case Fn::Exp:
        return float_result(node, args, std::exp(x), out);
      case Fn::Log: {
        if (x <= 0.0) return domain_error(node, args);
        if (args.size() == 1) return float_result(node, args, std::log(x), out);
        if (y <= 0.0) return domain_error(node, args);
        const double den = std::log(y);
        if (den == 0.0) {
          return fail(DiagCode::arithmetic_error, node.pos,
                      fmt::format("division by zero in {}", call_text(node.name, args)));
        }
        return float_result(node, args, std::log(x) / den, out);
      }
      case Fn::Log10:
        if (x <= 0.0) return domain_error(node, args);
        return float_result(node, args, std::log10(x), out);
      case Fn::Pow:
        // math.pow: always a float; domain errors where Python raises ValueError.
        if (y == 0.0) {
          out = ParamValue::make_float(1.0);
          return true;
        }
        if ((x == 0.0 && y < 0.0) || (x < 0.0 && std::trunc(y) != y)) {
          return domain_error(node, args);
        }
        return float_result(node, args, std::pow(x, y), out);
      case Fn::Sin:
        return float_result(node, args, std::sin(x), out);
      case Fn::Cos:
        return float_result(node, args, std::cos(x), out);
      case Fn::Tan:
        return float_result(node, args, std::tan(x), out);
      case Fn::Asin:
        if (x < -1.0 || x > 1.0) return domain_error(node, args);
        return float_result(node, args, std::asin(x), out);
      case Fn::Acos:
        if (x < -1.0 || x > 1.0) return domain_error(node, args);
        return float_result(node, args, std::acos(x), out);
      case Fn::Atan:
        return float_result(node, args, std::atan(x), out);
      case Fn::Atan2:
        return float_result(node, args, std::atan2(x, y), out);
      case Fn::Sinh:
        return float_result(node, args, std::sinh(x), out);
      case Fn::Cosh:
        return float_result(node, args, std::cosh(x), out);
      case Fn::Tanh:
        return float_result(node, args, std::tanh(x), out);
      // CPython: degrees(x) = x * (180/pi), radians(x) = x * (pi/180), in that order.
      case Fn::Degrees:
        return float_result(node, args, x * (180.0 / 3.141592653589793), out);
      case Fn::Radians:
        return float_result(node, args, x * (3.141592653589793 / 180.0), out);
      case Fn::Floor:
        if (a.kind == K::Int) {
          out = a;
          return true;
        }
        return int_result(node, args, std::floor(a.f), out);
      case Fn::Ceil:
        if (a.kind == K::Int) {
          out = a;
          return true;
        }
        return int_result(node, args, std::ceil(a.f), out);
      case Fn::Fabs:
        return float_result(node, args, std::fabs(x), out);
      case Fn::Fmod:
        if (y == 0.0) return domain_error(node, args);
        return float_result(node, args, std::fmod(x, y), out);
      case Fn::Hypot:
        return float_result(node, args, std::hypot(x, y), out);
    }
    return false;
  }

  // Python 3 round(int, n): unchanged for n >= 0; for n < 0 the nearest multiple of 10**-n,
  // ties to even (round(25, -1) == 20).
  bool round_int(const Node& node, const std::vector<ParamValue>& args, ParamValue& out) {
    const std::int64_t v = args[0].i;
    const std::int64_t n = args[1].i;
    if (n >= 0) {
      out = args[0];
      return true;
    }
    if (n < -38) {  // 10**39 exceeds Int128; every int64 rounds to 0 long before that
      out = ParamValue::make_int(0);
      return true;
    }
    Int128 p = 1;
    for (std::int64_t k = 0; k < -n; ++k) p *= 10;
    const Int128 x = v;
    Int128 q = x / p;
    Int128 r = x - q * p;
    if (r < 0) {  // floor division
      q -= 1;
      r += p;
    }
    if (2 * r > p || (2 * r == p && (q % 2 != 0))) q += 1;
    const Int128 result = q * p;
    if (result > std::numeric_limits<std::int64_t>::max() ||
        result < std::numeric_limits<std::int64_t>::min()) {
      return fail(
          DiagCode::arithmetic_error, node.pos,
          fmt::format("integer overflow: {} does not fit in 64 bits", call_text(node.name, args)));
    }
    out = ParamValue::make_int(static_cast<std::int64_t>(result));
    return true;
  }

  std::string_view text_;
  SourceLoc loc_;
  const std::vector<Node>& nodes_;
  const ParamLookup& lookup_;
  const ParamDefinedCheck& is_parameter_;
  DiagnosticSink& sink_;
};

}  // namespace

std::optional<ParamValue> evaluate_expression(std::string_view text, SourceLoc text_loc,
                                              const ParamLookup& lookup, DiagnosticSink& sink,
                                              const ParamDefinedCheck& is_parameter) {
  // Offsets are stored as 32-bit columns; a longer text is cut there (its tail is reported as
  // a syntax error rather than mis-located).
  constexpr std::size_t kMaxText = 0x7fffffffu;
  if (text.size() > kMaxText) {
    sink.report(DiagCode::expression_syntax, text_loc.shifted(0), "expression is too long");
    return std::nullopt;
  }
  try {
    const std::vector<Token> tokens = Lexer(text).run();
    Parser parser(text, text_loc, tokens, sink);
    const int root = parser.parse();
    if (root < 0) return std::nullopt;
    Evaluator evaluator(text, text_loc, parser.nodes(), lookup, is_parameter, sink);
    ParamValue value;
    if (!evaluator.eval(root, value)) return std::nullopt;
    return value;
  } catch (...) {
    // Only allocation failure can get here (a lookup callback that throws is the caller's bug,
    // but it must not escape either). Report it as an error on the expression.
    sink.report(DiagCode::expression_syntax, text_loc, "expression could not be evaluated");
    return std::nullopt;
  }
}

}  // namespace clinch
