// Lexer: line kinds, field splitting, keyword-line parsing and number syntax
// (input-syntax.md §1–§3). Expected values are exact (strings, locations, integers); reals are
// compared exactly because correct rounding (strtod semantics) is the requirement of §3.2.
#include <gtest/gtest.h>

#include "parser/block_context.hpp"
#include "parser/lexer.hpp"

namespace clinch {
namespace {

std::vector<Field> split(std::string_view text, DiagnosticSink& sink) {
  std::vector<Field> fields;
  split_fields(text, {0, 7, 1}, fields, sink);
  return fields;
}

TEST(Lexer, LineKinds) {
  DiagnosticSink sink;
  LineScanner scanner("** comment\n  ** indented comment\n*NODE\n\n   \n1, 2.\r\n*", 0, sink);
  EXPECT_EQ(scanner.next(), LineScanner::Kind::Comment);
  EXPECT_EQ(scanner.next(), LineScanner::Kind::Comment);
  EXPECT_EQ(scanner.next(), LineScanner::Kind::Keyword);
  EXPECT_EQ(scanner.next(), LineScanner::Kind::Blank);
  EXPECT_EQ(scanner.next(), LineScanner::Kind::Blank);
  EXPECT_EQ(scanner.next(), LineScanner::Kind::Data);
  EXPECT_EQ(scanner.text(), "1, 2.");  // the CR before the LF is dropped
  EXPECT_EQ(scanner.loc().line, 6u);
  EXPECT_EQ(scanner.next(), LineScanner::Kind::Keyword);  // a last line without a line end
  EXPECT_EQ(scanner.next(), LineScanner::Kind::End);
  EXPECT_FALSE(sink.has_errors());
}

TEST(Lexer, ControlCharactersAreReportedOncePerLine) {
  DiagnosticSink sink;
  std::string text = std::string("1, \x01\x02, 3\n") + "2\t, 4\n";
  LineScanner scanner(text, 0, sink);
  scanner.next();
  EXPECT_TRUE(scanner.line_rejected());
  scanner.next();
  EXPECT_FALSE(scanner.line_rejected());  // TAB is a blank
  ASSERT_EQ(sink.diagnostics().size(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].code, DiagCode::control_character);
  EXPECT_EQ(sink.diagnostics()[0].loc.column, 4u);
}

TEST(Lexer, FieldsAreTrimmedAndLocated) {
  DiagnosticSink sink;
  auto f = split("  12 ,  Set 1, \"Datum csys-1\", ,x,", sink);
  ASSERT_EQ(f.size(), 5u);  // the trailing empty field is dropped
  EXPECT_EQ(f[0].text, "12");
  EXPECT_EQ(f[0].loc.column, 3u);
  EXPECT_EQ(f[1].text, "Set1");  // inner blanks removed from unquoted fields
  EXPECT_TRUE(f[1].had_inner_blank);
  EXPECT_EQ(f[2].text, "Datum csys-1");
  EXPECT_TRUE(f[2].quoted);
  EXPECT_EQ(f[2].loc.column, 16u);
  EXPECT_TRUE(f[3].empty());
  EXPECT_EQ(f[4].text, "x");
  EXPECT_FALSE(sink.has_errors());
}

// A field's location spans its written text, trimmed, quotes included; an empty field is a
// point (ARCHITECTURE.md principle 7).
TEST(Lexer, FieldsSpanTheirText) {
  DiagnosticSink sink;
  auto f = split("  12 ,  Set 1, \"a, b\" , ,x", sink);
  ASSERT_EQ(f.size(), 5u);
  EXPECT_EQ(f[0].loc, (SourceLoc{0, 7, 3, 2}));
  EXPECT_EQ(f[1].loc, (SourceLoc{0, 7, 9, 5}));  // "Set 1": inner blanks belong to the span
  EXPECT_EQ(f[2].loc, (SourceLoc{0, 7, 16, 6}));
  EXPECT_EQ(f[2].loc.end_column(), 21u);
  EXPECT_EQ(f[3].loc.length, 0u);
  EXPECT_EQ(f[4].loc, (SourceLoc{0, 7, 26, 1}));
  EXPECT_EQ(f[0].loc.shifted(1), (SourceLoc{0, 7, 4}));  // a position inside is a point
}

TEST(Lexer, KeywordNamesAndParametersSpanTheirText) {
  DiagnosticSink sink;
  KeywordLine line;
  ASSERT_TRUE(parse_keyword_line({{" *Connector Section , elset = welds", {0, 4, 1}}}, line, sink));
  EXPECT_EQ(line.loc, (SourceLoc{0, 4, 2, 18}));  // "*Connector Section"
  ASSERT_EQ(line.params.size(), 1u);
  EXPECT_EQ(line.params[0].loc, (SourceLoc{0, 4, 23, 5}));        // "elset"
  EXPECT_EQ(line.params[0].value.loc, (SourceLoc{0, 4, 31, 5}));  // "welds"
}

TEST(Lexer, CommasInsideQuotesDoNotSplit) {
  DiagnosticSink sink;
  auto f = split("\"a, b\", c", sink);
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(f[0].text, "a, b");
  EXPECT_EQ(f[1].text, "c");
}

TEST(Lexer, UnterminatedQuoteAndNonAscii) {
  DiagnosticSink sink;
  std::vector<Field> fields;
  EXPECT_FALSE(split_fields("1, \"open", {0, 3, 1}, fields, sink));
  ASSERT_EQ(sink.diagnostics().size(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].code, DiagCode::unterminated_quote);
  EXPECT_EQ(sink.diagnostics()[0].loc.column, 4u);
  DiagnosticSink sink2;
  EXPECT_FALSE(split_fields("1, a\xc3\xa9", {0, 3, 1}, fields, sink2));
  EXPECT_EQ(sink2.diagnostics()[0].code, DiagCode::non_ascii);
  DiagnosticSink sink3;
  EXPECT_TRUE(split_fields("\"caf\xc3\xa9\"", {0, 3, 1}, fields, sink3));
  EXPECT_EQ(sink3.diagnostics()[0].code, DiagCode::non_ascii_text);  // a warning in quotes
}

TEST(Lexer, KeywordLineWithContinuation) {
  DiagnosticSink sink;
  KeywordLine line;
  std::vector<KeywordSegment> segments = {{"*Connector Section, elset=welds,", {0, 4, 1}},
                                          {"   BEHAVIOR = spotweld, TIME INTERVAL=0.5", {0, 5, 1}}};
  ASSERT_TRUE(parse_keyword_line(segments, line, sink));
  EXPECT_EQ(line.name, "CONNECTORSECTION");
  ASSERT_EQ(line.params.size(), 3u);
  EXPECT_EQ(line.params[0].name, "ELSET");
  EXPECT_EQ(line.params[0].value.text, "welds");
  EXPECT_EQ(line.params[1].name, "BEHAVIOR");
  EXPECT_EQ(line.params[1].loc.line, 5u);
  EXPECT_EQ(line.params[1].loc.column, 4u);
  EXPECT_EQ(line.params[1].value.text, "spotweld");
  EXPECT_EQ(line.params[2].name, "TIMEINTERVAL");
  EXPECT_FALSE(sink.has_errors());
}

TEST(Lexer, KeywordLineErrors) {
  DiagnosticSink sink;
  KeywordLine line;
  EXPECT_FALSE(parse_keyword_line({{"*, NSET=A", {0, 1, 1}}}, line, sink));
  EXPECT_EQ(sink.diagnostics().back().code, DiagCode::keyword_missing_name);
  EXPECT_FALSE(parse_keyword_line({{"*NODE, =1", {0, 2, 1}}}, line, sink));
  EXPECT_EQ(sink.diagnostics().back().code, DiagCode::malformed_parameter);
  EXPECT_EQ(sink.diagnostics().back().loc.column, 8u);
  EXPECT_FALSE(parse_keyword_line({{"*NODE, NSET==x", {0, 3, 1}}}, line, sink));
  EXPECT_EQ(sink.diagnostics().back().code, DiagCode::malformed_parameter);
  EXPECT_TRUE(parse_keyword_line({{"*ORIENTATION, NAME=\"a=b, c\"", {0, 4, 1}}}, line, sink));
  EXPECT_EQ(line.params[0].value.text, "a=b, c");
}

TEST(Lexer, RealSyntax) {
  double v = 0;
  bool overflow = false;
  EXPECT_TRUE(parse_real_text("1.0D+05", v, &overflow));
  EXPECT_EQ(v, 1.0e5);
  EXPECT_TRUE(parse_real_text("-2.5E-3", v, &overflow));
  EXPECT_EQ(v, -2.5e-3);
  EXPECT_TRUE(parse_real_text(".5", v, &overflow));
  EXPECT_EQ(v, 0.5);
  EXPECT_TRUE(parse_real_text("+1.", v, &overflow));
  EXPECT_EQ(v, 1.0);
  EXPECT_TRUE(parse_real_text("1d5", v, &overflow));
  EXPECT_EQ(v, 1.0e5);
  EXPECT_TRUE(parse_real_text("0.1", v, &overflow));
  EXPECT_EQ(v, 0.1);  // correctly rounded
  for (const char* bad : {"inf", "nan", "-inf", "0x1p3", "1.0+5", "1e", "e5", ".", "", "1..2",
                          "abc", "1,5"}) {
    EXPECT_FALSE(parse_real_text(bad, v, &overflow)) << bad;
  }
  EXPECT_TRUE(parse_real_text("1e999", v, &overflow));
  EXPECT_TRUE(overflow);
}

TEST(Lexer, IntegerSyntax) {
  std::int64_t v = 0;
  EXPECT_TRUE(parse_integer_text("-3", v));
  EXPECT_EQ(v, -3);
  EXPECT_TRUE(parse_integer_text("+4", v));
  EXPECT_EQ(v, 4);
  EXPECT_TRUE(parse_integer_text("9223372036854775807", v));
  EXPECT_EQ(v, INT64_MAX);
  EXPECT_TRUE(parse_integer_text("-9223372036854775808", v));
  EXPECT_EQ(v, INT64_MIN);
  for (const char* bad : {"9223372036854775808", "1.5", "", "-", "12a", "1 2"}) {
    EXPECT_FALSE(parse_integer_text(bad, v)) << bad;
  }
}

}  // namespace
}  // namespace clinch
