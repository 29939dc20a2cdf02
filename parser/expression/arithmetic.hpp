// Python semantics of int and float arithmetic that C++ does not give directly: floor division
// and remainder, exact int–float comparison, round() with ties to even (input-syntax.md §6.3).
#pragma once

#include <cstdint>

#include "parser/expression.hpp"

namespace clinch::expression_detail {

// Whether a float (already integral) fits in an int64.
bool fits_int64(double x);

// a % b truncated toward zero, for b != 0 (also for INT64_MIN % -1).
std::int64_t truncated_remainder(std::int64_t a, std::int64_t b);

// Python's a // b (rounded toward minus infinity) for b != 0 and (a, b) != (INT64_MIN, -1).
std::int64_t floor_divide(std::int64_t a, std::int64_t b);

// Python's a % b (the sign of the divisor) for b != 0.
std::int64_t floor_remainder(std::int64_t a, std::int64_t b);

// Python's comparison of two numbers (int or float, exact): -1, 0 or 1.
int compare_numbers(const ParamValue& a, const ParamValue& b);

// Python 3 round(x) for a float: nearest integer, ties to even.
double round_half_even(double x);

// Python 3 round(x, n) for a float, ties to even on the exact binary value of x.
double round_decimal(double x, std::int64_t n);

}  // namespace clinch::expression_detail
