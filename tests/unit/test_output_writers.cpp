// Output writers (cli-contract.md "History table", `<job>.sta`, `<job>.log`): each writes into a
// temporary directory, and the text is read back and checked exactly, numbers included.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "src/output/csv_table.hpp"
#include "src/output/history_table.hpp"
#include "src/output/progress.hpp"
#include "src/output/run_log.hpp"
#include "src/output/status_file.hpp"

namespace clinch {
namespace {

namespace fs = std::filesystem;

class OutputWriters : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           fmt::format("clinch-output-{}-{}", getpid(),
                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
  }

  fs::path dir_;
};

TEST_F(OutputWriters, HistoryTableHeaderAndRows) {
  HistoryTable table;
  std::string error;
  ASSERT_TRUE(table.open(dir_ / "job.history.csv", {"CTF1@12", "U2@5"}, &error)) << error;
  ASSERT_TRUE(table.write_row(1, 0, 0.0, 0.0, std::vector<double>{0.0, -2.5}));
  ASSERT_TRUE(table.write_row(2, 13, 0.75, 1.75, std::vector<double>{1e22, 1e-5}));
  EXPECT_EQ(slurp(dir_ / "job.history.csv"),
            "step,increment,step_time,total_time,CTF1@12,U2@5\n"
            "1,0,0,0,0,-2.5\n"
            "2,13,0.75,1.75,1e+22,1e-05\n");
}

TEST_F(OutputWriters, HistoryTableIsReadableBeforeItIsClosed) {
  // A run that stops early keeps every row written so far: each row is flushed at once.
  HistoryTable table;
  std::string error;
  ASSERT_TRUE(table.open(dir_ / "job.history.csv", {"CU1@1"}, &error)) << error;
  ASSERT_TRUE(table.write_row(1, 1, 0.5, 0.5, std::vector<double>{3.0}));
  EXPECT_EQ(slurp(dir_ / "job.history.csv"),
            "step,increment,step_time,total_time,CU1@1\n1,1,0.5,0.5,3\n");
}

TEST_F(OutputWriters, HistoryNumbersRoundTripExactly) {
  // Values with no short decimal form, the extremes of the double range, and a subnormal must read
  // back bit for bit (cli-contract.md: round-trip precision), so the comparison is exact equality.
  const std::vector<double> values = {1.0 / 3.0,
                                      1e-300,
                                      -2.0 / 3.0,
                                      0.1 + 0.2,
                                      std::numeric_limits<double>::max(),
                                      std::numeric_limits<double>::denorm_min(),
                                      -0.0};
  std::vector<std::string> columns;
  for (std::size_t i = 0; i < values.size(); ++i) columns.push_back(fmt::format("V{}@1", i));
  HistoryTable table;
  std::string error;
  const fs::path path = dir_ / "job.history.csv";
  ASSERT_TRUE(table.open(path, columns, &error)) << error;
  ASSERT_TRUE(table.write_row(1, 1, 1.0 / 3.0, 1e-300, values));

  const std::optional<CsvTable> read = read_csv_table(path.string(), &error);
  ASSERT_TRUE(read) << error;
  ASSERT_EQ(read->rows.size(), 1u);
  const std::vector<double>& row = read->rows[0];
  EXPECT_EQ(row[2], 1.0 / 3.0);
  EXPECT_EQ(row[3], 1e-300);
  for (std::size_t i = 0; i < values.size(); ++i) {
    EXPECT_EQ(row[4 + i], values[i]) << columns[i];
  }
  EXPECT_TRUE(std::signbit(row[4 + 6]));
}

TEST_F(OutputWriters, HistoryTableReportsUnwritablePath) {
  HistoryTable table;
  std::string error;
  EXPECT_FALSE(table.open(dir_ / "no-such-dir" / "job.history.csv", {}, &error));
  EXPECT_NE(error.find("cannot write"), std::string::npos) << error;
}

TEST_F(OutputWriters, HistoryTableRejectsAWrongNumberOfValues) {
  // A row that does not match the header is a bug in the caller, not a run outcome.
  HistoryTable table;
  std::string error;
  ASSERT_TRUE(table.open(dir_ / "job.history.csv", {"A@1", "B@1"}, &error)) << error;
  EXPECT_THROW(table.write_row(1, 1, 1.0, 1.0, std::vector<double>{1.0}), std::logic_error);
}

TEST_F(OutputWriters, StatusFileLinesAndFailure) {
  StatusFile sta;
  std::string error;
  ASSERT_TRUE(sta.open(dir_ / "job.sta", &error)) << error;
  sta.write_attempt({.step = 1,
                     .increment = 1,
                     .attempt = 1,
                     .cut_back = false,
                     .equilibrium_iterations = 3,
                     .total_iterations = 3,
                     .total_time = 0.25,
                     .step_time = 0.25,
                     .time_increment = 0.25});
  sta.write_attempt({.step = 1,
                     .increment = 2,
                     .attempt = 1,
                     .cut_back = true,
                     .equilibrium_iterations = 12,
                     .total_iterations = 14,
                     .total_time = 0.5,
                     .step_time = 0.5,
                     .time_increment = 0.25});
  sta.write_failed("no convergence with fixed increments", 1, 3, 0.75);
  EXPECT_EQ(slurp(dir_ / "job.sta"),
            " step   inc  att  cut  equil  total      total time       step time        time inc\n"
            "    1     1    1           3      3            0.25            0.25            0.25\n"
            "    1     2    1    U     12     14             0.5             0.5            0.25\n"
            "FAILED: no convergence with fixed increments (step 1, increment 3, time 0.75)\n");
}

TEST_F(OutputWriters, StatusFileCompleted) {
  StatusFile sta;
  std::string error;
  ASSERT_TRUE(sta.open(dir_ / "job.sta", &error)) << error;
  sta.write_attempt({.step = 2,
                     .increment = 10,
                     .attempt = 3,
                     .cut_back = false,
                     .equilibrium_iterations = 2,
                     .total_iterations = 5,
                     .total_time = 1.0 / 3.0,
                     .step_time = 1e-300,
                     .time_increment = 123456789.0});
  sta.write_completed();
  const std::string text = slurp(dir_ / "job.sta");
  // Times in the status file are shown with 7 significant digits.
  EXPECT_NE(text.find("\n    2    10    3           2      5       0.3333333          1e-300"
                      "    1.234568e+08\n"),
            std::string::npos)
      << text;
  EXPECT_TRUE(text.ends_with("\nCOMPLETED\n")) << text;
}

TEST_F(OutputWriters, RunLogHoldsWhatWasPrinted) {
  std::ostringstream out;
  std::ostringstream err;
  RunLog log(&out, &err);
  std::string error;
  ASSERT_TRUE(log.open(dir_ / "job.log", &error)) << error;
  log.info("step 1: 4 increments");
  log.warning("deck.inp:3:1: warning: *PREPRINT has no effect\n");
  log.iteration({.step = 1,
                 .increment = 2,
                 .attempt = 1,
                 .iteration = 3,
                 .residual_norm = 1.0 / 3.0,
                 .largest_residual = 0.25,
                 .largest_residual_at = "node 5 dof 2",
                 .correction_norm = 1e-300,
                 .largest_correction = 2e-300,
                 .largest_correction_at = "",
                 .constraint_violation = 0.0});
  log.error("no convergence");
  EXPECT_EQ(out.str(), "step 1: 4 increments\n");
  EXPECT_EQ(err.str(), "deck.inp:3:1: warning: *PREPRINT has no effect\nno convergence\n");
  EXPECT_EQ(slurp(dir_ / "job.log"),
            "step 1: 4 increments\n"
            "deck.inp:3:1: warning: *PREPRINT has no effect\n"
            "step 1 increment 2 attempt 1 iteration 3: residual 3.333333e-01 (largest "
            "2.500000e-01 at node 5 dof 2), correction 1.000000e-300 (largest 2.000000e-300), "
            "constraint violation 0.000000e+00\n"
            "no convergence\n");
}

TEST_F(OutputWriters, RunLogWithoutEchoStillLogs) {
  RunLog log;
  std::string error;
  ASSERT_TRUE(log.open(dir_ / "job.log", &error)) << error;
  log.info("quiet");
  EXPECT_EQ(slurp(dir_ / "job.log"), "quiet\n");
}

// A full disk (/dev/full fails every write with ENOSPC): each writer reports it with the file's
// name, and the log still prints what it could not log.
TEST_F(OutputWriters, WritersReportAFullDisk) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  std::string error;
  HistoryTable table;
  EXPECT_FALSE(table.open("/dev/full", {"A@1"}, &error));
  EXPECT_EQ(error, "cannot write '/dev/full': No space left on device");
  EXPECT_FALSE(table.write_row(1, 0, 0.0, 0.0, std::vector<double>{1.0}));
  EXPECT_EQ(table.file().error(), error);

  error.clear();
  StatusFile sta;
  EXPECT_FALSE(sta.open("/dev/full", &error));
  EXPECT_EQ(error, "cannot write '/dev/full': No space left on device");
  EXPECT_FALSE(sta.write_completed());

  std::ostringstream err;
  RunLog log(nullptr, &err);
  ASSERT_TRUE(log.open("/dev/full", &error)) << error;
  EXPECT_FALSE(log.file().failed());
  log.error("no convergence");
  EXPECT_EQ(err.str(), "no convergence\n");
  EXPECT_TRUE(log.file().failed());
  EXPECT_EQ(log.file().error(), "cannot write '/dev/full': No space left on device");
}

TEST_F(OutputWriters, ProgressRewritesOneLine) {
  std::ostringstream err;
  {
    Progress progress(&err);
    progress.update(1, 10, 0.5);
    progress.update(1, 2, 1.0);
  }
  // The shorter second line is padded over the first; destruction ends the line.
  EXPECT_EQ(err.str(),
            "\rstep 1  increment 10  time 0.5"
            "\rstep 1  increment 2  time 1   \n");
}

TEST_F(OutputWriters, ProgressNamesTheStep) {
  std::ostringstream err;
  Progress progress(&err);
  progress.update(2, 4, 1.4, "Close");
  EXPECT_EQ(err.str(), "\rstep 2 (Close)  increment 4  time 1.4");
}

TEST_F(OutputWriters, ProgressClearErasesTheLine) {
  std::ostringstream err;
  Progress progress(&err);
  progress.update(2, 1, 1.25);
  progress.clear();
  progress.finish();  // nothing is shown any more, so no newline
  EXPECT_EQ(err.str(), "\rstep 2  increment 1  time 1.25\r" + std::string(30, ' ') + "\r");
}

TEST_F(OutputWriters, QuietProgressShowsNothing) {
  Progress progress = Progress::for_stderr(true);
  EXPECT_FALSE(progress.enabled());
}

}  // namespace
}  // namespace clinch
