// The *PARAMETER expression language (input-syntax.md §6.3): a small, Python-compatible subset
// with int, float and string values. Text is lexed, parsed into a tree and then evaluated, so a
// syntax error is always reported before any evaluation error, and at most one error per
// expression.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "base/diagnostic.hpp"
#include "base/source_location.hpp"

namespace clinch {

// A parameter value. Python types: int (64-bit here, arbitrary in Python: overflow is an error,
// §6.3), float (double) and str.
struct ParamValue {
  enum class Kind { Int, Float, String };
  Kind kind = Kind::Int;
  std::int64_t i = 0;
  double f = 0.0;
  std::string s;

  static ParamValue make_int(std::int64_t value);
  static ParamValue make_float(double value);
  static ParamValue make_string(std::string value);

  bool is_number() const { return kind != Kind::String; }
  // The numeric value as a double (Int or Float; 0 for a String).
  double as_double() const;
  // Python repr: 3, 1.25, 1e-05, 3.0, 'abc'.
  std::string to_display() const;
};

// The longest string a parameter may hold (docs/decisions.md, "Parameter expressions"): far longer
// than any Abaqus data line (256 characters), and small enough that doubling a string from line to
// line cannot exhaust memory.
inline constexpr std::size_t kMaxParameterStringLength = 65536;

// Name resolution for evaluation: returns nullptr when the name is not (yet) defined. The
// callback reports E0402/E0403 itself; the evaluator then fails without a further diagnostic. It
// also returns nullptr, silently, for a parameter whose own definition failed (no cascade).
using ParamLookup = std::function<const ParamValue*(std::string_view name, SourceLoc use_loc)>;

// Whether a parameter of this name is defined at this point, without reporting anything. Asked
// for names that are also built-ins (pi, e, sqrt, ...), because a parameter defined earlier hides
// the built-in (input-syntax.md §6.2, W0404), and for called names, to tell "not a function"
// (E0405) from "unknown function" (E0408). An empty function means "no parameter is defined".
using ParamDefinedCheck = std::function<bool(std::string_view name)>;

// Evaluates one expression. text_loc is the location of text[0]; every diagnostic is located at
// text_loc shifted by the byte offset of the offending character. A '#' outside a string ends the
// expression (comment, §6.2). Reports into sink; returns nullopt after an error (warnings such as
// W0403 do not stop evaluation). Never throws.
std::optional<ParamValue> evaluate_expression(std::string_view text, SourceLoc text_loc,
                                              const ParamLookup& lookup, DiagnosticSink& sink,
                                              const ParamDefinedCheck& is_parameter = {});

// True for the names of §6.3 built-in functions and constants (for W0404).
bool is_builtin_function(std::string_view name);
bool is_builtin_constant(std::string_view name);
// True for the Python keywords listed in input-syntax.md §6.2 (E0404).
bool is_python_keyword(std::string_view name);

// Lexical helpers shared with the *PARAMETER pre-pass, so that both agree on what is inside a
// string literal. skip_string_literal: text[pos] starts a string literal (a quote, possibly after
// a prefix such as r or u); returns the offset just after its closing quote, or text.size() when
// it is unterminated. find_comment: offset of the first '#' outside string literals, or npos.
std::size_t skip_string_literal(std::string_view text, std::size_t pos);
std::size_t find_comment(std::string_view text);

}  // namespace clinch
