// AmplitudeFunction (keywords.md §8): TABULAR interpolation with a jump at a repeated time,
// constant values before the first and after the last point, SMOOTH STEP values and its zero
// end slopes, EQUALLY SPACED on the points the reader generates, and the time variable chosen
// by TIME=, and the formulas of PERIODIC, MODULATED and DECAY on either side of their start
// time. Expected values are computed by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "parser/deck_reader.hpp"
#include "parser/diagnostic_render.hpp"
#include "src/solver/amplitude_function.hpp"

namespace clinch {
namespace {

Amplitude make_amplitude(AmplitudeDefinition definition, std::vector<double> times,
                         std::vector<double> values) {
  Amplitude a;
  a.definition = definition;
  a.times = std::move(times);
  a.values = std::move(values);
  return a;
}

// Interpolation of O(1) numbers: a few ulps of rounding. 1e-14 is far below every difference a
// wrong segment or formula would produce (≥ 1e-3 in all the cases below).
constexpr double kTol = 1e-14;

TEST(AmplitudeFunction, TabularInterpolatesLinearly) {
  const AmplitudeFunction f(
      make_amplitude(AmplitudeDefinition::Tabular, {0.5, 1.5, 3.5}, {1.0, 3.0, -1.0}));
  EXPECT_NEAR(f.value_at(1.0), 2.0, kTol);  // halfway 1 → 3
  EXPECT_NEAR(f.value_at(2.0), 2.0, kTol);  // a quarter of 3 → −1
  EXPECT_NEAR(f.value_at(1.5), 3.0, kTol);  // a point
  EXPECT_NEAR(f.value_at(3.0), 0.0, kTol);  // three quarters of 3 → −1
  EXPECT_EQ(f.value_at(0.0), 1.0);          // before t₁: a₁
  EXPECT_EQ(f.value_at(-10.0), 1.0);
  EXPECT_EQ(f.value_at(3.5), -1.0);    // at tₙ
  EXPECT_EQ(f.value_at(100.0), -1.0);  // after tₙ: aₙ
}

TEST(AmplitudeFunction, RepeatedTimeIsAJumpToTheLaterValue) {
  // 0 → 1 over [0, 1], jump to 3 at t = 1, then 3 → 5 over [1, 2].
  const AmplitudeFunction f(
      make_amplitude(AmplitudeDefinition::Tabular, {0.0, 1.0, 1.0, 2.0}, {0.0, 1.0, 3.0, 5.0}));
  EXPECT_NEAR(f.value_at(0.999), 0.999, kTol);
  EXPECT_EQ(f.value_at(1.0), 3.0);
  EXPECT_NEAR(f.value_at(1.5), 4.0, kTol);
  // A jump as the last point: the later value from that time on.
  const AmplitudeFunction end(
      make_amplitude(AmplitudeDefinition::Tabular, {0.0, 1.0, 1.0}, {0.0, 1.0, 7.0}));
  EXPECT_NEAR(end.value_at(0.5), 0.5, kTol);
  EXPECT_EQ(end.value_at(1.0), 7.0);
  EXPECT_EQ(end.value_at(2.0), 7.0);
}

// The formulas hold A0 up to the start time t0; PERIODIC and DECAY start with a jump there
// (their value at t0 is the formula's), MODULATED starts continuously (sin 0 = 0).
TEST(AmplitudeFunction, FormulasHoldTheInitialValueBeforeTheirStart) {
  Amplitude periodic = make_amplitude(AmplitudeDefinition::Periodic, {}, {});
  periodic.formula = {.start_time = 1.0, .initial = 0.5, .omega = 2.0, .cosines = {1.0, 0.25},
                      .sines = {-1.0, 0.0}};
  const AmplitudeFunction p(periodic);
  EXPECT_EQ(p.value_at(0.999), 0.5);
  EXPECT_NEAR(p.value_at(1.0), 0.5 + 1.0 + 0.25, kTol);  // every cosine is 1 at t0
  // t − t0 = π/4: cos(π/2) = 0, sin(π/2) = 1, cos(π) = −1.
  EXPECT_NEAR(p.value_at(1.0 + 0.25 * std::numbers::pi), 0.5 - 1.0 - 0.25, kTol);

  Amplitude modulated = make_amplitude(AmplitudeDefinition::Modulated, {}, {});
  modulated.formula = {.start_time = 0.5, .initial = 2.0, .magnitude = 3.0, .omega = 1.0,
                       .omega2 = 0.5};
  const AmplitudeFunction m(modulated);
  EXPECT_EQ(m.value_at(0.5), 2.0);
  // t − t0 = π: sin(π)·sin(π/2) = 0; t − t0 = π/2: sin(π/2)·sin(π/4) = √2/2.
  EXPECT_NEAR(m.value_at(0.5 + 0.5 * std::numbers::pi), 2.0 + 3.0 * std::sqrt(0.5), kTol);

  Amplitude decay = make_amplitude(AmplitudeDefinition::Decay, {}, {});
  decay.formula = {.start_time = 1.0, .initial = 1.0, .magnitude = -2.0, .decay_time = 0.5};
  const AmplitudeFunction d(decay);
  EXPECT_EQ(d.value_at(0.5), 1.0);
  EXPECT_EQ(d.value_at(1.0), -1.0);
  EXPECT_NEAR(d.value_at(1.5), 1.0 - 2.0 * std::exp(-1.0), kTol);
}

TEST(AmplitudeFunction, SinglePointIsConstant) {
  const AmplitudeFunction f(make_amplitude(AmplitudeDefinition::Tabular, {1.0}, {2.5}));
  EXPECT_EQ(f.value_at(0.0), 2.5);
  EXPECT_EQ(f.value_at(1.0), 2.5);
  EXPECT_EQ(f.value_at(4.0), 2.5);
}

TEST(AmplitudeFunction, SmoothStepValues) {
  const AmplitudeFunction f(
      make_amplitude(AmplitudeDefinition::SmoothStep, {0.0, 2.0, 4.0}, {0.0, 1.0, 3.0}));
  EXPECT_NEAR(f.value_at(1.0), 0.5, kTol);  // ξ = 0.5: ξ³(10 − 15ξ + 6ξ²) = 0.5
  // ξ = 0.25: 0.25³ · (10 − 3.75 + 0.375) = 0.015625 · 6.625 = 0.103515625
  EXPECT_NEAR(f.value_at(0.5), 0.103515625, kTol);
  // Second interval, ξ = 0.75: 1 + 2 · (1 − 0.103515625) by the symmetry of the step.
  EXPECT_NEAR(f.value_at(3.5), 1.0 + 2.0 * 0.896484375, kTol);
  EXPECT_EQ(f.value_at(2.0), 1.0);
  EXPECT_EQ(f.value_at(-1.0), 0.0);
  EXPECT_EQ(f.value_at(5.0), 3.0);
}

TEST(AmplitudeFunction, SmoothStepHasZeroEndSlopes) {
  const AmplitudeFunction f(
      make_amplitude(AmplitudeDefinition::SmoothStep, {0.0, 2.0, 4.0}, {0.0, 1.0, 3.0}));
  auto slope = [&](double t, double h) {
    return (f.value_at(t + h) - f.value_at(t - h)) / (2 * h);
  };
  // Near an end the step grows like 10 ξ³, so the central difference there is O(h²/T³) ≈ 1e-8
  // for h = 1e-4; a linear ramp would give 0.5 or 1. The bound 1e-6 separates the two widely.
  const double h = 1e-4;
  for (double t : {0.0, 2.0, 4.0}) EXPECT_NEAR(slope(t, h), 0.0, 1e-6) << "t = " << t;
  // Mid-interval slope: da · 30 ξ²(1 − ξ)² / T = 1 · 30/16 / 2 = 0.9375. The central-difference
  // error is h² f'''/6 with |f'''| ≤ 60 da / T³ = 7.5: below 2e-8; allow 1e-6.
  EXPECT_NEAR(slope(1.0, h), 0.9375, 1e-6);
}

TEST(AmplitudeFunction, TimeVariableFollowsTheTimeParameter) {
  Amplitude a = make_amplitude(AmplitudeDefinition::Tabular, {0.0, 10.0}, {0.0, 1.0});
  EXPECT_NEAR(AmplitudeFunction(a).value(2.0, 7.0), 0.2, kTol);  // STEP TIME
  a.total_time = true;
  EXPECT_NEAR(AmplitudeFunction(a).value(2.0, 7.0), 0.7, kTol);  // TOTAL TIME
}

TEST(AmplitudeFunction, RejectsAmplitudesWithoutValidData) {
  EXPECT_THROW(AmplitudeFunction(make_amplitude(AmplitudeDefinition::Tabular, {}, {})),
               std::invalid_argument);
  Amplitude invalid = make_amplitude(AmplitudeDefinition::Tabular, {0.0}, {1.0});
  invalid.valid = false;
  EXPECT_THROW(AmplitudeFunction{invalid}, std::invalid_argument);
}

// EQUALLY SPACED relies on the reader to generate the times BEGIN + (i − 1)·FIXED INTERVAL (and
// to apply SCALEX afterwards); TABULAR jumps rely on it accepting a repeated time.
TEST(AmplitudeFunction, ReaderGeneratesEquallySpacedPointsAndKeepsJumps) {
  SourceManager sources;
  Model model;
  DiagnosticSink sink;
  read_deck_text("deck.inp",
                 "*AMPLITUDE, NAME=EQ, DEFINITION=EQUALLY SPACED, FIXED INTERVAL=0.5, BEGIN=1.\n"
                 "0., 2., 4.\n"
                 "*AMPLITUDE, NAME=JUMP\n"
                 "0., 0., 1., 1., 1., 3., 2., 5.\n"
                 "*AMPLITUDE, NAME=SCALED, DEFINITION=EQUALLY SPACED, FIXED INTERVAL=1., "
                 "SCALEX=2.\n"
                 "0., 1.\n"
                 "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n"
                 "*ELEMENT, TYPE=SPRINGA, ELSET=S\n1, 1, 2\n*SPRING, ELSET=S\n\n10.\n"
                 "*BOUNDARY\n1, 1, 3\n2, 2, 3\n"
                 "*STEP\n*STATIC\n*CLOAD, AMPLITUDE=EQ\n2, 1, 1.\n"
                 "*CLOAD, AMPLITUDE=JUMP\n2, 1, 1.\n*CLOAD, AMPLITUDE=SCALED\n2, 1, 1.\n"
                 "*END STEP\n",
                 sources, model, sink);
  std::string listing;
  for (const Diagnostic& d : sink.diagnostics()) listing += render_text(d, sources);
  ASSERT_FALSE(sink.has_errors()) << listing;
  const auto& amplitudes = model.history.amplitudes;
  ASSERT_EQ(amplitudes.size(), 3u);

  const AmplitudeFunction eq(amplitudes[0]);  // points (1, 0), (1.5, 2), (2, 4)
  EXPECT_EQ(eq.value_at(0.0), 0.0);
  EXPECT_NEAR(eq.value_at(1.25), 1.0, kTol);
  EXPECT_NEAR(eq.value_at(1.75), 3.0, kTol);
  EXPECT_EQ(eq.value_at(3.0), 4.0);

  const AmplitudeFunction jump(amplitudes[1]);
  EXPECT_NEAR(jump.value_at(0.5), 0.5, kTol);
  EXPECT_EQ(jump.value_at(1.0), 3.0);

  const AmplitudeFunction scaled(amplitudes[2]);  // points (0, 0), (2, 1)
  EXPECT_NEAR(scaled.value_at(1.0), 0.5, kTol);
}

}  // namespace
}  // namespace clinch
