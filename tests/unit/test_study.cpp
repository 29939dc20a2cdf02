// `clinch study`: the scaled decks (every step's *STATIC increments and INC scaled, the user's
// text otherwise kept, included files read from where they are) and the error estimates
// (differences from the finest run, observed order, Richardson limit) on tables whose exact
// error is known.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "parser/deck_reader.hpp"
#include "src/output/status_file_reader.hpp"
#include "src/study/convergence_estimate.hpp"
#include "src/study/scaled_deck.hpp"
#include "src/study/study_result.hpp"

namespace clinch {
namespace {

constexpr const char* kDeckHead = R"(*NODE
1, 0., 0., 0.
2, 1., 0., 0.
*ELEMENT, TYPE=CONN3D2, ELSET=E
1, 1, 2
*CONNECTOR SECTION, ELSET=E, BEHAVIOR=B
AXIAL,
*CONNECTOR BEHAVIOR, NAME=B
*CONNECTOR ELASTICITY, COMPONENT=1
100.
*BOUNDARY
1, 1, 6
2, 2, 6
)";

std::string scaled(const std::string& steps, double scale) {
  SourceManager sources;
  DiagnosticSink sink;
  Model model;
  read_deck_text("deck.inp", std::string(kDeckHead) + steps, sources, model, sink);
  EXPECT_FALSE(sink.has_errors());
  std::string error;
  std::optional<ScaledDeck> deck = ScaledDeck::prepare(model, sources, &error);
  EXPECT_TRUE(deck) << error;
  return deck ? deck->text(scale) : std::string();
}

// The text after the deck head.
std::string steps_of(const std::string& text) { return text.substr(std::string(kDeckHead).size()); }

TEST(ScaledDeck, DirectStepScalesTheIncrementAndRaisesInc) {
  const std::string steps =
      "*STEP, NAME=S1\n*STATIC, DIRECT\n0.25, 2.\n*BOUNDARY\n2, 1, 1, 0.1\n*END STEP\n";
  EXPECT_EQ(steps_of(scaled(steps, 1.0)),
            "*STEP, INC=100, NAME=S1\n*STATIC, DIRECT\n0.25, 2.0\n*BOUNDARY\n2, 1, 1, "
            "0.1\n*END STEP\n");
  // 2 / (0.25/64) = 512 increments needed; the default limit 100 scaled is 6400.
  EXPECT_EQ(steps_of(scaled(steps, 1.0 / 64)),
            "*STEP, INC=6400, NAME=S1\n*STATIC, DIRECT\n0.00390625, 2.0\n*BOUNDARY\n2, 1, 1, "
            "0.1\n*END STEP\n");
}

TEST(ScaledDeck, AutomaticStepScalesInitialAndMaximumAndKeepsTheMinimum) {
  const std::string steps =
      "*STEP, INC=40\n*STATIC\n0.1, 1., 1e-4, 0.5\n*BOUNDARY\n2, 1, 1, 0.1\n*END STEP\n";
  EXPECT_EQ(steps_of(scaled(steps, 0.5)),
            "*STEP, INC=80\n*STATIC\n0.05, 1.0, 0.0001, 0.25\n*BOUNDARY\n2, 1, 1, 0.1\n*END "
            "STEP\n");
}

TEST(ScaledDeck, MissingDataLineIsWrittenWithTheDefaults) {
  // Defaults (keywords.md §15): Δt₀ = T = 1, Δt_min = min(Δt₀, 1e-5 T), Δt_max = T.
  const std::string steps = "*STEP\n*STATIC\n*BOUNDARY\n2, 1, 1, 0.1\n*END STEP\n";
  EXPECT_EQ(steps_of(scaled(steps, 0.25)),
            "*STEP, INC=400\n*STATIC\n0.25, 1.0, 1e-05, 0.25\n*BOUNDARY\n2, 1, 1, 0.1\n*END "
            "STEP\n");
}

TEST(ScaledDeck, ScaledDeckReadsItsIncludeFromAnotherDirectory) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "clinch-study-include";
  fs::create_directories(dir / "sub");
  std::ofstream(dir / "sub" / "head.inp") << kDeckHead;
  std::ofstream(dir / "deck.inp")
      << "*INCLUDE, INPUT=sub/head.inp\n*STEP\n*STATIC, DIRECT\n0.5, 1.\n*END STEP\n";
  SourceManager sources;
  DiagnosticSink sink;
  Model model;
  std::string error;
  ASSERT_EQ(read_deck_file((dir / "deck.inp").string(), sources, model, sink, &error),
            ReadStatus::Ok)
      << error;
  std::optional<ScaledDeck> deck = ScaledDeck::prepare(model, sources, &error);
  ASSERT_TRUE(deck) << error;
  const std::string text = deck->text(0.5);
  EXPECT_EQ(text, fmt::format("*INCLUDE, INPUT={}\n*STEP, INC=200\n*STATIC, DIRECT\n0.25, "
                              "1.0\n*END STEP\n",
                              fs::absolute(dir / "sub" / "head.inp").lexically_normal().string()));
  // The copy, elsewhere, reads the same model.
  const fs::path elsewhere = fs::temp_directory_path() / "clinch-study-include-copy.inp";
  std::ofstream(elsewhere) << text;
  SourceManager copy_sources;
  DiagnosticSink copy_sink;
  Model copy;
  ASSERT_EQ(read_deck_file(elsewhere.string(), copy_sources, copy, copy_sink, &error),
            ReadStatus::Ok);
  EXPECT_FALSE(copy_sink.has_errors());
  EXPECT_EQ(copy.history.steps.at(0).procedure->initial_increment, 0.25);
}

TEST(ScaledDeck, StepInsideAnIncludedFileIsRefusedAtItsLine) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "clinch-study-step-include";
  fs::create_directories(dir);
  std::ofstream(dir / "step.inp") << "*STEP\n*STATIC, DIRECT\n0.5, 1.\n*END STEP\n";
  std::ofstream(dir / "deck.inp") << kDeckHead << "*INCLUDE, INPUT=step.inp\n";
  SourceManager sources;
  DiagnosticSink sink;
  Model model;
  std::string error;
  ASSERT_EQ(read_deck_file((dir / "deck.inp").string(), sources, model, sink, &error),
            ReadStatus::Ok);
  EXPECT_FALSE(ScaledDeck::prepare(model, sources, &error));
  EXPECT_NE(error.find("step.inp:1:1: error: this *STEP lies in an included file"),
            std::string::npos)
      << error;
}

// A table with one column v(t) = t + c·h·sin(t) at times 0..4: first-order error c·h·|sin|.
CsvTable first_order_table(double h, double c) {
  CsvTable table;
  table.path = fmt::format("h={}", h);
  table.columns = {"step", "increment", "step_time", "total_time", "V@1", "ZERO@1"};
  for (int i = 0; i <= 4; ++i) {
    const double t = i;
    table.rows.push_back({1, double(i), t, t, t + c * h * std::sin(t), 0.0});
  }
  return table;
}

// Four settings, scales 1, 1/2, 1/4, 1/8, each table made by `table_at(scale)`.
struct Ladder {
  std::vector<CsvTable> tables;
  std::vector<double> scales;
  std::vector<const CsvTable*> pointers;
  template <typename Make>
  explicit Ladder(Make table_at) {
    for (int k = 0; k < 4; ++k) {
      scales.push_back(std::pow(0.5, k));
      tables.push_back(table_at(scales.back()));
    }
    for (const CsvTable& t : tables) pointers.push_back(&t);
  }
  Ladder(const Ladder&) = delete;  // `pointers` point into `tables`
  Ladder& operator=(const Ladder&) = delete;
};

TEST(ConvergenceEstimate, FirstOrderRichardsonRecoversTheExactError) {
  const Ladder ladder([](double h) { return first_order_table(h, 0.3); });
  const std::vector<double>& scales = ladder.scales;
  const std::vector<const CsvTable*>& pointers = ladder.pointers;
  std::string error;
  const std::optional<StudyEstimate> e = estimate_errors(pointers, scales, 2.0, {}, false, &error);
  ASSERT_TRUE(e) << error;
  ASSERT_EQ(e->columns.size(), 2u);
  const ColumnEstimate& v = e->columns[0];
  EXPECT_EQ(v.status, OrderStatus::Observed);
  EXPECT_NEAR(v.order, 1.0, 1e-9);
  // Scale: the largest |v| over runs and times, at t = 4 of the finest run (sin 4 < 0).
  const double scale = 4.0 + 0.3 * 0.125 * std::sin(4.0);
  const double worst_sin = std::abs(std::sin(2.0));  // largest |sin t| at t = 0..4
  for (std::size_t r = 0; r < 4; ++r) {
    EXPECT_NEAR(v.estimated[r], 0.3 * scales[r] * worst_sin / scale, 1e-12) << r;
    EXPECT_NEAR(v.difference[r], 0.3 * (scales[r] - scales[3]) * worst_sin / scale, 1e-12) << r;
  }
  EXPECT_EQ(e->columns[1].status, OrderStatus::ZeroColumn);
  EXPECT_EQ(e->worst_column[0], "V@1");
  EXPECT_FALSE(e->estimate_is_bound[0]);
}

TEST(ConvergenceEstimate, NoOrderWhenDifferencesDoNotShrink) {
  // Differences 0.1, 0.2 between successive runs: growing, no order; the estimate is the
  // difference from the finest run, flagged as a bound.
  std::vector<CsvTable> tables = {first_order_table(1.0, 0.0), first_order_table(1.0, 0.1),
                                  first_order_table(1.0, 0.3)};
  std::vector<const CsvTable*> pointers = {&tables[0], &tables[1], &tables[2]};
  std::string error;
  const std::optional<StudyEstimate> e =
      estimate_errors(pointers, {1.0, 0.5, 0.25}, 2.0, {"V@1"}, false, &error);
  ASSERT_TRUE(e) << error;
  EXPECT_EQ(e->columns[0].status, OrderStatus::NotObserved);
  EXPECT_TRUE(e->estimate_is_bound[0]);
  EXPECT_EQ(e->columns[0].estimated[0], e->columns[0].difference[0]);
  EXPECT_EQ(e->columns[0].estimated[2], 0.0);
}

TEST(ConvergenceEstimate, TooFewRunsAndInterpolatedTimes) {
  CsvTable coarse = first_order_table(1.0, 0.0);
  CsvTable fine = coarse;
  // The finer run has rows between the coarse times; it is compared at the coarse times only.
  fine.rows.clear();
  for (int i = 0; i <= 8; ++i) fine.rows.push_back({1, double(i), i / 2.0, i / 2.0, i / 2.0, 0.0});
  std::string error;
  const std::optional<StudyEstimate> e =
      estimate_errors({&coarse, &fine}, {1.0, 0.5}, 2.0, {"V@1"}, false, &error);
  ASSERT_TRUE(e) << error;
  EXPECT_EQ(e->times.size(), 5u);
  EXPECT_EQ(e->columns[0].status, OrderStatus::TooFewRuns);
  EXPECT_EQ(e->columns[0].difference[0], 0.0);
  EXPECT_EQ(value_at(fine, 3, 4, 1.25), 1.25);
  EXPECT_FALSE(estimate_errors({&coarse}, {1.0}, 2.0, {"W@1"}, false, &error));
  EXPECT_NE(error.find("no column 'W@1'"), std::string::npos);
}

// A driven component: its total moment CTF4 is round-off (1e-9 h, changing with the increment),
// its friction moment CSF4 = 10 + 0.2 h sin t has a first-order error, and a force CTF1 = 1000
// sets the scale of forces and moments together.
CsvTable driven_table(double h) {
  CsvTable table;
  table.columns = {"step", "increment", "step_time", "total_time", "CTF1@1", "CTF4@1", "CSF4@1",
                   "CU4@1"};
  for (int i = 0; i <= 4; ++i) {
    const double t = i;
    table.rows.push_back({1, double(i), t, t, 1000.0, 1e-9 * h * std::cos(t),
                          10.0 + 0.2 * h * std::sin(t), 0.1 * t});
  }
  return table;
}

TEST(ConvergenceEstimate, ErrorsAgainstTheModelsScaleAndRoundOffColumnsLeftOut) {
  const Ladder ladder(driven_table);
  const std::vector<double>& scales = ladder.scales;
  const std::vector<const CsvTable*>& pointers = ladder.pointers;
  std::string error;
  const std::optional<StudyEstimate> e = estimate_errors(pointers, scales, 2.0, {}, false, &error);
  ASSERT_TRUE(e) << error;
  ASSERT_EQ(e->columns.size(), 4u);
  // CTF4: largest 1e-9 against the scale 1000 of forces and moments: left out.
  EXPECT_EQ(e->columns[1].status, OrderStatus::Negligible);
  EXPECT_EQ(e->columns[1].scale, 1000.0);
  // CSF4: error 0.2 h |sin 2| against the force scale 1000, not against its own peak 10.2.
  const ColumnEstimate& friction = e->columns[2];
  EXPECT_EQ(friction.status, OrderStatus::Observed);
  EXPECT_EQ(friction.scale, 1000.0);
  for (std::size_t r = 0; r < 4; ++r) {
    EXPECT_NEAR(friction.estimated[r], 0.2 * scales[r] * std::abs(std::sin(2.0)) / 1000.0, 1e-14)
        << r;
  }
  EXPECT_EQ(e->worst_column[0], "CSF4@1");
  // CU4 is exact: its motion scale is its own 0.4, and every setting agrees.
  EXPECT_EQ(e->columns[3].status, OrderStatus::Agree);
  EXPECT_EQ(e->columns[3].scale, 0.4);
  // Chosen with --columns, the round-off column is estimated, against the model's force scale
  // still: its differences (1e-12 of it at most) are round-off, the settings agree.
  const std::optional<StudyEstimate> kept =
      estimate_errors(pointers, scales, 2.0, {"CTF4@1"}, true, &error);
  ASSERT_TRUE(kept) << error;
  EXPECT_EQ(kept->columns[0].status, OrderStatus::Agree);
  EXPECT_EQ(kept->columns[0].scale, 1000.0);
}

TEST(StudyResult, CheapestSettingBelowTheTolerance) {
  StudyResult result;
  StudyEstimate estimate;
  estimate.worst_estimated = {1e-1, 1e-2, 1e-3};
  result.estimate = estimate;
  for (int i = 0; i < 3; ++i) {
    StudySetting s;
    s.run = i;
    s.status = StatusRecord{};
    s.status->attempts.push_back(IncrementAttempt{.total_iterations = 10 << i});
    result.settings.push_back(s);
  }
  EXPECT_EQ(cheapest_setting(result, 0.05), 1u);
  EXPECT_EQ(cheapest_setting(result, 1.0), 0u);
  EXPECT_FALSE(cheapest_setting(result, 1e-4));
  EXPECT_EQ(scale_text(0.125), "1/8");
  EXPECT_EQ(scale_text(1.0), "1");
}

TEST(StatusFileReader, AttemptsCutbacksAndEnding) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "clinch-study.sta";
  std::ofstream(path)
      << " step   inc  att  cut  equil  total      total time       step time        time inc\n"
         "    1     1    1    U     16     16               0               0               1\n"
         "    1     1    2           3      4            0.25            0.25            0.25\n"
         "FAILED: too many cutbacks (step 1, increment 2, time 0.25)\n";
  std::string error;
  const std::optional<StatusRecord> r = read_status_file(path.string(), &error);
  ASSERT_TRUE(r) << error;
  ASSERT_EQ(r->attempts.size(), 2u);
  EXPECT_TRUE(r->attempts[0].cut_back);
  EXPECT_EQ(r->converged_increments(), 1);
  EXPECT_EQ(r->cutbacks(), 1);
  EXPECT_EQ(r->total_iterations(), 20);
  EXPECT_EQ(r->attempts[1].total_time, 0.25);
  EXPECT_EQ(r->ending, "FAILED: too many cutbacks (step 1, increment 2, time 0.25)");
}

TEST(StatusFileReader, StepNames) {
  // What StatusFile writes: a STEP line before each step's attempts, a name with blanks and a
  // colon kept whole (docs/study-and-report.md, "Abaqus names and step names").
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "clinch-step-names.sta";
  {
    StatusFile sta;
    std::string error;
    ASSERT_TRUE(sta.open(path, &error)) << error;
    ASSERT_TRUE(sta.write_step(1, "Open"));
    ASSERT_TRUE(sta.write_attempt({1, 1, 1, false, 2, 2, 1.0, 1.0, 1.0}));
    ASSERT_TRUE(sta.write_step(2, "Close: slowly"));
    ASSERT_TRUE(sta.write_attempt({2, 1, 1, false, 1, 1, 2.0, 1.0, 1.0}));
    ASSERT_TRUE(sta.write_completed());
  }
  std::string error;
  const std::optional<StatusRecord> r = read_status_file(path.string(), &error);
  ASSERT_TRUE(r) << error;
  EXPECT_EQ(r->attempts.size(), 2u);
  EXPECT_EQ(r->step_names.at(1), "Open");
  EXPECT_EQ(r->step_names.at(2), "Close: slowly");
  EXPECT_EQ(r->ending, "COMPLETED");
  std::ofstream(path) << "header\nSTEP x: bad\n";
  EXPECT_FALSE(read_status_file(path.string(), &error));
  EXPECT_NE(error.find(":2: not a step line"), std::string::npos) << error;
}

}  // namespace
}  // namespace clinch
