// The built-in functions and constants of *PARAMETER expressions (input-syntax.md §6.3).
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace clinch::expression_detail {

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
inline constexpr std::array<FnInfo, 28> kFunctions = {{
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

// The entry of kFunctions with this name, or nullptr.
const FnInfo* find_function(std::string_view name);

// Python's math.pi and math.e.
std::optional<double> builtin_constant(std::string_view name);

}  // namespace clinch::expression_detail
