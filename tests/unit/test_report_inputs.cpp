// `clinch report` inputs: the Newton iteration lines read back from a log exactly as RunLog
// writes them (other lines skipped), and the page data built from a run's tables, attempts and
// a golden comparison.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "src/output/csv_table.hpp"
#include "src/output/iteration_log_reader.hpp"
#include "src/output/run_log.hpp"
#include "src/output/table_comparison.hpp"
#include "src/report/report_data.hpp"

namespace clinch {
namespace {

TEST(IterationLogReader, ReadsWhatRunLogWrites) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "clinch-report.log";
  {
    RunLog log;
    std::string error;
    ASSERT_TRUE(log.open(path, &error)) << error;
    log.info("deck.inp: 2 nodes, 1 connectors");
    log.iteration({.step = 2,
                   .increment = 3,
                   .attempt = 2,
                   .iteration = 1,
                   .residual_norm = 1.25e3,
                   .largest_residual = 1e3,
                   .largest_residual_at = "DOF u1 of node Part-1-1.2 (instance Part-1-1)",
                   .correction_norm = 4.5e-7,
                   .largest_correction = 4e-7,
                   .largest_correction_at = "DOF u2 of node 2",
                   .constraint_violation = 2.5e-12});
    log.info("done");
  }
  std::string error;
  const auto records = read_iteration_log(path.string(), &error);
  ASSERT_TRUE(records) << error;
  ASSERT_EQ(records->size(), 1u);
  const IterationRecord& r = records->front();
  EXPECT_EQ(r.step, 2);
  EXPECT_EQ(r.increment, 3);
  EXPECT_EQ(r.attempt, 2);
  EXPECT_EQ(r.iteration, 1);
  // Six significant digits, as the log writes them.
  EXPECT_DOUBLE_EQ(r.residual_norm, 1.25e3);
  EXPECT_DOUBLE_EQ(r.correction_norm, 4.5e-7);
  EXPECT_DOUBLE_EQ(r.constraint_violation, 2.5e-12);
  EXPECT_FALSE(read_iteration_log("/nonexistent/x.log", &error));
}

TEST(ReportData, GoldenWorstDeviationAndAttempts) {
  std::string error;
  const auto result = parse_csv_table(
      "r.csv", "step,increment,step_time,total_time,A@1\n1,0,0,0,0\n1,1,1,1,1.5\n1,2,2,2,2\n",
      &error);
  const auto golden = parse_csv_table(
      "g.csv", "step,increment,step_time,total_time,A@1\n1,1,1,1,1\n1,2,2,2,2\n", &error);
  ASSERT_TRUE(result && golden) << error;
  CompareOptions options;
  options.rtol = 0.1;
  options.atol = 0.0;
  const auto comparison = compare_tables(*result, *golden, options, &error);
  ASSERT_TRUE(comparison) << error;
  StatusRecord status;
  status.attempts.push_back({.step = 1, .increment = 1, .attempt = 1, .cut_back = true});
  status.attempts.push_back({.step = 1, .increment = 1, .attempt = 2, .total_iterations = 3});
  status.ending = "COMPLETED";
  ReportInputs inputs;
  inputs.job = "r";
  inputs.history = &*result;
  inputs.status = &status;
  inputs.golden = &*golden;
  inputs.comparison = &*comparison;
  inputs.compare_options = options;
  inputs.max_connectors = 7;
  const nlohmann::json data = report_data(inputs);
  EXPECT_EQ(data["max_connectors"], 7);
  EXPECT_EQ(data["attempts"].size(), 2u);
  EXPECT_EQ(data["attempts"][0]["cut_back"], true);
  EXPECT_EQ(data["ending"], "COMPLETED");
  const nlohmann::json& a = data["golden"]["comparison"][0];
  EXPECT_EQ(a["name"], "A@1");
  EXPECT_EQ(a["verdict"], "fail");
  // |1.5 - 1| at t = 1 against an allowance of 0.1 * max(|1|, 2) = 0.2.
  EXPECT_EQ(a["worst"]["total_time"], 1.0);
  EXPECT_DOUBLE_EQ(a["worst"]["difference"], 0.5);
  EXPECT_DOUBLE_EQ(a["worst"]["allowed"], 0.2);
  EXPECT_EQ(data["iterations"].size(), 0u);
  EXPECT_FALSE(data.contains("study_csv"));
}

// A job or column name from a file name in Latin-1 (0xFF is never UTF-8): the data is still
// written, as valid JSON, with U+FFFD where the byte was.
TEST(ReportData, NamesThatAreNotUtf8AreReplaced) {
  std::string error;
  const auto history = parse_csv_table(
      "r.csv", "step,increment,step_time,total_time,A@w\xff\n1,0,0,0,0\n", &error);
  ASSERT_TRUE(history) << error;
  ReportInputs inputs;
  inputs.job = "weld\xff";
  inputs.history = &*history;
  const std::string text = report_data_text(inputs);
  const nlohmann::json data = nlohmann::json::parse(text);
  EXPECT_EQ(data["job"], "weld\xef\xbf\xbd");
  EXPECT_EQ(data["history"]["columns"][4], "A@w\xef\xbf\xbd");
}

// JSON has no NaN or infinity (a diverged run writes them): they travel as strings that
// report_page.py turns back into numbers.
TEST(ReportData, NonFiniteNumbersAreStrings) {
  std::string error;
  const auto history = parse_csv_table(
      "r.csv", "step,increment,step_time,total_time,A@1\n1,1,1,1,nan\n1,2,2,2,-inf\n", &error);
  ASSERT_TRUE(history) << error;
  ReportInputs inputs;
  inputs.job = "r";
  inputs.history = &*history;
  const std::vector<IterationRecord> iterations = {{.residual_norm = INFINITY}};
  inputs.iterations = &iterations;
  const nlohmann::json data = nlohmann::json::parse(report_data_text(inputs));
  EXPECT_EQ(data["history"]["rows"][0][4], "nan");
  EXPECT_EQ(data["history"]["rows"][1][4], "-inf");
  EXPECT_EQ(data["history"]["rows"][1][3], 2.0);
  EXPECT_EQ(data["iterations"][0]["residual"], "inf");
}

}  // namespace
}  // namespace clinch
