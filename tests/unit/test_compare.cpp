// `clinch compare` (cli-contract.md): reading history tables back, matching rows by total_time,
// linear interpolation at golden times, the tolerance test |r - g| <= atol + rtol * max(|g|,
// scale_of_column), missing columns and steps, the --columns filter and the printed report.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "src/output/csv_table.hpp"
#include "src/output/table_comparison.hpp"

namespace clinch {
namespace {

CsvTable parse(const std::string& text, const std::string& path = "table.csv") {
  std::string error;
  std::optional<CsvTable> table = parse_csv_table(path, text, &error);
  EXPECT_TRUE(table) << error;
  return table ? *table : CsvTable{};
}

std::string parse_error(const std::string& text) {
  std::string error;
  EXPECT_FALSE(parse_csv_table("bad.csv", text, &error));
  return error;
}

std::shared_ptr<const re2::RE2> pattern(const std::string& text) {
  std::string error;
  std::shared_ptr<const re2::RE2> compiled = compile_column_pattern(text, &error);
  EXPECT_TRUE(compiled) << error;
  return compiled;
}

TableComparison compare(const std::string& result, const std::string& golden,
                        CompareOptions options = {}) {
  std::string error;
  std::optional<TableComparison> c =
      compare_tables(parse(result, "result.csv"), parse(golden, "golden.csv"), options, &error);
  EXPECT_TRUE(c) << error;
  return c ? *c : TableComparison{};
}

std::string compare_error(const std::string& result, const std::string& golden,
                          CompareOptions options = {}) {
  std::string error;
  EXPECT_FALSE(
      compare_tables(parse(result, "result.csv"), parse(golden, "golden.csv"), options, &error));
  return error;
}

const std::string kHeader = "step,increment,step_time,total_time,F@1\n";

TEST(CsvTable, ReadsHeaderRowsAndCommentLines) {
  const CsvTable t = parse(
      "# provenance: closed form\n"
      "#   F = 2 t\n"
      "step,increment,step_time,total_time,F@1\r\n"
      "1,0,0,0,0\r\n"
      "1, 1, 0.5, 0.5, +1e0\n"
      "\n"
      "1,2,1,1,-inf\n");
  ASSERT_EQ(t.columns.size(), 5u);
  EXPECT_EQ(t.columns[4], "F@1");
  ASSERT_EQ(t.rows.size(), 3u);
  EXPECT_EQ(t.rows[1][4], 1.0);
  EXPECT_EQ(t.rows[2][4], -std::numeric_limits<double>::infinity());
  EXPECT_EQ(t.row_lines[1], 5u);
  EXPECT_EQ(t.column_index("total_time"), 3u);
  EXPECT_FALSE(t.column_index("G@1"));
}

TEST(CsvTable, ReportsFileAndLine) {
  EXPECT_EQ(parse_error("a,b\n1,2\n1,x2\n"), "bad.csv:3: 'x2' in column 'b' is not a number");
  EXPECT_EQ(parse_error("a,b\n1,2\n1\n"), "bad.csv:3: row has 1 fields, the header has 2");
  EXPECT_EQ(parse_error("a,b\n1,2,3\n"), "bad.csv:2: row has 3 fields, the header has 2");
  EXPECT_EQ(parse_error(""), "bad.csv:1: empty table: no header row");
  EXPECT_EQ(parse_error("# only a comment\n"), "bad.csv:2: empty table: no header row");
  EXPECT_EQ(parse_error("a,,b\n"), "bad.csv:1: empty column name in the header");
  EXPECT_EQ(parse_error("a,b,a\n"), "bad.csv:1: column 'a' appears twice in the header");
  EXPECT_EQ(parse_error("a\n1\n# late comment\n"),
            "bad.csv:3: '# late comment' in column 'a' is not a number");
  EXPECT_EQ(parse_error("a\n1.5.2\n"), "bad.csv:2: '1.5.2' in column 'a' is not a number");
}

TEST(CsvTable, UnreadableFile) {
  std::string error;
  EXPECT_FALSE(read_csv_table("/no/such/file.csv", &error));
  EXPECT_EQ(error.rfind("/no/such/file.csv: cannot read", 0), 0u) << error;
}

TEST(Compare, IdenticalTablesPass) {
  const std::string table = kHeader + "1,0,0,0,0\n1,1,1,1,2.5\n";
  const TableComparison c = compare(table, table);
  ASSERT_EQ(c.columns.size(), 1u);
  EXPECT_EQ(c.columns[0].name, "F@1");
  EXPECT_EQ(c.columns[0].verdict, ColumnVerdict::Pass);
  EXPECT_EQ(c.columns[0].compared_rows, 2u);
  EXPECT_TRUE(c.passed());
}

TEST(Compare, ValueExactlyAtTheTolerancePassesJustAboveFails) {
  // scale_of_column = max |g| = 4, so allowed = atol + rtol * 4 = 0.5 + 0.125 * 4 = 1 at every row
  // (all numbers are exact in binary). The row g = 4 with r = 5 is exactly at the tolerance.
  CompareOptions options;
  options.rtol = 0.125;
  options.atol = 0.5;
  const std::string golden = kHeader + "1,0,0,0,2\n1,1,1,1,4\n";
  const TableComparison at = compare(kHeader + "1,0,0,0,2\n1,1,1,1,5\n", golden, options);
  EXPECT_EQ(at.columns[0].verdict, ColumnVerdict::Pass);
  EXPECT_EQ(at.columns[0].difference, 1.0);
  EXPECT_EQ(at.columns[0].allowed, 1.0);

  // The next double above 5: |diff| exceeds 1 by one ulp of 5.
  const std::string above = kHeader + "1,0,0,0,2\n1,1,1,1,5.000000000000001\n";
  ASSERT_GT(5.000000000000001, 5.0);
  const TableComparison over = compare(above, golden, options);
  EXPECT_EQ(over.columns[0].verdict, ColumnVerdict::Fail);
  EXPECT_EQ(over.columns[0].failed_rows, 1u);
  EXPECT_FALSE(over.passed());
}

TEST(Compare, ScaleOfColumnWidensSmallValues) {
  // Near a zero crossing (g = 1e-3 in a column whose largest |g| is 1000) the relative tolerance
  // is taken of the column scale: allowed = 1e-6 * 1000 = 1e-3, so r = 1.5e-3 passes.
  CompareOptions options;
  options.rtol = 1e-6;
  options.atol = 0.0;
  const std::string golden = kHeader + "1,0,0,0,1e-3\n1,1,1,1,1000\n";
  EXPECT_TRUE(compare(kHeader + "1,0,0,0,1.5e-3\n1,1,1,1,1000\n", golden, options).passed());
  EXPECT_FALSE(compare(kHeader + "1,0,0,0,2.5e-3\n1,1,1,1,1000\n", golden, options).passed());
}

TEST(Compare, InterpolatesBetweenResultRows) {
  // Result rows at t = 0.5 (F = 1) and t = 1 (F = 3); golden at t = 0.625 lies a quarter of the
  // way: F = 1 + 0.25 * 2 = 1.5 exactly. Zero tolerance: only the exact linear value passes.
  CompareOptions options;
  options.rtol = 0.0;
  options.atol = 0.0;
  const std::string result = kHeader + "1,0,0,0,0\n1,1,0.5,0.5,1\n1,2,1,1,3\n";
  const TableComparison c = compare(result, kHeader + "1,3,0.625,0.625,1.5\n", options);
  EXPECT_TRUE(c.passed());
  EXPECT_EQ(c.columns[0].result, 1.5);
  EXPECT_EQ(c.columns[0].total_time, 0.625);
  EXPECT_FALSE(compare(result, kHeader + "1,3,0.625,0.625,1.4999999\n", options).passed());
}

TEST(Compare, RepeatedTimeUsesTheLastRow) {
  // Two result rows at t = 0.5 (a re-solved increment): the golden value at 0.5 is matched with
  // the later one (F = 7); a golden time between 0.5 and 1 interpolates from that later row.
  CompareOptions options;
  options.rtol = 0.0;
  options.atol = 0.0;
  const std::string result = kHeader + "1,0,0,0,0\n1,1,0.5,0.5,1\n1,2,0.5,0.5,7\n1,3,1,1,9\n";
  EXPECT_TRUE(compare(result, kHeader + "1,1,0.5,0.5,7\n", options).passed());
  EXPECT_FALSE(compare(result, kHeader + "1,1,0.5,0.5,1\n", options).passed());
  EXPECT_TRUE(compare(result, kHeader + "1,2,0.75,0.75,8\n", options).passed());
  // Just below 0.5 the bracketing rows are t = 0 and the first row at 0.5.
  EXPECT_TRUE(compare(result, kHeader + "1,1,0.25,0.25,0.5\n", options).passed());
}

TEST(Compare, RowsOfStepsAtOneTimeAreMatchedByStep) {
  // Steps 2 and 3 are perturbation steps (no time): their rows share t = 1 with the end of step 1.
  // A golden row at t = 1 is matched with the result's row of its own step, and with the last
  // row at that time when its step has none there.
  CompareOptions options;
  options.rtol = 0.0;
  options.atol = 0.0;
  const std::string result =
      kHeader + "1,0,0,0,0\n1,1,1,1,5\n2,1,0,1,0.5\n3,1,0,1,-2\n4,1,1,2,6\n";
  EXPECT_TRUE(compare(result, kHeader + "1,1,1,1,5\n2,1,0,1,0.5\n3,1,0,1,-2\n", options)
                  .passed());
  EXPECT_FALSE(compare(result, kHeader + "2,1,0,1,5\n", options).passed());
  EXPECT_TRUE(compare(result, kHeader + "4,1,0,1,-2\n", options).passed());
  // Between times the bracketing rows stay the adjacent pair: step 3's row and step 4's.
  EXPECT_TRUE(compare(result, kHeader + "4,1,0.5,1.5,2\n", options).passed());
}

TEST(Compare, TimesEqualUpToRoundOffMatch) {
  // 0.1 + 0.2 != 0.3 in binary; a result that reached 0.3 by a sum of increments still matches a
  // golden row at 0.3 (within 1e-12 of the time scale) and is not outside the time range.
  CompareOptions options;
  options.rtol = 0.0;
  options.atol = 0.0;
  const std::string result =
      kHeader + fmt::format("1,0,0,0,0\n1,1,0.1,0.1,1\n1,2,{},{},5\n", 0.1 + 0.2, 0.1 + 0.2);
  EXPECT_TRUE(compare(result, kHeader + "1,2,0.3,0.3,5\n", options).passed());
}

TEST(Compare, GoldenTimeOutsideTheResultFailsTheColumn) {
  // A run that stopped at t = 1 cannot pass a golden table that goes to t = 2.
  const std::string result = kHeader + "1,0,0,0,0\n1,1,1,1,1\n";
  const TableComparison c = compare(result, kHeader + "1,0,0,0,0\n1,2,2,2,2\n");
  EXPECT_EQ(c.columns[0].verdict, ColumnVerdict::Fail);
  EXPECT_EQ(c.columns[0].out_of_range_rows, 1u);
  EXPECT_EQ(c.columns[0].first_out_of_range_time, 2.0);
  EXPECT_EQ(c.columns[0].failed_rows, 0u);
  EXPECT_FALSE(c.passed());
}

TEST(Compare, GoldenStepMissingInTheResultFails) {
  const std::string result = kHeader + "1,0,0,0,0\n1,1,1,1,1\n";
  const TableComparison c = compare(result, kHeader + "1,0,0,0,0\n2,0,0,1,1\n");
  EXPECT_EQ(c.columns[0].verdict, ColumnVerdict::Pass);
  ASSERT_EQ(c.problems.size(), 1u);
  EXPECT_EQ(c.problems[0], "step 2 of the golden table has no row in the result");
  EXPECT_FALSE(c.passed());
}

TEST(Compare, MissingColumnFails) {
  const std::string result = kHeader + "1,0,0,0,0\n";
  const TableComparison c =
      compare(result, "step,increment,step_time,total_time,F@1,G@1\n1,0,0,0,0,0\n");
  ASSERT_EQ(c.columns.size(), 2u);
  EXPECT_EQ(c.columns[0].verdict, ColumnVerdict::Pass);
  EXPECT_EQ(c.columns[1].name, "G@1");
  EXPECT_EQ(c.columns[1].verdict, ColumnVerdict::Missing);
  EXPECT_FALSE(c.passed());
}

TEST(Compare, ExtraResultColumnsAreIgnored) {
  const TableComparison c = compare("step,increment,step_time,total_time,F@1,G@1\n1,0,0,0,0,9\n",
                                    kHeader + "1,0,0,0,0\n");
  EXPECT_EQ(c.columns.size(), 1u);
  EXPECT_TRUE(c.passed());
}

TEST(Compare, ColumnsFilterMatchesTheWholeName) {
  const std::string header = "step,increment,step_time,total_time,CTF1@1,CTF2@1,CU1@1\n";
  const std::string result = header + "1,0,0,0,1,2,3\n";
  const std::string golden = header + "1,0,0,0,1,20,30\n";
  CompareOptions options;
  options.columns = pattern("CTF1@.*");
  const TableComparison c = compare(result, golden, options);
  ASSERT_EQ(c.columns.size(), 1u);
  EXPECT_EQ(c.columns[0].name, "CTF1@1");
  EXPECT_TRUE(c.passed());
  // "CTF" alone matches no full name: a partial match does not select a column.
  options.columns = pattern("CTF");
  EXPECT_EQ(compare_error(result, golden, options),
            "golden.csv: --columns selects none of its columns");
  options.columns = pattern("CTF.*");
  const TableComparison two = compare(result, golden, options);
  ASSERT_EQ(two.columns.size(), 2u);
  EXPECT_FALSE(two.passed());
}

TEST(Compare, ColumnPatternRejectedByRe2IsAnError) {
  std::string error;
  EXPECT_FALSE(compile_column_pattern("(", &error));
  EXPECT_EQ(error, "missing ): (");
  EXPECT_FALSE(compile_column_pattern("a\\1", &error));  // backreferences need backtracking
}

TEST(Compare, NanNeverPassesEqualInfinitiesDo) {
  EXPECT_FALSE(compare(kHeader + "1,0,0,0,nan\n", kHeader + "1,0,0,0,nan\n").passed());
  EXPECT_FALSE(compare(kHeader + "1,0,0,0,nan\n", kHeader + "1,0,0,0,1\n").passed());
  EXPECT_TRUE(compare(kHeader + "1,0,0,0,inf\n", kHeader + "1,0,0,0,inf\n").passed());
}

TEST(Compare, WorstRowIsAFailingOne) {
  // allowed = 0.5 everywhere. Row t = 0 passes (|diff| 0.25); rows t = 1 (|diff| 1) and t = 2
  // (|diff| 0.75) fail. The worst is the failing row with the largest |diff| / allowed: t = 1.
  CompareOptions options;
  options.rtol = 0.0;
  options.atol = 0.5;
  const TableComparison c = compare(kHeader + "1,0,0,0,0.25\n1,1,1,1,3\n1,2,2,2,2.75\n",
                                    kHeader + "1,0,0,0,0\n1,1,1,1,2\n1,2,2,2,2\n", options);
  EXPECT_EQ(c.columns[0].failed_rows, 2u);
  EXPECT_EQ(c.columns[0].total_time, 1.0);
  EXPECT_EQ(c.columns[0].difference, 1.0);
}

TEST(Compare, TablesThatCannotBeCompared) {
  EXPECT_EQ(compare_error("step,increment,step_time,F@1\n1,0,0,0\n", kHeader + "1,0,0,0,0\n"),
            "result.csv: no 'total_time' column: not a history table");
  EXPECT_EQ(compare_error(kHeader + "1,0,0,0,0\n", kHeader),
            "golden.csv: the golden table has no rows");
  EXPECT_EQ(
      compare_error(kHeader + "1,0,0,0,0\n1,1,1,1,0\n1,2,0.5,0.5,0\n", kHeader + "1,0,0,0,0\n"),
      "result.csv:4: total_time 0.5 comes after 1: rows must be in time order");
  EXPECT_EQ(
      compare_error(kHeader + "1,0,0,0,0\n", "step,increment,step_time,total_time\n1,0,0,0\n"),
      "golden.csv: the golden table has no column besides the keys");
}

TEST(Compare, ReportShowsWorstDeviationAndVerdicts) {
  CompareOptions options;
  options.rtol = 0.125;
  options.atol = 0.5;
  const TableComparison c = compare(
      "step,increment,step_time,total_time,F@1\n1,0,0,0,2\n1,1,1,1,5.5\n",
      "step,increment,step_time,total_time,F@1,Missing@2\n1,0,0,0,2,0\n1,1,1,1,4,0\n", options);
  EXPECT_EQ(render_comparison(c, options),
            "rtol 0.125, atol 0.5; 2 golden rows\n"
            "column     verdict                   result                   golden     |diff|"
            "    allowed  total_time\n"
            "F@1        FAIL                         5.5                        4  1.500e+00"
            "  1.000e+00  1  (1 of 2 rows fail)\n"
            "Missing@2  FAIL    missing in the result\n"
            "FAIL: 2 of 2 columns fail\n");
}

}  // namespace
}  // namespace clinch
