// The step driver honours what a law asks of the time step (behaviour contract,
// src/behavior/behavior.hpp): an increment whose law suggests a ratio below 1 is abandoned and
// retried that much smaller, under automatic incrementation; with DIRECT it cannot be, and the
// path inside the increment is followed in smaller steps to its end; a law that suggests a ratio of
// 1, or reports Unreliable, keeps the increment from growing. Each test runs the whole driver on a
// small deck and reads its outputs.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "parser/deck_reader.hpp"
#include "src/assembly/connector_step_problem.hpp"
#include "src/assembly/connector_system.hpp"
#include "src/output/history_columns.hpp"
#include "src/solver/step_driver.hpp"
#include "tests/tangent/contract_test_laws.hpp"
#include "tests/unit/checked_deck.hpp"

namespace clinch {
namespace {

constexpr double kLimit = 0.02;  // the law's largest motion increment

// AXIAL between node 1 (held) and node 2, moved by 0.1 along the axis over a step of period 1
// that starts with one increment of 1 (`procedure` is the *STATIC line and its data).
// `drive` moves it: by default the prescribed motion; a *CLOAD of 100 reaches the same 0.1 on
// the law's stiffness of 1000.
std::string axial_deck(const std::string& procedure,
                       const std::string& drive = "*BOUNDARY\n2, 1, 1, 0.1") {
  return "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*NSET, NSET=N2\n2\n"
         "*ELEMENT, TYPE=CONN3D2, ELSET=C\n1, 1, 2\n*CONNECTOR SECTION, ELSET=C\nAXIAL,\n"
         "*BOUNDARY\n1, 1, 3\n2, 2, 3\n*STEP\n" +
         procedure + "\n" + drive + "\n*OUTPUT, HISTORY\n*NODE OUTPUT, NSET=N2\nU1\n*END STEP\n";
}

struct DriverRun {
  RunResult result;
  std::vector<double> u1;  // U1 of node 2, one value per history row
  std::string status_file;
};

DriverRun run_with_law(const std::string& deck_text, const Behavior& law, const std::string& job,
                       const RunOptions& options = {}) {
  CheckedDeck deck;
  read_deck_text("deck.inp", deck_text, deck.sources, deck.model, deck.sink);
  EXPECT_FALSE(deck.sink.has_errors()) << deck.dump();
  std::string error;
  std::optional<AnalysisPlan> plan = build_analysis_plan(deck.model, &error);
  EXPECT_TRUE(plan) << error;
  DriverRun run;
  if (!plan) return run;
  plan->add_law(0, law);
  ConnectorSystem system(deck.model, *plan);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "clinch-step-driver";
  std::filesystem::create_directories(dir);
  HistoryColumns columns(deck.model, *plan);
  HistoryTable table;
  StatusFile status;
  RunLog log;
  EXPECT_TRUE(table.open(dir / (job + ".csv"), columns.names(), &error)) << error;
  EXPECT_TRUE(status.open(dir / (job + ".sta"), &error)) << error;
  EXPECT_TRUE(log.open(dir / (job + ".log"), &error)) << error;
  Progress progress = Progress::for_stderr(true);
  HistoryRecorder history(columns, table, system);
  RunOutputs outputs(history, status, log, progress);
  ConnectorStepProblem step_problem(deck.model, system);
  const SolverFactory solvers = [](bool symmetric, bool tangent_changes) {
    return make_linear_solver(SolverChoice::Automatic, symmetric, true, tangent_changes);
  };
  run.result = run_analysis(deck.model, system, step_problem, solvers, outputs, options);
  table = HistoryTable{};
  status = StatusFile{};
  std::ifstream csv(dir / (job + ".csv"));
  std::string line;
  std::size_t column = 0;
  while (std::getline(csv, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> fields;
    std::stringstream split(line);
    for (std::string f; std::getline(split, f, ',');) fields.push_back(f);
    if (column == 0) {
      column = static_cast<std::size_t>(std::find(fields.begin(), fields.end(), "U1@2") -
                                        fields.begin());
      EXPECT_LT(column, fields.size()) << line;
      continue;
    }
    if (column < fields.size()) run.u1.push_back(std::stod(fields[column]));
  }
  std::ifstream sta(dir / (job + ".sta"));
  run.status_file.assign(std::istreambuf_iterator<char>(sta), {});
  return run;
}

// Automatic incrementation: the first attempt (Δu = 0.1) is abandoned, and every accepted
// increment moves by at most the limit; the step still ends at U1 = 0.1 exactly.
TEST(StepDriver, CutsBackWhenALawAsksForASmallerIncrement) {
  const IncrementLimitedSpring law(1000.0, kLimit);
  const DriverRun run = run_with_law(axial_deck("*STATIC\n1., 1."), law, "automatic");
  ASSERT_TRUE(run.result.completed) << run.result.reason;
  EXPECT_GE(run.result.cutbacks, 1);
  EXPECT_GE(run.result.increments, 5);  // 0.1 in steps of at most 0.02
  ASSERT_GE(run.u1.size(), 6u);
  for (std::size_t i = 1; i < run.u1.size(); ++i) {
    EXPECT_LE(std::abs(run.u1[i] - run.u1[i - 1]), kLimit * (1 + 1e-12)) << "row " << i;
  }
  EXPECT_DOUBLE_EQ(run.u1.back(), 0.1);
}

// DIRECT under a prescribed motion: the increment cannot be cut back, so the path inside it is
// followed (docs/riks.md "Inside a *STATIC increment") in steps the law accepts, to the
// increment's end: one increment, ending at U1 = 0.1 exactly.
TEST(StepDriver, DirectIncrementationFollowsThePathWhenALawAsksForASmallerIncrement) {
  const IncrementLimitedSpring law(1000.0, kLimit);
  const DriverRun run = run_with_law(axial_deck("*STATIC, DIRECT\n1., 1."), law, "direct");
  ASSERT_TRUE(run.result.completed) << run.result.reason;
  EXPECT_EQ(run.result.increments, 1);
  ASSERT_EQ(run.u1.size(), 2u);
  EXPECT_DOUBLE_EQ(run.u1.back(), 0.1);
}

// DIRECT under a load that keeps rising along the path (a linear law: no limit point): the same.
TEST(StepDriver, DirectIncrementationUnderARisingLoadFollowsThePathToo) {
  const IncrementLimitedSpring law(1000.0, kLimit);
  const DriverRun run =
      run_with_law(axial_deck("*STATIC, DIRECT\n1., 1.", "*CLOAD\n2, 1, 100."), law, "direct-load");
  ASSERT_TRUE(run.result.completed) << run.result.reason;
  EXPECT_EQ(run.result.increments, 1);
  ASSERT_EQ(run.u1.size(), 2u);
  EXPECT_NEAR(run.u1.back(), 0.1, 1e-12);
}

// Automatic incrementation from 0.1 of a step of 1: a linear problem converges in one iteration,
// so after two easy increments the driver grows the increment (keywords.md §16, D_D = 1.5) and
// needs fewer than 10. A law that suggests a ratio of 1, or calls its results Unreliable, holds
// every increment at 0.1: exactly 10, none cut back.
TEST(StepDriver, ALawCanHoldTheIncrementFromGrowing) {
  const IncrementLimitedSpring free_law(1000.0, 1.0);  // never asks for anything here
  const DriverRun grown = run_with_law(axial_deck("*STATIC\n0.1, 1."), free_law, "grown");
  ASSERT_TRUE(grown.result.completed) << grown.result.reason;
  EXPECT_LT(grown.result.increments, 10);
  for (bool unreliable : {false, true}) {
    const GrowthHoldingSpring law(1000.0, unreliable);
    const DriverRun held =
        run_with_law(axial_deck("*STATIC\n0.1, 1."), law, unreliable ? "unreliable" : "ratio-one");
    ASSERT_TRUE(held.result.completed) << held.result.reason;
    EXPECT_EQ(held.result.increments, 10) << (unreliable ? "Unreliable" : "ratio 1");
    EXPECT_EQ(held.result.cutbacks, 0);
    EXPECT_DOUBLE_EQ(held.u1.back(), 0.1);
  }
}

// A stop asked from outside (src/cli/stop_signals.hpp), answered the n-th time the driver asks,
// n = 1..8: before an attempt or before a factorization inside Newton alike, the run stops there,
// says so in the status file, and the history holds every increment before it.
int stop_questions = 0;
constexpr int kStopFromCall = 4;
const char* stop_when_asked_enough() {
  return ++stop_questions >= kStopFromCall ? "SIGTERM" : nullptr;
}

TEST(StepDriver, AStopAskedFromOutsideEndsTheRunWithEveryConvergedIncrement) {
  const IncrementLimitedSpring law(1000.0, 1.0);
  for (int from = 1; from <= 2 * kStopFromCall; ++from) {
    stop_questions = kStopFromCall - from;
    const DriverRun run = run_with_law(axial_deck("*STATIC, DIRECT\n0.1, 1."), law, "stopped",
                                       RunOptions{false, stop_when_asked_enough});
    EXPECT_FALSE(run.result.completed);
    EXPECT_FALSE(run.result.io_error);
    EXPECT_EQ(run.result.reason, "interrupted by SIGTERM");
    // Rows 0 .. increment - 1: the interrupted increment has none.
    EXPECT_EQ(run.u1.size(), static_cast<std::size_t>(run.result.increment)) << from;
    EXPECT_TRUE(run.status_file.ends_with(
        fmt::format("FAILED: interrupted by SIGTERM (step 1, increment {}, time {})\n",
                    run.result.increment, run.result.time)))
        << run.status_file;
  }
}

// A force that overflows beyond U1 = 0.05 fails the attempt (ARCHITECTURE.md principle 8): the
// driver cuts back until it can cut back no further, then stops naming the element; every row of
// the history holds a finite U1 no further than the limit.
TEST(StepDriver, ANonFiniteForceCutsBackAndNeverReachesTheHistory) {
  const OverflowingSpring law(1000.0, 0.05);
  const DriverRun run = run_with_law(axial_deck("*STATIC\n1., 1., 1e-3"), law, "overflow");
  EXPECT_FALSE(run.result.completed);
  EXPECT_GE(run.result.cutbacks, 1);
  EXPECT_NE(run.result.reason.find("connector element 1: a force or output is not finite"),
            std::string::npos)
      << run.result.reason;
  ASSERT_GE(run.u1.size(), 2u);  // the initial row and at least one converged increment
  for (double u : run.u1) {
    EXPECT_TRUE(std::isfinite(u));
    EXPECT_LE(u, 0.05);
  }
}

}  // namespace
}  // namespace clinch
