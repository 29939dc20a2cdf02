// The implicit *DYNAMIC procedure (docs/dynamics.md): the Hilber–Hughes–Taylor α operator, or
// backward Euler for APPLICATION=QUASI-STATIC, over fixed increments (DIRECT; automatic
// incrementation by the half-increment residual is refused at the *DYNAMIC line). Its
// increments use the *STATIC time policy with DIRECT (static_time_stepper.hpp): the same
// increment throughout, the last one ending exactly at the period, no cutback. Each increment
// starts from the converged state, with the inertia and rates of the operator.
#pragma once

#include "src/solver/procedure.hpp"
#include "src/solver/static_time_stepper.hpp"

namespace clinch {

class DynamicStepProcedure final : public Procedure {
 public:
  explicit DynamicStepProcedure(const Step& step);

  double period() const override { return settings_.period; }
  std::unique_ptr<TimeStepper> time_stepper() const override;
  IncrementRules increment_rules() const override { return rules_; }
  void begin_increment(StepProblem& problem, const IncrementTimes& times) const override;

 private:
  StaticTimeSettings settings_;
  IncrementRules rules_;
  DynamicProcedure operator_;
};

}  // namespace clinch
