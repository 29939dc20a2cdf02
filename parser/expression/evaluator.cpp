#include "parser/expression/evaluator.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <utility>

#include "base/suggest.hpp"
#include "parser/expression/arithmetic.hpp"
#include "parser/expression/builtins.hpp"

namespace clinch::expression_detail {

namespace {

__extension__ typedef __int128 Int128;  // exact intermediate for round(int, -n)

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

  // Tree depth is bounded by the parser's depth cap (kMaxDepth, parser.cpp), so this recursion is
  // bounded too.
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

bool evaluate_tree(std::string_view text, SourceLoc loc, const std::vector<Node>& nodes, int root,
                   const ParamLookup& lookup, const ParamDefinedCheck& is_parameter,
                   DiagnosticSink& sink, ParamValue& out) {
  Evaluator evaluator(text, loc, nodes, lookup, is_parameter, sink);
  return evaluator.eval(root, out);
}

}  // namespace clinch::expression_detail
