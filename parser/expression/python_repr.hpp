// Python's repr of a float and of a str: how a parameter value is shown in diagnostics and how a
// substituted value is written into a field (input-syntax.md §6.3).
#pragma once

#include <string>
#include <string_view>

namespace clinch::expression_detail {

// Python repr of a float: 3.0, 1.25, 1e-05, 1e+16, inf, nan.
std::string float_repr(double x);
// Python repr of a str: 'abc', "it's".
std::string string_repr(std::string_view s);

}  // namespace clinch::expression_detail
