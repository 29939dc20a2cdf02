// The implicit *DYNAMIC procedure (docs/dynamics.md): the Hilber–Hughes–Taylor α operator, or
// backward Euler for APPLICATION=QUASI-STATIC. Its increments use the *STATIC time policy
// (static_time_stepper.hpp): with DIRECT the same increment throughout, the last one ending
// exactly at the period, no cutback; otherwise automatic incrementation, whose increments are
// also held to the half-increment residual (check_increment; docs/dynamics.md "Automatic
// incrementation"). Each increment starts from the converged state, with the inertia and rates
// of the operator.
#pragma once

#include <optional>

#include "src/solver/procedure.hpp"
#include "src/solver/static_time_stepper.hpp"

namespace clinch {

// The half-increment residual tolerance of an automatic *DYNAMIC step: HAFTOL when given, else
// the APPLICATION's default, a fraction of the time-average force q̄ (docs/decisions.md
// "Implicit dynamics"); none for QUASI-STATIC without HAFTOL, whose increments follow the
// convergence of Newton only.
struct HalfIncrementTolerance {
  std::optional<double> absolute;  // HAFTOL
  double of_average_force = 0.0;   // the default: this times q̄
  static std::optional<HalfIncrementTolerance> of(const DynamicProcedure& procedure);
  double value(double average_force) const {
    return absolute ? *absolute : of_average_force * average_force;
  }
};

class DynamicStepProcedure final : public Procedure {
 public:
  explicit DynamicStepProcedure(const Step& step, const std::vector<double>& output_intervals = {});

  double period() const override { return settings_.period; }
  std::unique_ptr<TimeStepper> time_stepper() const override;
  IncrementRules increment_rules() const override { return rules_; }
  void begin_increment(StepProblem& problem, const IncrementTimes& times) const override;
  IncrementAccuracy check_increment(StepProblem& problem, const IncrementTimes& times,
                                    double average_force) const override;

 private:
  StaticTimeSettings settings_;
  IncrementRules rules_;
  DynamicProcedure operator_;
  std::optional<HalfIncrementTolerance> tolerance_;  // none: increments are not checked
};

}  // namespace clinch
