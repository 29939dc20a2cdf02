// StaticStepProcedure (src/solver/static_step_procedure.hpp) on its own: Newton's increment rules
// for each *STATIC form (keywords.md §15), and what it tells the step problem at the start of an
// increment (the times, and the extrapolation ratio Δt/Δt_prev of *STEP, EXTRAPOLATION=LINEAR,
// none for a step's first increment or under EXTRAPOLATION=NO). The ratios are one division of
// decimal inputs: 1e-15 relative covers their rounding.
#include <gtest/gtest.h>

#include "src/solver/procedure.hpp"
#include "src/solver/static_step_procedure.hpp"

namespace clinch {
namespace {

// Records begin_increment; the other methods are never called by a procedure.
class IncrementRecorder final : public StepProblem {
 public:
  double step_time = -1, total_time = -1, dt = -1, extrapolate_scale = -1;
  bool dynamic = false;

  void begin_dynamic_increment(double s, double t, double d, const DynamicProcedure&) override {
    step_time = s;
    total_time = t;
    dt = d;
    dynamic = true;
  }
  void begin_increment(double s, double t, double d, double scale) override {
    step_time = s;
    total_time = t;
    dt = d;
    extrapolate_scale = scale;
  }
  void begin_step(std::size_t, bool) override {}
  void end_step(double, double) override {}
  bool laws_symmetric() const override { return true; }
  bool has_multipliers() const override { return false; }
  void use_storage(bool) override {}
  ProcedureNeeds procedure_needs() const override { return {}; }
  std::string check_tangent(int, int) override { return {}; }
  void set_load_factor(double) override {}
  void set_increment_fraction(double, double, double) override {}
  bool loads_change(double, double) const override { return false; }
  double nodal_value(std::int32_t, int) const override { return 0.0; }
  void commit() override {}
  void revert() override {}
  bool update_active_set() override { return false; }
  void end_increment() override {}
  std::vector<std::string> release_failed_components() override { return {}; }
  std::vector<std::string> step_summary() const override { return {}; }
  std::vector<std::string> take_events() override { return {}; }
  StepRequest step_request() const override { return {}; }
  std::string describe_failure(const NewtonReport&) const override { return {}; }
  std::string failure_note(int) const override { return {}; }
};

Step static_step(bool direct, bool no_stop, double period = 2.0) {
  Step step;
  StaticProcedure p;
  p.direct = direct;
  p.no_stop = no_stop;
  p.period = period;
  p.initial_increment = 0.5;
  step.procedure = p;
  return step;
}

TEST(StaticStepProcedure, AutomaticIncrementsNeitherAcceptNorFix) {
  const std::unique_ptr<Procedure> procedure = procedure_for(static_step(false, false));
  EXPECT_FALSE(procedure->increment_rules().accept_unconverged);
  EXPECT_FALSE(procedure->increment_rules().fixed_increments);
  EXPECT_EQ(procedure->period(), 2.0);
}

TEST(StaticStepProcedure, DirectFixesTheIncrementAndNoStopAcceptsIt) {
  const IncrementRules direct = procedure_for(static_step(true, false))->increment_rules();
  EXPECT_TRUE(direct.fixed_increments);
  EXPECT_FALSE(direct.accept_unconverged);
  const IncrementRules no_stop = procedure_for(static_step(true, true))->increment_rules();
  EXPECT_TRUE(no_stop.fixed_increments);
  EXPECT_TRUE(no_stop.accept_unconverged);
}

TEST(StaticStepProcedure, AStepWithoutProcedureIsStaticWithItsDefaults) {
  const std::unique_ptr<Procedure> procedure = procedure_for(Step{});
  EXPECT_EQ(procedure->period(), 1.0);
  const TimeProposal first = procedure->time_stepper()->first();
  EXPECT_EQ(first.kind, TimeProposal::Kind::Attempt);
  EXPECT_EQ(first.dt, 1.0);
}

TEST(StaticStepProcedure, EachTimeStepperStartsAtTheStepStart) {
  const std::unique_ptr<Procedure> procedure = procedure_for(static_step(false, false));
  const std::unique_ptr<TimeStepper> used = procedure->time_stepper();
  used->first();
  used->next(AttemptOutcome{});
  const std::unique_ptr<TimeStepper> fresh = procedure->time_stepper();
  EXPECT_EQ(fresh->increments(), 0);
  EXPECT_EQ(fresh->step_time(), 0.0);
  EXPECT_EQ(fresh->first().dt, 0.5);
}

TEST(StaticStepProcedure, ExtrapolatesByTheRatioOfIncrementsAfterTheFirst) {
  const std::unique_ptr<Procedure> procedure = procedure_for(static_step(false, false));
  IncrementRecorder problem;
  procedure->begin_increment(problem, {0.5, 3.5, 0.5, 0.0});
  EXPECT_EQ(problem.extrapolate_scale, 0.0);  // the step's first increment: nothing to extrapolate
  EXPECT_EQ(problem.step_time, 0.5);
  EXPECT_EQ(problem.total_time, 3.5);
  EXPECT_EQ(problem.dt, 0.5);
  procedure->begin_increment(problem, {1.25, 4.25, 0.75, 0.5});
  EXPECT_NEAR(problem.extrapolate_scale, 1.5, 1.5e-15);
  procedure->begin_increment(problem, {1.35, 4.35, 0.1, 0.75});
  EXPECT_NEAR(problem.extrapolate_scale, 0.1 / 0.75, 1e-15 * (0.1 / 0.75));
}

TEST(StaticStepProcedure, ExtrapolationNoStartsEveryIncrementFromTheConvergedState) {
  Step step = static_step(false, false);
  step.extrapolation = false;
  IncrementRecorder problem;
  procedure_for(step)->begin_increment(problem, {1.0, 1.0, 0.5, 0.5});
  EXPECT_EQ(problem.extrapolate_scale, 0.0);
  EXPECT_EQ(problem.dt, 0.5);
}

}  // namespace
}  // namespace clinch
