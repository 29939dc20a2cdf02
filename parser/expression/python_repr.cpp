#include "parser/expression/python_repr.hpp"

#include <fmt/format.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace clinch::expression_detail {

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

}  // namespace clinch::expression_detail
