// StaticTimeStepper (src/solver/static_time_stepper.hpp) on its own, with no deck and no files:
// the increments it proposes after each kind of attempt, against keywords.md §15–§16 worked by
// hand. Each expected increment is a product of at most a few decimal factors: 1e-15 relative
// covers their rounding.
#include <gtest/gtest.h>

#include <algorithm>

#include "src/solver/static_time_stepper.hpp"

namespace clinch {
namespace {

constexpr double kTol = 1e-15;
using Kind = TimeProposal::Kind;

StaticTimeSettings settings(double initial, double period = 1.0) {
  StaticTimeSettings s;
  s.initial_increment = initial;
  s.period = period;
  return s;
}

AttemptOutcome converged(int iterations) {
  AttemptOutcome o;
  o.iterations = iterations;
  return o;
}

AttemptOutcome failed(AttemptOutcome::Kind kind, std::string reason = "no convergence") {
  AttemptOutcome o;
  o.kind = kind;
  o.reason = std::move(reason);
  return o;
}

TEST(StaticTimeStepper, StartsWithTheInitialIncrementCappedAtThePeriod) {
  StaticTimeStepper a(settings(0.1));
  EXPECT_EQ(a.first().kind, Kind::Attempt);
  StaticTimeStepper b(settings(0.1));
  EXPECT_NEAR(b.first().dt, 0.1, 0.1 * kTol);
  StaticTimeStepper c(settings(5.0, 2.0));
  EXPECT_DOUBLE_EQ(c.first().dt, 2.0);
}

// I_G = 4 iterations or fewer is easy; after two easy increments in a row the increment grows by
// D_D = 1.5, and not beyond the maximum increment.
TEST(StaticTimeStepper, GrowsAfterTwoEasyIncrements) {
  StaticTimeSettings s = settings(0.1, 10.0);
  s.max_increment = 0.2;
  StaticTimeStepper stepper(s);
  stepper.first();
  EXPECT_NEAR(stepper.next(converged(3)).dt, 0.1, 0.1 * kTol);    // one easy increment
  EXPECT_NEAR(stepper.next(converged(4)).dt, 0.15, 0.15 * kTol);  // two: × 1.5
  EXPECT_NEAR(stepper.next(converged(2)).dt, 0.2, 0.2 * kTol);    // 0.225, capped at 0.2
  EXPECT_EQ(stepper.increments(), 3);
  EXPECT_NEAR(stepper.step_time(), 0.35, 0.35 * kTol);
}

// More than I_L = 10 iterations: the next increment is D_B = 0.75 of this one; 5–10 iterations
// keep it and break the run of easy increments.
// With an accuracy measure (AccuracyControls: the half-increment residual of *DYNAMIC), the
// increment grows only after N_S = 3 increments in a row with ε/T < D_H = 0.75, to
// min(D_S/(ε/T), D_M) = min(0.8/(ε/T), 1.25) of the last and no more than D_D allows; an
// inaccurate increment or a cutback restarts the count.
TEST(StaticTimeStepper, GrowsNoMoreThanTheAccuracyAllows) {
  StaticTimeSettings s = settings(0.1, 10.0);
  s.max_increment = 10.0;
  s.accuracy = AccuracyControls{};
  StaticTimeStepper stepper(s);
  stepper.first();
  auto accurate = [](double ratio) {
    AttemptOutcome o = converged(1);
    o.accuracy = ratio;
    return o;
  };
  EXPECT_NEAR(stepper.next(accurate(0.5)).dt, 0.1, 0.1 * kTol);  // one accurate increment
  EXPECT_NEAR(stepper.next(accurate(0.5)).dt, 0.1, 0.1 * kTol);  // two: D_D would grow
  EXPECT_NEAR(stepper.next(accurate(0.8)).dt, 0.1, 0.1 * kTol);  // 0.8 ≥ D_H: count restarts
  EXPECT_NEAR(stepper.next(accurate(0.7)).dt, 0.1, 0.1 * kTol);
  EXPECT_NEAR(stepper.next(accurate(0.7)).dt, 0.1, 0.1 * kTol);
  EXPECT_NEAR(stepper.next(accurate(0.7)).dt, 0.8 / 0.7 * 0.1, 1e-16);         // third: D_S/(ε/T)
  EXPECT_NEAR(stepper.next(accurate(0.1)).dt, 1.25 * 0.8 / 0.7 * 0.1, 1e-16);  // capped by D_M
  AttemptOutcome smaller = failed(AttemptOutcome::Kind::LawAsksSmaller, "half-increment residual");
  smaller.dt_ratio = 0.5;
  EXPECT_NEAR(stepper.next(smaller).dt, 0.5 * 1.25 * 0.8 / 0.7 * 0.1, 1e-16);
  EXPECT_NEAR(stepper.next(accurate(0.1)).dt, 0.5 * 1.25 * 0.8 / 0.7 * 0.1, 1e-16);  // restarts
}

TEST(StaticTimeStepper, ShrinksAfterAHardIncrement) {
  StaticTimeStepper stepper(settings(0.1, 10.0));
  stepper.first();
  EXPECT_NEAR(stepper.next(converged(11)).dt, 0.075, 0.075 * kTol);
  EXPECT_NEAR(stepper.next(converged(1)).dt, 0.075, 0.075 * kTol);
  EXPECT_NEAR(stepper.next(converged(7)).dt, 0.075, 0.075 * kTol);
  EXPECT_NEAR(stepper.next(converged(1)).dt, 0.075, 0.075 * kTol);
}

// A failed attempt is cut back by D_C = 0.5, a diverging one by D_F = 0.25; a cutback also ends
// a run of easy increments.
TEST(StaticTimeStepper, CutsBackAFailedAttempt) {
  StaticTimeStepper stepper(settings(0.4, 10.0));
  stepper.first();
  TimeProposal p = stepper.next(failed(AttemptOutcome::Kind::NotConverged));
  EXPECT_EQ(p.kind, Kind::Attempt);
  EXPECT_TRUE(p.cut_back);
  EXPECT_NEAR(p.dt, 0.2, 0.2 * kTol);
  p = stepper.next(failed(AttemptOutcome::Kind::Diverged));
  EXPECT_NEAR(p.dt, 0.05, 0.05 * kTol);
  EXPECT_EQ(stepper.cutbacks(), 2);
  EXPECT_EQ(stepper.increments(), 0);
  p = stepper.next(converged(1));
  EXPECT_FALSE(p.cut_back);
  EXPECT_NEAR(stepper.step_time(), 0.05, 0.05 * kTol);
  EXPECT_NEAR(p.dt, 0.05, 0.05 * kTol);  // one easy increment only: no growth yet
}

// A law that asks for a ratio below 1 has the increment retried that much smaller; a ratio
// above 1 caps the growth of the next one; an unreliable result keeps it from growing.
TEST(StaticTimeStepper, HonoursTheLawsRequests) {
  StaticTimeStepper stepper(settings(0.4, 10.0));
  stepper.first();
  AttemptOutcome smaller = failed(AttemptOutcome::Kind::LawAsksSmaller, "damage grows fast");
  smaller.dt_ratio = 0.3;
  TimeProposal p = stepper.next(smaller);
  EXPECT_TRUE(p.cut_back);
  EXPECT_NEAR(p.dt, 0.12, 0.12 * kTol);
  stepper.next(converged(1));
  AttemptOutcome capped = converged(1);
  capped.dt_ratio = 1.2;  // growth by D_D = 1.5 capped at 1.2
  EXPECT_NEAR(stepper.next(capped).dt, 0.144, 0.144 * kTol);
  AttemptOutcome doubtful = converged(1);
  doubtful.unreliable = true;
  EXPECT_NEAR(stepper.next(doubtful).dt, 0.144, 0.144 * kTol);
}

// More than I_A = 5 cutbacks of one increment stop the step with the last reason.
TEST(StaticTimeStepper, StopsAfterTooManyCutbacks) {
  StaticTimeSettings s = settings(1.0);
  s.min_increment = 1e-9;
  StaticTimeStepper stepper(s);
  stepper.first();
  TimeProposal p;
  for (int i = 0; i < 5; ++i) {
    p = stepper.next(failed(AttemptOutcome::Kind::NotConverged));
    ASSERT_EQ(p.kind, Kind::Attempt);
  }
  EXPECT_NEAR(p.dt, 1.0 / 32, kTol);
  p = stepper.next(failed(AttemptOutcome::Kind::NotConverged, "no convergence in 16 iterations"));
  EXPECT_EQ(p.kind, Kind::Stop);
  EXPECT_EQ(p.reason, "too many cutbacks (5; last: no convergence in 16 iterations)");
}

// A cutback below the minimum increment stops the step; a singular system's reason stands on its
// own, and the state's note follows.
TEST(StaticTimeStepper, StopsBelowTheMinimumIncrement) {
  StaticTimeSettings s = settings(1.0);
  s.min_increment = 0.3;
  StaticTimeStepper stepper(s);
  stepper.first();
  EXPECT_NEAR(stepper.next(failed(AttemptOutcome::Kind::NotConverged)).dt, 0.5, kTol);
  TimeProposal p = stepper.next(failed(AttemptOutcome::Kind::NotConverged, "r grows"));
  EXPECT_EQ(p.kind, Kind::Stop);
  EXPECT_EQ(p.reason, "time increment 0.25 below the minimum 0.3 (r grows)");

  StaticTimeStepper singular(s);
  singular.first();
  singular.next(failed(AttemptOutcome::Kind::NotConverged));
  AttemptOutcome o =
      failed(AttemptOutcome::Kind::NotConverged, "singular system: DOF u2 of node 2");
  o.reason_stands = true;
  o.note = "after connector element 1 was deleted (damage)";
  EXPECT_EQ(singular.next(o).reason,
            "singular system: DOF u2 of node 2; after connector element 1 was deleted (damage)");
}

// DIRECT keeps the increment whatever the iterations, and stops on the first failure, saying
// why; an evaluation that fails stops it with its own message.
TEST(StaticTimeStepper, DirectKeepsTheIncrementAndStopsCleanly) {
  StaticTimeSettings s = settings(0.25);
  s.direct = true;
  StaticTimeStepper stepper(s);
  stepper.first();
  EXPECT_DOUBLE_EQ(stepper.next(converged(1)).dt, 0.25);
  EXPECT_DOUBLE_EQ(stepper.next(converged(15)).dt, 0.25);
  TimeProposal p = stepper.next(failed(AttemptOutcome::Kind::NotConverged, "r grows"));
  EXPECT_EQ(p.kind, Kind::Stop);
  EXPECT_EQ(p.reason, "no convergence with fixed increments (r grows)");
  EXPECT_EQ(stepper.cutbacks(), 0);

  StaticTimeStepper law(s);
  law.first();
  AttemptOutcome smaller = failed(AttemptOutcome::Kind::LawAsksSmaller, "d grows by 0.9");
  smaller.dt_ratio = 0.5;
  EXPECT_EQ(law.next(smaller).reason,
            "a law asks for a smaller increment than DIRECT allows (d grows by 0.9)");
  StaticTimeStepper evaluation(s);
  evaluation.first();
  EXPECT_EQ(
      evaluation.next(failed(AttemptOutcome::Kind::EvaluationFailed, "element 3: overflow")).reason,
      "element 3: overflow");
}

// The last increment ends exactly at the period: 0.3 + 0.3 + 0.3 leaves 0.1 (up to the rounding
// of the sum), which is taken whole, and the step is then done.
TEST(StaticTimeStepper, HitsTheStepEndExactly) {
  StaticTimeSettings s = settings(0.3);
  s.direct = true;
  StaticTimeStepper stepper(s);
  stepper.first();
  stepper.next(converged(1));
  stepper.next(converged(1));
  const TimeProposal last = stepper.next(converged(1));
  EXPECT_NEAR(last.dt, 0.1, 1e-15);
  EXPECT_FALSE(stepper.at_end());
  EXPECT_EQ(stepper.next(converged(1)).kind, Kind::Done);
  EXPECT_TRUE(stepper.at_end());
  EXPECT_DOUBLE_EQ(stepper.step_time(), 1.0);
  // An increment within 1e-6 of itself of what remains is stretched to it rather than leave a
  // sliver.
  StaticTimeStepper near(settings(1.0 - 1e-10));
  EXPECT_DOUBLE_EQ(near.first().dt, 1.0);
}

TEST(StaticTimeStepper, StopsAtTheIncrementLimit) {
  StaticTimeSettings s = settings(0.1);
  s.max_increments = 2;
  StaticTimeStepper stepper(s);
  stepper.first();
  stepper.next(converged(1));
  const TimeProposal p = stepper.next(converged(1));
  EXPECT_EQ(p.kind, Kind::Stop);
  EXPECT_EQ(p.reason, "too many increments (INC=2)");
}

// TIME INTERVAL (keywords.md §17): an increment that would pass an output time ends there; the next
// resumes at the increment it was shortened from. DIRECT 0.3 with outputs every 0.25 over 1:
// 0.25 (shortened), 0.25 (to 0.5, shortened), 0.25 (to 0.75), 0.25 (to 1). A cutback of a
// shortened attempt cuts what was attempted.
TEST(StaticTimeStepper, EndsIncrementsAtOutputTimes) {
  StaticTimeSettings s = settings(0.3);
  s.direct = true;
  s.output_intervals = {0.25};
  StaticTimeStepper stepper(s);
  EXPECT_NEAR(stepper.first().dt, 0.25, 1e-15);
  EXPECT_NEAR(stepper.next(converged(1)).dt, 0.25, 1e-15);
  EXPECT_EQ(stepper.step_time(), 0.25);  // exactly the output time
  EXPECT_NEAR(stepper.next(converged(1)).dt, 0.25, 1e-15);
  EXPECT_EQ(stepper.step_time(), 0.5);
  stepper.next(converged(1));
  EXPECT_EQ(stepper.next(converged(1)).kind, Kind::Done);
  EXPECT_EQ(stepper.increments(), 4);

  // Automatic: 0.4 is shortened to the output at 0.25; after two easy increments the natural
  // 0.4 grows to 0.6, still shortened to the next output times. A cutback halves the 0.25 tried.
  StaticTimeSettings a = settings(0.4, 2.0);
  a.max_increment = 1.0;
  a.output_intervals = {0.25, 1.0};
  StaticTimeStepper automatic(a);
  EXPECT_NEAR(automatic.first().dt, 0.25, 1e-15);
  EXPECT_NEAR(automatic.next(converged(1)).dt, 0.25, 1e-15);  // 0.4 would pass 0.5
  const TimeProposal cut = automatic.next(failed(AttemptOutcome::Kind::NotConverged));
  EXPECT_TRUE(cut.cut_back);
  EXPECT_NEAR(cut.dt, 0.125, 1e-15);
}

// 3·10⁶ fixed increments of 10⁻⁴: a plain sum drifts from the exact multiples by rounding
// (1.3·10⁻¹⁰ short of 256.5, more than 10⁻⁶ of an increment); each increment still ends at the
// output time it reaches and at the period, with no sliver increment after it.
TEST(StaticTimeStepper, LeavesNoSliverAtOutputTimesAfterLongRuns) {
  StaticTimeSettings s = settings(1e-4, 300.0);
  s.direct = true;
  s.max_increments = 10000000;
  s.output_intervals = {0.5};
  StaticTimeStepper stepper(s);
  double smallest = 1.0;
  for (TimeProposal p = stepper.first(); p.kind == Kind::Attempt; p = stepper.next(converged(1))) {
    smallest = std::min(smallest, p.dt);
  }
  EXPECT_EQ(stepper.increments(), 3000000);
  EXPECT_GT(smallest, 1e-4 * (1 - 1e-6));
  EXPECT_EQ(stepper.step_time(), 300.0);
  // Without output times, 3·10⁶ increments end at the period itself.
  s.output_intervals.clear();
  StaticTimeStepper plain(s);
  smallest = 1.0;
  for (TimeProposal p = plain.first(); p.kind == Kind::Attempt; p = plain.next(converged(1))) {
    smallest = std::min(smallest, p.dt);
  }
  EXPECT_EQ(plain.increments(), 3000000);
  EXPECT_GT(smallest, 1e-4 * (1 - 1e-6));
}

// Where the step would stop, a stepper that may follow the path asks for it instead
// (TimeProposal::FollowPath, docs/riks.md "Inside a *STATIC increment") over the first increment
// tried there, at least the initial one, with the stop's reason; once the path reaches its end,
// that increment is accepted and the next starts at its size. D_C = 0.25 per cutback, I_A = 5:
// 0.1 at 0.2, cut to 0.025, 0.00625, ..., the sixth failure asks for the path over 0.1.
TEST(StaticTimeStepper, FollowsThePathWhereTheStepWouldStop) {
  StaticTimeSettings s = settings(0.1);
  s.follow_path_on_stop = true;
  StaticTimeStepper stepper(s);
  stepper.first();
  stepper.next(converged(3));
  stepper.next(converged(3));  // at 0.2, the next increment 0.15
  TimeProposal p;
  for (int i = 0; i < 6; ++i) p = stepper.next(failed(AttemptOutcome::Kind::NotConverged));
  EXPECT_EQ(p.kind, Kind::FollowPath);
  EXPECT_NEAR(p.dt, 0.15, 0.15 * kTol);  // the first tried at 0.2, above the initial 0.1
  EXPECT_NE(p.reason.find("too many cutbacks"), std::string::npos) << p.reason;
  p = stepper.next(converged(8));
  EXPECT_NEAR(stepper.step_time(), 0.35, 0.35 * kTol);
  EXPECT_EQ(stepper.increments(), 3);
  EXPECT_EQ(p.kind, Kind::Attempt);
  EXPECT_NEAR(p.dt, 0.15, 0.15 * kTol);  // 5–10 iterations: not grown, not cut

  // Under DIRECT: the fixed increment.
  StaticTimeSettings d = settings(0.25);
  d.direct = true;
  d.follow_path_on_stop = true;
  StaticTimeStepper direct(d);
  direct.first();
  p = direct.next(failed(AttemptOutcome::Kind::NotConverged));
  EXPECT_EQ(p.kind, Kind::FollowPath);
  EXPECT_DOUBLE_EQ(p.dt, 0.25);
  direct.next(converged(3));
  EXPECT_DOUBLE_EQ(direct.step_time(), 0.25);
}

}  // namespace
}  // namespace clinch
