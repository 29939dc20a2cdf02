// Unit tests of the *PARAMETER pre-pass (input-syntax.md §6.2, §6.4): file-order evaluation,
// the spot weld example, every E04xx/W04xx the pre-pass reports with its location and notes,
// and the no-cascade rule.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.hpp"
#include "parser/parameters.hpp"

namespace clinch {
namespace {

// Line k of the list is line k+1 of file 0; each line starts at column 1.
ParameterTable evaluate_lines(std::initializer_list<std::string_view> lines, DiagnosticSink& sink) {
  ParameterTable table;
  std::uint32_t line = 1;
  for (std::string_view text : lines) table.add_line({std::string(text), SourceLoc{0, line++, 1}});
  table.evaluate(sink);
  return table;
}

SourceLoc at(std::uint32_t line, std::uint32_t column) { return SourceLoc{0, line, column}; }

// Exactly one diagnostic; returns it for further checks.
const Diagnostic& only(const DiagnosticSink& sink) {
  EXPECT_EQ(sink.diagnostics().size(), 1u);
  static const Diagnostic none{};
  return sink.diagnostics().empty() ? none : sink.diagnostics()[0];
}

void expect_single(std::initializer_list<std::string_view> lines, DiagCode code, SourceLoc loc,
                   std::string_view message_part) {
  SCOPED_TRACE(std::string(*lines.begin()));
  DiagnosticSink sink;
  evaluate_lines(lines, sink);
  ASSERT_EQ(sink.diagnostics().size(), 1u)
      << (sink.diagnostics().empty() ? "" : sink.diagnostics()[0].message);
  const Diagnostic& d = sink.diagnostics()[0];
  EXPECT_EQ(diag_code_id(d.code), diag_code_id(code)) << d.message;
  EXPECT_EQ(d.loc, loc) << d.message;
  EXPECT_NE(d.message.find(message_part), std::string::npos) << d.message;
}

TEST(Parameters, SpotWeldExample) {
  // input-syntax.md §6.4, derived-components-and-potentials.md §3.
  DiagnosticSink sink;
  ParameterTable table = evaluate_lines(
      {"I_xx = 30.68", "A    = 19.63", "r_n  = sqrt(I_xx/A)", "r_s  = 2.0*r_n", "or_n = 1/r_n"},
      sink);
  EXPECT_TRUE(sink.diagnostics().empty());
  const double exact_r_n = std::sqrt(30.68 / 19.63);
  const ParameterTable::Entry* r_n = table.use("r_n");
  ASSERT_NE(r_n, nullptr);
  ASSERT_TRUE(r_n->ok);
  EXPECT_EQ(r_n->value.kind, ParamValue::Kind::Float);
  // Same correctly rounded IEEE operations as the reference expression, so identical in
  // practice; 1e-12 relative is a safety margin, far below any physical significance.
  EXPECT_NEAR(r_n->value.f, exact_r_n, 1e-12 * exact_r_n);
  // The spec prints 6 significant digits (1.25017): half a unit of the last digit is 5e-6.
  EXPECT_NEAR(r_n->value.f, 1.25017, 5e-6);

  const ParameterTable::Entry* r_s = table.use("r_s");
  ASSERT_NE(r_s, nullptr);
  EXPECT_EQ(r_s->value.f, 2.0 * r_n->value.f);  // multiplying by 2 is exact

  const ParameterTable::Entry* or_n = table.use("or_n");
  ASSERT_NE(or_n, nullptr);
  EXPECT_EQ(or_n->value.kind, ParamValue::Kind::Float);            // int / float: no W0403
  EXPECT_NEAR(or_n->value.f, 1.0 / exact_r_n, 1e-12 / exact_r_n);  // as for r_n
  EXPECT_NEAR(or_n->value.f, 0.799894, 5e-7);                      // 0.799894: 6 significant digits
  EXPECT_EQ(or_n->loc, at(5, 1));
  EXPECT_EQ(or_n->name, "or_n");

  // I_xx, A and r_n are used by other definitions, r_s and or_n by use(): nothing unused.
  table.report_unused(sink);
  EXPECT_TRUE(sink.diagnostics().empty());
  EXPECT_FALSE(table.empty());
}

TEST(Parameters, BlankAndCommentLinesAreSkipped) {
  DiagnosticSink sink;
  ParameterTable table = evaluate_lines(
      {"# geometry", "", "   ", "a = 1  # one", "b = 'x#y'  # a '#' in a string is not a comment"},
      sink);
  EXPECT_TRUE(sink.diagnostics().empty());
  ASSERT_NE(table.use("a"), nullptr);
  EXPECT_EQ(table.use("a")->value.i, 1);
  ASSERT_NE(table.use("b"), nullptr);
  EXPECT_EQ(table.use("b")->value.s, "x#y");

  DiagnosticSink quiet;
  EXPECT_TRUE(evaluate_lines({"# only a comment", "  "}, quiet).empty());
  EXPECT_TRUE(ParameterTable{}.empty());
  EXPECT_TRUE(quiet.diagnostics().empty());
}

TEST(Parameters, UseBeforeDefinitionPointsAtTheLaterDefinition) {
  DiagnosticSink sink;
  ParameterTable table = evaluate_lines({"x = A * 2", "A = 3"}, sink);
  const Diagnostic& d = only(sink);
  EXPECT_EQ(d.code, DiagCode::parameter_used_before_definition);
  EXPECT_EQ(d.loc, at(1, 5));
  EXPECT_EQ(d.message, "parameter 'A' is used before it is defined");
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0].message, "defined later here");
  EXPECT_EQ(d.notes[0].loc, at(2, 1));
  // x failed: its uses stay silent. A counts as used (it was referenced), so no W0402 either.
  const ParameterTable::Entry* x = table.use("x");
  ASSERT_NE(x, nullptr);
  EXPECT_FALSE(x->ok);
  table.report_unused(sink);
  EXPECT_EQ(sink.diagnostics().size(), 1u);
}

TEST(Parameters, SelfReferenceNeedsAnEarlierDefinition) {
  {
    DiagnosticSink sink;
    evaluate_lines({"a = a + 1"}, sink);
    const Diagnostic& d = only(sink);
    EXPECT_EQ(d.code, DiagCode::parameter_used_before_definition);
    EXPECT_EQ(d.loc, at(1, 5));
    EXPECT_TRUE(d.notes.empty());
  }
  {
    DiagnosticSink sink;
    ParameterTable table = evaluate_lines({"a = 1", "a = a + 1"}, sink);
    const Diagnostic& d = only(sink);
    EXPECT_EQ(d.code, DiagCode::parameter_redefined);
    EXPECT_EQ(d.severity, Severity::Warning);
    ASSERT_NE(table.use("a"), nullptr);
    EXPECT_EQ(table.use("a")->value.i, 2);  // the final value (§6.4 item 4)
    EXPECT_EQ(table.use("a")->loc, at(2, 1));
  }
}

TEST(Parameters, UndefinedNameSuggestsACloseOne) {
  DiagnosticSink sink;
  ParameterTable table =
      evaluate_lines({"or_n = 0.8", "x = or_N * 2", "radius = 1", "y = radus"}, sink);
  ASSERT_EQ(sink.diagnostics().size(), 2u);
  const Diagnostic& d = sink.diagnostics()[0];
  EXPECT_EQ(d.code, DiagCode::undefined_parameter);
  EXPECT_EQ(d.loc, at(2, 5));
  EXPECT_EQ(d.message, "undefined parameter 'or_N'");
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0].message, "did you mean 'or_n'? (parameter names are case-sensitive)");
  const Diagnostic& typo = sink.diagnostics()[1];
  EXPECT_EQ(typo.loc, at(4, 5));
  ASSERT_EQ(typo.notes.size(), 1u);
  EXPECT_EQ(typo.notes[0].message, "did you mean 'radius'?");

  EXPECT_EQ(table.suggest("OR_N"), std::optional<std::string>("or_n"));
  EXPECT_EQ(table.suggest("completely_different"), std::nullopt);
  EXPECT_EQ(table.use("nothing"), nullptr);

  // What a field substitution reports for an undefined <name> (§6.4 item 4).
  DiagnosticSink field;
  table.report_undefined(field, "Radius", at(40, 2));
  const Diagnostic& f = only(field);
  EXPECT_EQ(f.code, DiagCode::undefined_parameter);
  EXPECT_EQ(f.loc, at(40, 2));
  ASSERT_EQ(f.notes.size(), 1u);
  EXPECT_EQ(f.notes[0].message, "did you mean 'radius'? (parameter names are case-sensitive)");
}

TEST(Parameters, InvalidNames) {
  DiagnosticSink sink;
  evaluate_lines({"lambda = 3"}, sink);
  const Diagnostic& d = only(sink);
  EXPECT_EQ(d.code, DiagCode::invalid_parameter_name);
  EXPECT_EQ(d.loc, at(1, 1));
  EXPECT_EQ(d.message, "'lambda' is a reserved word and cannot be a parameter name");
  expect_single({"  True = 1"}, DiagCode::invalid_parameter_name, at(1, 3), "reserved word");
  expect_single({"2a = 1"}, DiagCode::invalid_parameter_name, at(1, 1), "'2a' is not a valid");
  expect_single({"my-param = 3"}, DiagCode::invalid_parameter_name, at(1, 1), "'my-param'");
}

TEST(Parameters, OnlySimpleAssignments) {
  expect_single({"a += 1"}, DiagCode::unsupported_expression, at(1, 3), "augmented assignment");
  expect_single({"a **= 2"}, DiagCode::unsupported_expression, at(1, 3), "'**='");
  expect_single({"a == 1"}, DiagCode::unsupported_expression, at(1, 3), "comparison");
  expect_single({"a = 1; b = 2"}, DiagCode::unsupported_expression, at(1, 6), "';'");
  expect_single({"a = (1 +"}, DiagCode::unsupported_expression, at(1, 5), "never closed");
  expect_single({"a = 1 + \\"}, DiagCode::unsupported_expression, at(1, 9), "continuation");
  expect_single({"a, b = 1, 2"}, DiagCode::unsupported_expression, at(1, 2), "tuple assignment");
  expect_single({"a = b = 1"}, DiagCode::unsupported_expression, at(1, 7), "'='");
  expect_single({"import math"}, DiagCode::unsupported_expression, at(1, 1), "'import'");
  expect_single({"print(a)"}, DiagCode::unsupported_expression, at(1, 1), "name = expression");
  expect_single({"a"}, DiagCode::unsupported_expression, at(1, 1), "name = expression");
  expect_single({"a.b = 1"}, DiagCode::unsupported_expression, at(1, 2), "plain name");
  expect_single({"= 3"}, DiagCode::expression_syntax, at(1, 1), "expected a parameter name");
  expect_single({"a ="}, DiagCode::expression_syntax, at(1, 4), "expected an expression after '='");
  expect_single({"a = 2 *"}, DiagCode::expression_syntax, at(1, 8), "after '*'");
  // A rejected statement with a recognisable name is a failed definition: no cascade.
  expect_single({"a += 1", "b = a"}, DiagCode::unsupported_expression, at(1, 3), "augmented");
  expect_single({"a =", "b = a"}, DiagCode::expression_syntax, at(1, 4), "expected");
}

TEST(Parameters, RedefinitionWarns) {
  DiagnosticSink sink;
  ParameterTable table = evaluate_lines({"beta = 1", "gamma = beta", "beta = 2"}, sink);
  const Diagnostic& d = only(sink);
  EXPECT_EQ(d.code, DiagCode::parameter_redefined);
  EXPECT_EQ(d.loc, at(3, 1));
  EXPECT_EQ(d.message, "parameter 'beta' redefined");
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0].message, "previous definition is here");
  EXPECT_EQ(d.notes[0].loc, at(1, 1));
  EXPECT_EQ(table.use("gamma")->value.i, 1);  // file order, like a Python script
  EXPECT_EQ(table.use("beta")->value.i, 2);
}

TEST(Parameters, ParameterHidesBuiltinFromThenOn) {
  DiagnosticSink sink;
  ParameterTable table = evaluate_lines({"x = e", "e = 3", "y = e * 2"}, sink);
  const Diagnostic& d = only(sink);
  EXPECT_EQ(d.code, DiagCode::parameter_shadows_builtin);
  EXPECT_EQ(d.severity, Severity::Warning);
  EXPECT_EQ(d.loc, at(2, 1));
  EXPECT_EQ(d.message, "parameter 'e' hides the constant e");
  EXPECT_EQ(table.use("x")->value.f, 2.718281828459045);  // still the constant on line 1
  EXPECT_EQ(table.use("y")->value.kind, ParamValue::Kind::Int);
  EXPECT_EQ(table.use("y")->value.i, 6);

  DiagnosticSink fn;
  evaluate_lines({"sqrt = 2", "z = sqrt(4)"}, fn);
  ASSERT_EQ(fn.diagnostics().size(), 2u);
  EXPECT_EQ(fn.diagnostics()[0].message, "parameter 'sqrt' hides the built-in function sqrt");
  EXPECT_EQ(fn.diagnostics()[1].code, DiagCode::parameter_type_error);
  EXPECT_EQ(fn.diagnostics()[1].loc, at(2, 5));
}

TEST(Parameters, FailedDefinitionsDoNotCascade) {
  DiagnosticSink sink;
  ParameterTable table = evaluate_lines({"a = sqrt(-1)", "b = a * 2", "c = b + 1"}, sink);
  const Diagnostic& d = only(sink);
  EXPECT_EQ(d.code, DiagCode::arithmetic_error);
  EXPECT_EQ(d.loc, at(1, 5));
  EXPECT_EQ(d.message, "math domain error in sqrt(-1)");
  const ParameterTable::Entry* c = table.use("c");
  ASSERT_NE(c, nullptr);
  EXPECT_FALSE(c->ok);
  table.report_unused(sink);  // failed parameters are not reported again
  EXPECT_EQ(sink.diagnostics().size(), 1u);
}

TEST(Parameters, UnusedParameters) {
  DiagnosticSink sink;
  ParameterTable table = evaluate_lines({"A_old = 1", "A = 2", "B = A"}, sink);
  EXPECT_TRUE(sink.diagnostics().empty());
  ASSERT_NE(table.use("B"), nullptr);
  table.report_unused(sink);
  const Diagnostic& d = only(sink);
  EXPECT_EQ(d.code, DiagCode::parameter_unused);
  EXPECT_EQ(d.loc, at(1, 1));
  EXPECT_EQ(d.message, "parameter 'A_old' is defined but never used");
}

TEST(Parameters, ExpressionDiagnosticsAreLocatedInTheLine) {
  DiagnosticSink sink;
  ParameterTable table = evaluate_lines({"half = 7/2"}, sink);
  const Diagnostic& d = only(sink);
  EXPECT_EQ(d.code, DiagCode::integer_division);
  EXPECT_EQ(d.loc, at(1, 9));
  EXPECT_EQ(d.message, "'7/2' is 3.5 here but 3 in Abaqus versions that use Python 2; write 7.0/2");
  EXPECT_EQ(table.use("half")->value.f, 3.5);

  expect_single({"s = 'abc' + 1"}, DiagCode::parameter_type_error, at(1, 11),
                "cannot add a string and a number");
  expect_single({"   k = atan2(1)"}, DiagCode::wrong_argument_count, at(1, 8),
                "atan2 takes 2 arguments, 1 given");
  expect_single({"k = sqr(2)"}, DiagCode::unknown_function, at(1, 5), "unknown function 'sqr'");

  DiagnosticSink strings;
  ParameterTable named = evaluate_lines({"name = 'weld' + '_1'"}, strings);
  EXPECT_TRUE(strings.diagnostics().empty());
  EXPECT_EQ(named.use("name")->value.s, "weld_1");
}

TEST(Parameters, EvaluateIsIdempotentAndScales) {
  ParameterTable table;
  table.add_line({"p0 = 0", SourceLoc{0, 1, 1}});
  for (std::uint32_t k = 1; k <= 5000; ++k) {
    table.add_line({fmt::format("p{} = p{} + 1", k, k - 1), SourceLoc{0, k + 1, 1}});
  }
  DiagnosticSink sink;
  table.evaluate(sink);
  table.evaluate(sink);  // a second call does nothing
  EXPECT_TRUE(sink.diagnostics().empty());
  ASSERT_NE(table.use("p5000"), nullptr);
  EXPECT_EQ(table.use("p5000")->value.i, 5000);
}

TEST(Parameters, RandomLinesNeverCrash) {
  static const std::vector<std::string> fragments = {
      "a", "b",     "A", "x1", " ",      "=",      "==", "+=", "1",   "2.5",
      "(", ")",     ",", ";",  "#",      "'s'",    "'",  "\\", "*",   "/",
      "-", "sqrt(", "e", "pi", "lambda", "import", ".",  "[",  "\x90"};
  std::mt19937 rng(7u);  // fixed seed: reproducible
  std::uniform_int_distribution<std::size_t> pick(0, fragments.size() - 1);
  std::uniform_int_distribution<int> length(0, 12);
  for (int deck = 0; deck < 500; ++deck) {
    ParameterTable table;
    std::vector<std::size_t> sizes;
    for (std::uint32_t line = 1; line <= 12; ++line) {
      std::string text;
      const int n = length(rng);
      for (int k = 0; k < n; ++k) text += fragments[pick(rng)];
      sizes.push_back(text.size());
      table.add_line({text, SourceLoc{0, line, 1}});
    }
    DiagnosticSink sink;
    table.evaluate(sink);
    table.report_unused(sink);
    for (const Diagnostic& d : sink.diagnostics()) {
      ASSERT_GE(d.loc.line, 1u);
      ASSERT_LE(d.loc.line, 12u);
      EXPECT_GE(d.loc.column, 1u);
      EXPECT_LE(d.loc.column, sizes[d.loc.line - 1] + 1);
    }
  }
}

}  // namespace
}  // namespace clinch
