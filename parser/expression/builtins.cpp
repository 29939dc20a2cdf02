#include "parser/expression/builtins.hpp"

#include <algorithm>

#include "parser/expression.hpp"

namespace clinch::expression_detail {

const FnInfo* find_function(std::string_view name) {
  for (const FnInfo& info : kFunctions) {
    if (info.name == name) return &info;
  }
  return nullptr;
}

std::optional<double> builtin_constant(std::string_view name) {
  if (name == "pi") return 3.141592653589793;
  if (name == "e") return 2.718281828459045;
  return std::nullopt;
}

}  // namespace clinch::expression_detail

namespace clinch {

using expression_detail::builtin_constant;
using expression_detail::find_function;

namespace {

// The Python keywords of input-syntax.md §6.2: never parameter names (E0404).
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

}  // namespace clinch
