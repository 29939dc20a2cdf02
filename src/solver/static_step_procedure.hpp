// The *STATIC procedure (keywords.md §15): automatic or DIRECT incrementation
// (static_time_stepper.hpp) over the step period, Newton keeping an increment at the iteration
// limit only under DIRECT=NO STOP, and increments that start from the converged state, with the
// linear extrapolation of the last converged increment unless *STEP, EXTRAPOLATION=NO.
#pragma once

#include "src/solver/procedure.hpp"
#include "src/solver/static_time_stepper.hpp"

namespace clinch {

class StaticStepProcedure final : public Procedure {
 public:
  explicit StaticStepProcedure(const Step& step, const std::vector<double>& output_intervals = {});

  double period() const override { return settings_.period; }
  std::unique_ptr<TimeStepper> time_stepper() const override;
  IncrementRules increment_rules() const override { return rules_; }
  void begin_increment(StepProblem& problem, const IncrementTimes& times) const override;

 private:
  StaticStepProcedure(const Step& step, const StaticProcedure& procedure,
                      const std::vector<double>& output_intervals);

  StaticTimeSettings settings_;
  IncrementRules rules_;
  bool extrapolation_ = true;
};

}  // namespace clinch
