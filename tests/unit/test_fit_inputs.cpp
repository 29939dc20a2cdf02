// What a fit reads (docs/fit.md): the measured curves and the model's values at their points
// (src/fit/measured_curves.hpp), and the deck copies with the varied parameters
// (src/fit/parameter_deck.hpp). The interpolated values are checked against hand-computed ones
// (exact in binary or to 1e-15 relative: one multiplication and one addition).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "src/fit/measured_curves.hpp"
#include "src/fit/parameter_deck.hpp"

namespace clinch {
namespace {

namespace fs = std::filesystem;

class FitInputs : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / fmt::format("clinch-fit-inputs-{}", getpid());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    const fs::path path = dir_ / name;
    std::ofstream(path) << text;
    return path.string();
  }
  fs::path dir_;
};

CsvTable run_table(const std::string& text) {
  std::string error;
  std::optional<CsvTable> table = parse_csv_table("run.history.csv", text, &error);
  EXPECT_TRUE(table) << error;
  return *table;
}

TEST_F(FitInputs, ModelInterpolatedAtTheMeasuredAbscissa) {
  std::string error;
  const std::string data = write("test.csv", "# a note\nCU1@1, CTM1@1\n-0.05,2.0\n-0.2,9.0\n");
  const std::optional<MeasuredCurves> curves = read_measured_curves(data, "CU1@1", {}, &error);
  ASSERT_TRUE(curves) << error;
  EXPECT_EQ(curves->header_position(1), data + ":2:8");
  ASSERT_EQ(curves->columns.size(), 1u);
  EXPECT_EQ(curves->columns[0].scale, 9.0);  // the largest |measured value|
  // A pull in -1: the run's abscissa decreases; CTM1 is the run's CTF4.
  const CsvTable run = run_table(
      "step,increment,step_time,total_time,CU1@1,CTF4@1\n"
      "1,0,0,0,0,0\n1,1,0.5,0.5,-0.1,4\n1,2,1,1,-0.2,10\n");
  ASSERT_TRUE(check_columns_written(*curves, run, "deck.inp", &error)) << error;
  const std::optional<std::vector<double>> model = model_values(*curves, run, &error);
  ASSERT_TRUE(model) << error;
  EXPECT_EQ(*model, (std::vector<double>{2.0, 10.0}));  // halfway 0..4, then the last row
  std::vector<double> residuals;
  append_residuals(*curves, *model, residuals);
  EXPECT_EQ(residuals, (std::vector<double>{0.0, 1.0 / 9.0}));
}

TEST_F(FitInputs, ColumnNotWrittenIsAtItsHeaderPosition) {
  std::string error;
  const std::string data = write("test.csv", "total_time,CSF1@1\n0.5,1.0\n");
  const std::optional<MeasuredCurves> curves =
      read_measured_curves(data, "total_time", {}, &error);
  ASSERT_TRUE(curves) << error;
  const CsvTable run = run_table("step,increment,step_time,total_time,CTF1@1\n1,1,1,1,3\n");
  EXPECT_FALSE(check_columns_written(*curves, run, "deck.inp", &error));
  EXPECT_NE(error.find(data + ":1:12: error: the run of deck.inp writes no column 'CSF1@1'"),
            std::string::npos)
      << error;
}

TEST_F(FitInputs, AbscissaThatTurnsBackOrDoesNotReach) {
  std::string error;
  const std::string data = write("test.csv", "CU1@1,CTF1@1\n0.5,1.0\n");
  const std::optional<MeasuredCurves> curves = read_measured_curves(data, "CU1@1", {}, &error);
  ASSERT_TRUE(curves) << error;
  const CsvTable cyclic = run_table(
      "step,increment,step_time,total_time,CU1@1,CTF1@1\n1,1,1,1,1,1\n1,2,2,2,0,0\n1,3,3,3,2,2\n");
  EXPECT_FALSE(model_values(*curves, cyclic, &error));
  EXPECT_NE(error.find("turns back"), std::string::npos) << error;
  const CsvTable short_run =
      run_table("step,increment,step_time,total_time,CU1@1,CTF1@1\n1,1,1,1,0.1,1\n1,2,2,2,0.2,2\n");
  EXPECT_FALSE(model_values(*curves, short_run, &error));
  EXPECT_NE(error.find(data + ":2: error: CU1@1 = 0.5 lies outside the run's range [0.1, 0.2]"),
            std::string::npos)
      << error;
}

TEST_F(FitInputs, DeckCopyReplacesTheFinalDefinitionsOnly) {
  write("included.inp", "*NODE\n1, 0., 0., 0.\n");
  const std::string deck = write("deck.inp",
                                 "*PARAMETER\nk = 1.0  # first\nk = 2.0\nr = 2*k\nname = 'x'\n"
                                 "*INCLUDE, INPUT=included.inp\n");
  std::string error;
  const std::optional<ParameterDeck> copy = ParameterDeck::prepare(deck, {"k"}, &error);
  ASSERT_TRUE(copy) << error;
  EXPECT_EQ(copy->values(), (std::vector<double>{2.0}));
  EXPECT_EQ(copy->positions(), (std::vector<std::string>{deck + ":3:1"}));
  EXPECT_EQ(copy->text({0.125}),
            fmt::format("*PARAMETER\nk = 1.0  # first\nk = 0.125\nr = 2*k\nname = 'x'\n"
                        "*INCLUDE, INPUT={}\n",
                        (dir_ / "included.inp").string()));
  EXPECT_FALSE(ParameterDeck::prepare(deck, {"K"}, &error));
  EXPECT_NE(error.find("defines no *PARAMETER 'K' (did you mean 'k'?)"), std::string::npos)
      << error;
  EXPECT_FALSE(ParameterDeck::prepare(deck, {"name"}, &error));
  EXPECT_NE(error.find(deck + ":5:1: error: --vary name: the parameter is not a number"),
            std::string::npos)
      << error;
}

}  // namespace
}  // namespace clinch
