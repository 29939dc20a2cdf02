// Unit tests of the *PARAMETER expression language (input-syntax.md §6.3): values against hand
// calculations and Python 3, and every diagnostic with its code and exact column.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <string_view>

#include "base/diagnostic.hpp"
#include "parser/expression.hpp"

namespace clinch {
namespace {

// The expression text starts at line 7, column 10 of file 0, so offset k is column 10 + k.
constexpr std::uint32_t kColumn = 10;
constexpr SourceLoc kLoc{0, 7, kColumn};

struct Result {
  std::optional<ParamValue> value;
  DiagnosticSink sink;
};

// Parameters visible to the expressions of these tests; an unknown name is reported as E0402, as
// the pre-pass does.
const std::map<std::string, ParamValue, std::less<>>& test_parameters() {
  static const std::map<std::string, ParamValue, std::less<>> params = {
      {"I_xx", ParamValue::make_float(30.68)},
      {"A", ParamValue::make_float(19.63)},
      {"n", ParamValue::make_int(7)},
      {"name", ParamValue::make_string("weld")},
      {"big", ParamValue::make_int(std::numeric_limits<std::int64_t>::max())},
  };
  return params;
}

Result run(std::string_view text, const ParamDefinedCheck& is_parameter = {}) {
  Result r;
  DiagnosticSink* sink = &r.sink;
  const ParamLookup lookup = [sink](std::string_view name, SourceLoc loc) -> const ParamValue* {
    const auto& params = test_parameters();
    if (auto it = params.find(name); it != params.end()) return &it->second;
    sink->report(DiagCode::undefined_parameter, loc,
                 "undefined parameter '" + std::string(name) + "'");
    return nullptr;
  };
  r.value = evaluate_expression(text, kLoc, lookup, r.sink, is_parameter);
  return r;
}

std::int64_t int_value(std::string_view text) {
  const Result r = run(text);
  EXPECT_TRUE(r.sink.diagnostics().empty()) << text << ": " << r.sink.diagnostics()[0].message;
  EXPECT_TRUE(r.value.has_value()) << text;
  if (!r.value) return 0;
  EXPECT_EQ(r.value->kind, ParamValue::Kind::Int) << text;
  return r.value->i;
}

double float_value(std::string_view text) {
  const Result r = run(text);
  EXPECT_TRUE(r.sink.diagnostics().empty()) << text << ": " << r.sink.diagnostics()[0].message;
  EXPECT_TRUE(r.value.has_value()) << text;
  if (!r.value) return std::nan("");
  EXPECT_EQ(r.value->kind, ParamValue::Kind::Float) << text;
  return r.value->f;
}

// Exactly one diagnostic, an error with this code, at offset `offset` of the text, whose message
// contains `message` (empty: not checked). Evaluation must fail.
void expect_error(std::string_view text, DiagCode code, std::uint32_t offset,
                  std::string_view message = {}) {
  SCOPED_TRACE(std::string(text));
  const Result r = run(text);
  EXPECT_FALSE(r.value.has_value());
  ASSERT_EQ(r.sink.diagnostics().size(), 1u);
  const Diagnostic& d = r.sink.diagnostics()[0];
  EXPECT_EQ(diag_code_id(d.code), diag_code_id(code)) << d.message;
  EXPECT_EQ(d.severity, Severity::Error);
  EXPECT_EQ(d.loc, (SourceLoc{0, 7, kColumn + offset})) << d.message;
  if (!message.empty()) {
    EXPECT_NE(d.message.find(message), std::string::npos) << d.message;
  }
}

// ---- values ---------------------------------------------------------------------------------

TEST(Expression, NumberLiterals) {
  EXPECT_EQ(int_value("3"), 3);
  EXPECT_EQ(float_value("3."), 3.0);
  EXPECT_EQ(float_value(".5"), 0.5);
  EXPECT_EQ(float_value("1e-3"), 1e-3);
  EXPECT_EQ(float_value("2E+5"), 2e5);
  EXPECT_EQ(int_value("0x1F"), 31);
  EXPECT_EQ(int_value("0o17"), 15);
  EXPECT_EQ(int_value("0b101"), 5);
  EXPECT_EQ(int_value("1_000"), 1000);
  EXPECT_EQ(int_value("0"), 0);
  EXPECT_EQ(int_value("00"), 0);
  EXPECT_EQ(int_value("9223372036854775807"), std::numeric_limits<std::int64_t>::max());
  EXPECT_EQ(float_value("1e-400"), 0.0);  // underflow is 0.0 in Python, not an error
}

TEST(Expression, Precedence) {
  // input-syntax.md §6.3: ** is right-associative and binds tighter than a unary minus on its
  // left.
  EXPECT_EQ(int_value("-2**2"), -4);
  EXPECT_EQ(float_value("2**-1"), 0.5);
  EXPECT_EQ(int_value("2**3**2"), 512);
  EXPECT_EQ(int_value("(-2)**2"), 4);
  EXPECT_EQ(int_value("-3**2"), -9);
  EXPECT_EQ(float_value("2**-2**2"), 0.0625);  // 2**(-(2**2))
  EXPECT_EQ(int_value("2*3**2"), 18);
  EXPECT_EQ(int_value("2+3*4"), 14);
  EXPECT_EQ(int_value("(2+3)*4"), 20);
  EXPECT_EQ(int_value("10-4-3"), 3);
  EXPECT_EQ(float_value("100/10/5"), 2.0);
  EXPECT_EQ(int_value("- - +3"), 3);
  EXPECT_EQ(int_value("2**0"), 1);
  EXPECT_EQ(int_value("(-2)**63"), std::numeric_limits<std::int64_t>::min());
  EXPECT_EQ(int_value("2**62"), std::int64_t{1} << 62);
}

TEST(Expression, FloorDivisionAndModuloFollowPython) {
  EXPECT_EQ(int_value("7//2"), 3);
  EXPECT_EQ(int_value("-7//2"), -4);
  EXPECT_EQ(int_value("-7%2"), 1);
  EXPECT_EQ(int_value("7%-2"), -1);
  EXPECT_EQ(int_value("-7%-2"), -1);
  EXPECT_EQ(int_value("(-9223372036854775807-1)%-1"), 0);
  EXPECT_EQ(float_value("7.5//2"), 3.0);
  EXPECT_EQ(float_value("-7.5//2"), -4.0);
  EXPECT_EQ(float_value("-7.5%2"), 0.5);
  EXPECT_EQ(float_value("7.5%-2"), -0.5);
  EXPECT_EQ(float_value("7.5//-2"), -4.0);
}

TEST(Expression, TrueDivisionIsFloatAndWarnsWhenInexact) {
  const Result r = run("7/2");
  ASSERT_TRUE(r.value.has_value());
  EXPECT_EQ(r.value->kind, ParamValue::Kind::Float);
  EXPECT_EQ(r.value->f, 3.5);
  ASSERT_EQ(r.sink.diagnostics().size(), 1u);
  const Diagnostic& d = r.sink.diagnostics()[0];
  EXPECT_EQ(d.code, DiagCode::integer_division);
  EXPECT_EQ(d.severity, Severity::Warning);
  EXPECT_EQ(d.loc, (SourceLoc{0, 7, kColumn + 1}));  // the '/'
  EXPECT_EQ(d.message, "'7/2' is 3.5 here but 3 in Abaqus versions that use Python 2; write 7.0/2");

  const Result named = run("1 + n / 2");
  ASSERT_EQ(named.sink.diagnostics().size(), 1u);
  EXPECT_EQ(named.sink.diagnostics()[0].message,
            "'n / 2' is 3.5 here but 3 in Abaqus versions that use Python 2; write float(n) / 2");
  EXPECT_EQ(named.sink.diagnostics()[0].loc, (SourceLoc{0, 7, kColumn + 6}));

  // Python 2 floors: -7/2 is -4 there.
  const Result negative = run("-7/2");
  ASSERT_EQ(negative.sink.diagnostics().size(), 1u);
  EXPECT_NE(negative.sink.diagnostics()[0].message.find("but -4 in"), std::string::npos);

  EXPECT_EQ(float_value("6/3"), 2.0);  // exact: no warning
  EXPECT_EQ(float_value("7.0/2"), 3.5);
  EXPECT_EQ(float_value("7/2.0"), 3.5);
}

TEST(Expression, IntegerOverflowIsAnError) {
  expect_error("9223372036854775807 + 1", DiagCode::arithmetic_error, 20, "integer overflow");
  expect_error("big * 2", DiagCode::arithmetic_error, 4, "integer overflow");
  expect_error("2**63", DiagCode::arithmetic_error, 1, "integer overflow");
  expect_error("3037000500*3037000500", DiagCode::arithmetic_error, 10);
  expect_error("-(-9223372036854775807-1)", DiagCode::arithmetic_error, 0);
  expect_error("(-9223372036854775807-1)//-1", DiagCode::arithmetic_error, 24);
  expect_error("abs(-9223372036854775807-1)", DiagCode::arithmetic_error, 0);
  expect_error("9223372036854775808", DiagCode::arithmetic_error, 0, "does not fit in 64 bits");
  expect_error("0xFFFFFFFFFFFFFFFFFF", DiagCode::arithmetic_error, 0);
}

// INT64_MIN by -1 is the one int64 quotient that does not fit (its C++ remainder is undefined and
// traps on x86). Python 3 gives a float for '/', exact here so without W0403, and 0 for '%';
// '//' overflows 64 bits (E0406, tested above). The other divisors behave as in Python.
TEST(Expression, MostNegativeIntegerDividedByMinusOne) {
  const std::int64_t min = std::numeric_limits<std::int64_t>::min();
  EXPECT_EQ(float_value("(-9223372036854775807-1)/-1"), 9223372036854775808.0);
  EXPECT_EQ(int_value("(-9223372036854775807-1)%-1"), 0);
  EXPECT_EQ(float_value("(-9223372036854775807-1)%-1.0"), 0.0);
  EXPECT_EQ(int_value("(-9223372036854775807-1)//1"), min);
  EXPECT_EQ(int_value("(-9223372036854775807-1)//7"), -1317624576693539402);
  EXPECT_EQ(int_value("(-9223372036854775807-1)%7"), 6);
  EXPECT_EQ(int_value("(-2)**63"), min);
  // A floored quotient in the W0403 text goes through the same guarded division.
  const Result r = run("(-9223372036854775807-1)/7");
  ASSERT_EQ(r.sink.diagnostics().size(), 1u);
  EXPECT_EQ(r.sink.diagnostics()[0].code, DiagCode::integer_division);
  EXPECT_NE(r.sink.diagnostics()[0].message.find("but -1317624576693539402 in"), std::string::npos)
      << r.sink.diagnostics()[0].message;
}

TEST(Expression, NonFiniteAndDivisionByZero) {
  expect_error("1e999", DiagCode::arithmetic_error, 0, "not finite");
  expect_error("2 * 1e999", DiagCode::arithmetic_error, 4);
  expect_error("1e308 * 10", DiagCode::arithmetic_error, 6, "not finite");
  expect_error("1/0", DiagCode::arithmetic_error, 1, "division by zero");
  expect_error("1//0", DiagCode::arithmetic_error, 1, "division by zero");
  expect_error("1%0", DiagCode::arithmetic_error, 1, "division by zero");
  expect_error("1.0/0.0", DiagCode::arithmetic_error, 3, "division by zero");
  expect_error("0**-1", DiagCode::arithmetic_error, 1);
  expect_error("0.0**-1", DiagCode::arithmetic_error, 3);
  expect_error("(-8)**(1.0/3)", DiagCode::arithmetic_error, 4, "fractional power");
  expect_error("10.0**400", DiagCode::arithmetic_error, 4);
}

TEST(Expression, RoundTiesToEvenAndDecimalPlaces) {
  EXPECT_EQ(int_value("round(2.5)"), 2);
  EXPECT_EQ(int_value("round(3.5)"), 4);
  EXPECT_EQ(int_value("round(-2.5)"), -2);
  EXPECT_EQ(int_value("round(0.5)"), 0);
  EXPECT_EQ(int_value("round(1.5)"), 2);
  EXPECT_EQ(int_value("round(2.6)"), 3);
  EXPECT_EQ(int_value("round(7)"), 7);
  // Two arguments: Python 3 rounds the exact binary value, so 2.675 (stored as 2.67499999...)
  // gives 2.67, and the exact tie 0.125 goes to the even 0.12.
  EXPECT_EQ(float_value("round(2.675, 2)"), 2.67);
  EXPECT_EQ(float_value("round(0.125, 2)"), 0.12);
  EXPECT_EQ(float_value("round(1234.5, -2)"), 1200.0);
  EXPECT_EQ(float_value("round(2.5, 0)"), 2.0);
  EXPECT_EQ(float_value("round(1.23456, 10)"), 1.23456);
  EXPECT_EQ(int_value("round(25, -1)"), 20);
  EXPECT_EQ(int_value("round(35, -1)"), 40);
  EXPECT_EQ(int_value("round(-25, -1)"), -20);
  EXPECT_EQ(int_value("round(1234, 2)"), 1234);
  expect_error("round(1e300)", DiagCode::arithmetic_error, 0, "does not fit in 64 bits");
  expect_error("round(1.5, 1.0)", DiagCode::parameter_type_error, 11, "integer number of decimal");
}

TEST(Expression, BuiltinFunctions) {
  EXPECT_EQ(float_value("sqrt(16)"), 4.0);
  EXPECT_EQ(float_value("exp(0)"), 1.0);
  EXPECT_EQ(float_value("log(e)"), 1.0);
  // log(x, base) is log(x)/log(base) as in CPython, including its rounding:
  // Python gives log(1000, 10) == 2.9999999999999996.
  EXPECT_EQ(float_value("log(1000, 10)"), std::log(1000.0) / std::log(10.0));
  EXPECT_EQ(float_value("log(8, 2)"), 3.0);
  EXPECT_EQ(float_value("log10(1000)"), 3.0);
  EXPECT_EQ(float_value("pow(2, 3)"), 8.0);  // math.pow: always a float
  EXPECT_EQ(float_value("sin(0)"), 0.0);
  EXPECT_EQ(float_value("cos(0)"), 1.0);
  EXPECT_EQ(float_value("tan(0)"), 0.0);
  EXPECT_EQ(float_value("asin(1)"), std::asin(1.0));
  EXPECT_EQ(float_value("acos(1)"), 0.0);
  EXPECT_EQ(float_value("atan(1)"), std::atan(1.0));
  EXPECT_EQ(float_value("atan2(1, 1)"), std::atan2(1.0, 1.0));
  EXPECT_EQ(float_value("sinh(0)"), 0.0);
  EXPECT_EQ(float_value("cosh(0)"), 1.0);
  EXPECT_EQ(float_value("tanh(0)"), 0.0);
  EXPECT_EQ(float_value("degrees(pi)"), 180.0);
  EXPECT_EQ(float_value("radians(180)"), 3.141592653589793);
  EXPECT_EQ(int_value("floor(-2.5)"), -3);
  EXPECT_EQ(int_value("ceil(2.1)"), 3);
  EXPECT_EQ(int_value("floor(4)"), 4);
  EXPECT_EQ(int_value("int(-2.7)"), -2);  // toward zero
  EXPECT_EQ(int_value("int(2.7)"), 2);
  EXPECT_EQ(float_value("float(3)"), 3.0);
  EXPECT_EQ(int_value("abs(-3)"), 3);
  EXPECT_EQ(float_value("abs(-2.5)"), 2.5);
  EXPECT_EQ(float_value("fabs(-3)"), 3.0);
  EXPECT_EQ(float_value("fmod(-7, 2)"), -1.0);
  EXPECT_EQ(float_value("hypot(3, 4)"), 5.0);
  EXPECT_EQ(float_value("min(3, 1.5, 2)"), 1.5);
  EXPECT_EQ(int_value("max(2, 7, 5)"), 7);
  EXPECT_EQ(int_value("max(1, 1.0)"), 1);  // Python returns the first of equal arguments
  // int and float compare exactly, as in Python: 2**53 + 1 > 2.0**53 although both round to
  // the same double.
  EXPECT_EQ(float_value("min(9007199254740993, 9007199254740992.0)"), 9007199254740992.0);
  EXPECT_EQ(float_value("pi"), 3.141592653589793);
  EXPECT_EQ(float_value("e"), 2.718281828459045);
}

// Same as expect_error, and the message must be exactly `message`.
void expect_error_exact(std::string_view text, DiagCode code, std::uint32_t offset,
                        std::string_view message) {
  SCOPED_TRACE(std::string(text));
  const Result r = run(text);
  EXPECT_FALSE(r.value.has_value());
  ASSERT_EQ(r.sink.diagnostics().size(), 1u);
  EXPECT_EQ(diag_code_id(r.sink.diagnostics()[0].code), diag_code_id(code));
  EXPECT_EQ(r.sink.diagnostics()[0].loc, (SourceLoc{0, 7, kColumn + offset}));
  EXPECT_EQ(r.sink.diagnostics()[0].message, message);
}

TEST(Expression, SpotWeldRadius) {
  // derived-components-and-potentials.md §3 / input-syntax.md §6.4: r_n = sqrt(I_xx/A).
  const double r_n = float_value("sqrt(I_xx/A)");
  // The evaluator performs the same two correctly rounded IEEE operations (a division, then a
  // square root) as std::sqrt(30.68 / 19.63), so the results should be identical; 1e-12
  // relative only leaves room for a different libm sqrt, which IEEE 754 forbids anyway.
  EXPECT_NEAR(r_n, std::sqrt(30.68 / 19.63), 1e-12 * std::sqrt(30.68 / 19.63));
  // The spec prints 1.25017, rounded to 6 significant digits: at most half a unit (5e-6) away.
  EXPECT_NEAR(r_n, 1.25017, 5e-6);
}

TEST(Expression, Strings) {
  Result r = run("'abc' + \"def\"");
  ASSERT_TRUE(r.value);
  EXPECT_EQ(r.value->kind, ParamValue::Kind::String);
  EXPECT_EQ(r.value->s, "abcdef");
  r = run("'a' 'b'");  // adjacent literals concatenate, as in Python
  ASSERT_TRUE(r.value);
  EXPECT_EQ(r.value->s, "ab");
  r = run("name + '_1'");
  ASSERT_TRUE(r.value);
  EXPECT_EQ(r.value->s, "weld_1");
  r = run("r'a\\n'");
  ASSERT_TRUE(r.value);
  EXPECT_EQ(r.value->s, "a\\n");
  r = run("'it\\'s\\t'");
  ASSERT_TRUE(r.value);
  EXPECT_EQ(r.value->s, "it's\t");
  r = run("'''x'y'''");
  ASSERT_TRUE(r.value);
  EXPECT_EQ(r.value->s, "x'y");
  r = run("'#' + 'a'  # a comment");  // '#' in a string is not a comment
  ASSERT_TRUE(r.value);
  EXPECT_EQ(r.value->s, "#a");
  EXPECT_TRUE(r.sink.diagnostics().empty());

  expect_error_exact("'abc' + 1", DiagCode::parameter_type_error, 6,
                     "cannot add a string and a number");
  expect_error("1 + name", DiagCode::parameter_type_error, 2, "cannot add a string and a number");
  expect_error("'a' * 3", DiagCode::parameter_type_error, 4);
  expect_error("'a' - 'b'", DiagCode::parameter_type_error, 4, "strings");
  expect_error("'a' ** 2", DiagCode::parameter_type_error, 4);
  expect_error("-name", DiagCode::parameter_type_error, 0);
  expect_error("sqrt(name)", DiagCode::parameter_type_error, 5, "expects a number");
  expect_error("max(1, 'a')", DiagCode::parameter_type_error, 7, "expects a number");
  expect_error("'abc", DiagCode::expression_syntax, 0, "unterminated string");
  expect_error("1 + \"abc", DiagCode::expression_syntax, 4, "unterminated string");
  expect_error("f'{n}'", DiagCode::unsupported_expression, 0, "f-strings");
  expect_error("b'x'", DiagCode::unsupported_expression, 0, "byte strings");
}

// A string longer than kMaxParameterStringLength is E0406, a literal at its quote and a sum at its
// '+' before the sum is built; a string of exactly the limit is a value (docs/decisions.md).
TEST(Expression, StringLengthLimit) {
  const std::string full(kMaxParameterStringLength, 'x');
  Result r = run("'" + full + "'");
  ASSERT_TRUE(r.value);
  EXPECT_EQ(r.value->s.size(), kMaxParameterStringLength);
  r = run("'" + full.substr(1) + "' + 'y'");
  ASSERT_TRUE(r.value);
  EXPECT_EQ(r.value->s.size(), kMaxParameterStringLength);
  expect_error_exact("'" + full + "x'", DiagCode::arithmetic_error, 0,
                     "this string literal is 65537 characters long; a parameter string may have "
                     "at most 65536 characters");
  const std::string half(kMaxParameterStringLength / 2, 'x');
  expect_error_exact("'a' + '" + half + "' + '" + half + "'", DiagCode::arithmetic_error,
                     static_cast<std::uint32_t>(half.size()) + 9,
                     "''a' + '" + std::string(30, 'x') +
                         "...' would be 65537 characters long; a parameter string may have at "
                         "most 65536 characters");
}

TEST(Expression, DisplayIsPythonRepr) {
  EXPECT_EQ(ParamValue::make_int(3).to_display(), "3");
  EXPECT_EQ(ParamValue::make_int(-7).to_display(), "-7");
  EXPECT_EQ(ParamValue::make_float(1.25).to_display(), "1.25");
  EXPECT_EQ(ParamValue::make_float(3.0).to_display(), "3.0");
  EXPECT_EQ(ParamValue::make_float(-0.5).to_display(), "-0.5");
  EXPECT_EQ(ParamValue::make_float(1e-5).to_display(), "1e-05");
  EXPECT_EQ(ParamValue::make_float(0.0001).to_display(), "0.0001");
  EXPECT_EQ(ParamValue::make_float(1e16).to_display(), "1e+16");
  EXPECT_EQ(ParamValue::make_float(1234567890123456.0).to_display(), "1234567890123456.0");
  EXPECT_EQ(ParamValue::make_float(123456789012345678.0).to_display(), "1.2345678901234568e+17");
  EXPECT_EQ(ParamValue::make_float(0.1 + 0.2).to_display(), "0.30000000000000004");
  EXPECT_EQ(ParamValue::make_float(-0.0).to_display(), "-0.0");
  EXPECT_EQ(ParamValue::make_float(1.5e300).to_display(), "1.5e+300");
  EXPECT_EQ(ParamValue::make_float(5e-324).to_display(), "5e-324");
  EXPECT_EQ(ParamValue::make_string("abc").to_display(), "'abc'");
  EXPECT_EQ(ParamValue::make_string("it's").to_display(), "\"it's\"");
  EXPECT_EQ(ParamValue::make_string("a'b\"c").to_display(), "'a\\'b\"c'");
  EXPECT_TRUE(ParamValue::make_int(1).is_number());
  EXPECT_FALSE(ParamValue::make_string("1").is_number());
  EXPECT_EQ(ParamValue::make_int(4).as_double(), 4.0);
}

// ---- E0401 ----------------------------------------------------------------------------------

TEST(Expression, SyntaxErrorsPointAtTheFirstUnparsableCharacter) {
  expect_error_exact("2*", DiagCode::expression_syntax, 2, "expected an expression after '*'");
  expect_error_exact("", DiagCode::expression_syntax, 0, "expected an expression");
  expect_error("2 3", DiagCode::expression_syntax, 2, "got '3'");
  expect_error_exact("1+2)", DiagCode::expression_syntax, 3, "unmatched ')'");
  expect_error("1 $ 2", DiagCode::expression_syntax, 2, "unexpected character '$'");
  expect_error("1D5", DiagCode::expression_syntax, 1, "write 1E5");
  expect_error("2.5d-3", DiagCode::expression_syntax, 3, "write 2.5E-3");
  expect_error("010", DiagCode::expression_syntax, 0, "leading zeros");
  expect_error("1e", DiagCode::expression_syntax, 1, "exponent");
  expect_error("1e+", DiagCode::expression_syntax, 1, "exponent");
  expect_error("1abc", DiagCode::expression_syntax, 1, "invalid number");
  expect_error("1__0", DiagCode::expression_syntax, 1, "'_'");
  expect_error("0x", DiagCode::expression_syntax, 0, "no digits");
  expect_error("2 ** * 3", DiagCode::expression_syntax, 5, "after '**'");
  expect_error("sqrt(1 2)", DiagCode::expression_syntax, 7, "',' or ')'");
  expect_error("\xc3\xa9", DiagCode::expression_syntax, 0, "byte 0xC3");
  expect_error("else", DiagCode::expression_syntax, 0, "reserved word");
  // The first fault in text order wins, even when a later one is lexical.
  expect_error("1 + * 2 ; 3", DiagCode::expression_syntax, 4);
  // A syntax error is reported even after a literal that would overflow (Python compiles first).
  expect_error("1e999 +", DiagCode::expression_syntax, 7);
}

// ---- E0407 ----------------------------------------------------------------------------------

TEST(Expression, UnsupportedConstructsAreNamed) {
  expect_error_exact("n == 1", DiagCode::unsupported_expression, 2,
                     "comparisons are not supported in parameter expressions");
  expect_error("1 < 2", DiagCode::unsupported_expression, 2, "comparisons");
  expect_error("1 in 2", DiagCode::unsupported_expression, 2, "comparisons");
  expect_error("1 and 2", DiagCode::unsupported_expression, 2, "boolean");
  expect_error("not 1", DiagCode::unsupported_expression, 0, "boolean");
  expect_error("1 if n else 2", DiagCode::unsupported_expression, 2, "conditional");
  expect_error("[1, 2]", DiagCode::unsupported_expression, 0, "lists");
  expect_error("n[0]", DiagCode::unsupported_expression, 1, "indexing");
  expect_error("math.sqrt(2)", DiagCode::unsupported_expression, 4, "write sqrt");
  expect_error("n.real", DiagCode::unsupported_expression, 1, "attribute access");
  expect_error("import math", DiagCode::unsupported_expression, 0, "import");
  expect_error("lambda x: x", DiagCode::unsupported_expression, 0, "lambda");
  expect_error("(1, 2)", DiagCode::unsupported_expression, 2, "tuples");
  expect_error("1, 2", DiagCode::unsupported_expression, 1, "tuples");
  expect_error("()", DiagCode::unsupported_expression, 0, "tuples");
  expect_error("1; 2", DiagCode::unsupported_expression, 1, "';'");
  expect_error("1 + \\", DiagCode::unsupported_expression, 4, "continuation");
  expect_error("(1 + 2", DiagCode::unsupported_expression, 0, "never closed");
  expect_error("sqrt((1 + 2)", DiagCode::unsupported_expression, 4, "never closed");
  expect_error("(1 +", DiagCode::unsupported_expression, 0, "never closed");
  expect_error("1 & 2", DiagCode::unsupported_expression, 2, "bitwise");
  expect_error("~1", DiagCode::unsupported_expression, 0, "bitwise");
  expect_error("True", DiagCode::unsupported_expression, 0, "booleans");
  expect_error("None", DiagCode::unsupported_expression, 0, "None");
  expect_error("sqrt(x=1)", DiagCode::unsupported_expression, 5, "keyword arguments");
  expect_error("max(*n)", DiagCode::unsupported_expression, 4, "unpacking");
  expect_error("1j", DiagCode::unsupported_expression, 1, "complex");
  expect_error("{1: 2}", DiagCode::unsupported_expression, 0, "dictionaries");
  expect_error("n = 2", DiagCode::unsupported_expression, 2, "'='");
  expect_error("n += 2", DiagCode::unsupported_expression, 2, "augmented");
  expect_error("sqrt(2)(3)", DiagCode::unsupported_expression, 7, "called");
  expect_error("sqrt", DiagCode::unsupported_expression, 0, "is a function");
  expect_error("x @ y", DiagCode::unsupported_expression, 2, "'@'");
  expect_error("[x for x in n]", DiagCode::unsupported_expression, 0, "lists");
  expect_error("max(x for x in n)", DiagCode::unsupported_expression, 6, "comprehensions");
}

// ---- E0406, E0408, E0409 ---------------------------------------------------------------------

TEST(Expression, FunctionErrors) {
  {
    const Result r = run("2 * sqr(2)");
    ASSERT_EQ(r.sink.diagnostics().size(), 1u);
    const Diagnostic& d = r.sink.diagnostics()[0];
    EXPECT_EQ(d.code, DiagCode::unknown_function);
    EXPECT_EQ(d.loc, (SourceLoc{0, 7, kColumn + 4}));
    EXPECT_EQ(d.message, "unknown function 'sqr'");
    ASSERT_EQ(d.notes.size(), 1u);
    EXPECT_EQ(d.notes[0].message, "did you mean 'sqrt'?");
  }
  expect_error("frobnicate(2)", DiagCode::unknown_function, 0, "unknown function 'frobnicate'");
  expect_error_exact("atan2(1)", DiagCode::wrong_argument_count, 0,
                     "atan2 takes 2 arguments, 1 given");
  expect_error_exact("sqrt(1, 2)", DiagCode::wrong_argument_count, 0,
                     "sqrt takes 1 argument, 2 given");
  expect_error_exact("1 + min(1)", DiagCode::wrong_argument_count, 4,
                     "min takes at least 2 arguments, 1 given");
  expect_error_exact("log(1, 2, 3)", DiagCode::wrong_argument_count, 0,
                     "log takes 1 or 2 arguments, 3 given");
  expect_error_exact("round()", DiagCode::wrong_argument_count, 0,
                     "round takes 1 or 2 arguments, 0 given");
  expect_error_exact("sqrt(-0.5)", DiagCode::arithmetic_error, 0,
                     "math domain error in sqrt(-0.5)");
  expect_error_exact("2 + sqrt(-1)", DiagCode::arithmetic_error, 4,
                     "math domain error in sqrt(-1)");
  expect_error("log(0)", DiagCode::arithmetic_error, 0, "math domain error in log(0)");
  expect_error("log(-1, 10)", DiagCode::arithmetic_error, 0, "domain");
  expect_error("log(10, 0)", DiagCode::arithmetic_error, 0, "domain");
  expect_error("log(2, 1)", DiagCode::arithmetic_error, 0, "division by zero in log(2, 1)");
  expect_error("log10(0)", DiagCode::arithmetic_error, 0, "domain");
  expect_error("asin(2)", DiagCode::arithmetic_error, 0, "math domain error in asin(2)");
  expect_error("acos(-1.5)", DiagCode::arithmetic_error, 0, "domain");
  expect_error("fmod(1, 0)", DiagCode::arithmetic_error, 0, "domain");
  expect_error("pow(0, -1)", DiagCode::arithmetic_error, 0, "domain");
  expect_error("pow(-8, 1.0/3)", DiagCode::arithmetic_error, 0, "domain");
  expect_error_exact("exp(1000)", DiagCode::arithmetic_error, 0, "math range error in exp(1000)");
  expect_error("cosh(1000)", DiagCode::arithmetic_error, 0, "range");
  expect_error("int(1e300)", DiagCode::arithmetic_error, 0, "does not fit in 64 bits");
  expect_error("floor(-1e300)", DiagCode::arithmetic_error, 0, "does not fit in 64 bits");
  expect_error("pi(2)", DiagCode::parameter_type_error, 0, "constant");
}

// ---- names ----------------------------------------------------------------------------------

TEST(Expression, NamesGoThroughTheLookup) {
  expect_error_exact("2 * radius", DiagCode::undefined_parameter, 4,
                     "undefined parameter 'radius'");

  // The lookup gets the location of the name.
  DiagnosticSink sink;
  std::vector<SourceLoc> seen;
  const ParamValue five = ParamValue::make_int(5);
  const ParamLookup lookup = [&](std::string_view name, SourceLoc loc) -> const ParamValue* {
    seen.push_back(loc);
    return name == "a" ? &five : nullptr;  // "failed" is silent: its error is already reported
  };
  auto value = evaluate_expression("a + 2*a", kLoc, lookup, sink);
  ASSERT_TRUE(value);
  EXPECT_EQ(value->i, 15);
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_EQ(seen[0], (SourceLoc{0, 7, kColumn}));
  EXPECT_EQ(seen[1], (SourceLoc{0, 7, kColumn + 6}));
  // No cascade: a name the lookup rejects silently fails the expression silently.
  value = evaluate_expression("1 + failed", kLoc, lookup, sink);
  EXPECT_FALSE(value);
  EXPECT_TRUE(sink.diagnostics().empty());

  // Without a lookup, the evaluator reports the name itself.
  value = evaluate_expression("q", kLoc, ParamLookup{}, sink);
  EXPECT_FALSE(value);
  ASSERT_EQ(sink.diagnostics().size(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].code, DiagCode::undefined_parameter);
}

TEST(Expression, ParameterHidesBuiltin) {
  DiagnosticSink sink;
  const ParamValue three = ParamValue::make_int(3);
  const ParamLookup lookup = [&](std::string_view name, SourceLoc) -> const ParamValue* {
    return name == "e" || name == "sqrt" ? &three : nullptr;
  };
  const ParamDefinedCheck defined = [](std::string_view name) {
    return name == "e" || name == "sqrt";
  };
  auto value = evaluate_expression("e*2", kLoc, lookup, sink, defined);
  ASSERT_TRUE(value);
  EXPECT_EQ(value->kind, ParamValue::Kind::Int);
  EXPECT_EQ(value->i, 6);
  // Not hidden: the constant.
  value = evaluate_expression("e*2", kLoc, lookup, sink);
  ASSERT_TRUE(value);
  EXPECT_EQ(value->f, 2 * 2.718281828459045);
  EXPECT_TRUE(sink.diagnostics().empty());

  value = evaluate_expression("sqrt(4)", kLoc, lookup, sink, defined);
  EXPECT_FALSE(value);
  ASSERT_EQ(sink.diagnostics().size(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].code, DiagCode::parameter_type_error);
  EXPECT_EQ(sink.diagnostics()[0].message, "'sqrt' is a parameter, not a function");
  EXPECT_TRUE(is_builtin_function("hypot"));
  EXPECT_TRUE(is_builtin_constant("pi"));
  EXPECT_FALSE(is_builtin_constant("tau"));
  EXPECT_TRUE(is_python_keyword("lambda"));
  EXPECT_FALSE(is_python_keyword("print"));
}

TEST(Expression, CommentHelper) {
  EXPECT_EQ(find_comment("a = 1 # c"), 6u);
  EXPECT_EQ(find_comment("a = '#' # c"), 8u);
  EXPECT_EQ(find_comment("a = r'\\'#' # c"), 11u);
  EXPECT_EQ(find_comment("a = '''#'''"), std::string_view::npos);
  EXPECT_EQ(find_comment("a = '#"), std::string_view::npos);  // unterminated: no comment
}

// ---- robustness -----------------------------------------------------------------------------

TEST(Expression, DeepNestingIsRejectedWithoutCrashing) {
  // Recursion is capped at 200 levels (Python's own limit for parentheses).
  const std::string deep = std::string(1000, '(') + "1" + std::string(1000, ')');
  expect_error(deep, DiagCode::expression_syntax, 200, "nested too deeply");
  const std::string fine = std::string(100, '(') + "1" + std::string(100, ')');
  EXPECT_EQ(int_value(fine), 1);
  expect_error(std::string(100000, '-') + "1", DiagCode::expression_syntax, 200,
               "nested too deeply");
  std::string powers;
  for (int k = 0; k < 300; ++k) powers += "1**";
  powers += "1";
  expect_error(powers, DiagCode::expression_syntax, 600, "nested too deeply");
  // A long flat chain is not nesting: it is evaluated iteratively.
  std::string chain = "1";
  for (int k = 0; k < 100000; ++k) chain += "+1";
  EXPECT_EQ(int_value(chain), 100001);
  expect_error(std::string(5000, '9'), DiagCode::arithmetic_error, 0, "does not fit");
  expect_error(std::string(5000, '9') + ".0", DiagCode::arithmetic_error, 0, "not finite");
  expect_error("1e99999999999999999999999", DiagCode::arithmetic_error, 0, "not finite");
}

TEST(Expression, RandomInputNeverCrashesAndAlwaysExplainsFailure) {
  // Fixed seed: reproducible. Fragments are biased towards the grammar so that evaluation, not
  // only lexing, is exercised.
  static const std::vector<std::string> fragments = {
      "0",      "1",    "7",    "2.5",    "1e308", ".5",   "0x7f", "9223372036854775807",
      "+",      "-",    "*",    "/",      "//",    "%",    "**",   "(",
      ")",      ",",    "'a'",  "\"b\"",  "'",     "#",    "\\",   ";",
      "=",      "==",   "<",    "[",      "]",     "{",    ".",    "sqrt(",
      "round(", "log(", "min(", "atan2(", "n",     "name", "big",  "e",
      "pi",     "I_xx", "A",    "zz",     "if",    "and",  "not",  "lambda",
      " ",      "\t",   "D",    "j",      "_",     "\x80", "\x01", "f'",
      "r'",     "@",    "~"};
  std::mt19937 rng(20240517u);
  std::uniform_int_distribution<std::size_t> pick(0, fragments.size() - 1);
  std::uniform_int_distribution<int> length(0, 24);
  for (int iteration = 0; iteration < 20000; ++iteration) {
    std::string text;
    const int n = length(rng);
    for (int k = 0; k < n; ++k) text += fragments[pick(rng)];
    const Result r = run(text);
    SCOPED_TRACE(text);
    // Every failure is explained by an error, and every diagnostic points into the text.
    EXPECT_TRUE(r.value.has_value() || r.sink.has_errors());
    if (r.value.has_value()) {
      EXPECT_FALSE(r.sink.has_errors());
    }
    for (const Diagnostic& d : r.sink.diagnostics()) {
      EXPECT_EQ(d.loc.line, 7u);
      EXPECT_GE(d.loc.column, kColumn);
      EXPECT_LE(d.loc.column, kColumn + text.size());
    }
    if (::testing::Test::HasFailure()) break;
  }
}

}  // namespace
}  // namespace clinch
