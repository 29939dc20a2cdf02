#include "parser/expression/arithmetic.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "parser/expression/characters.hpp"

namespace clinch::expression_detail {

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
  if (mantissa.empty()) mantissa.push_back('0');
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

}  // namespace clinch::expression_detail
