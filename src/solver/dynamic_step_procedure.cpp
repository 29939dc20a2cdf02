#include "src/solver/dynamic_step_procedure.hpp"

namespace clinch {

DynamicStepProcedure::DynamicStepProcedure(const Step& step)
    : settings_(StaticTimeSettings::of(step.procedure.value_or(StaticProcedure{}),
                                       step.max_increments, step.controls.time)),
      rules_{settings_.direct && step.procedure && step.procedure->no_stop, settings_.direct},
      operator_(step.dynamic.value_or(DynamicProcedure{})) {}

std::unique_ptr<TimeStepper> DynamicStepProcedure::time_stepper() const {
  return std::make_unique<StaticTimeStepper>(settings_);
}

void DynamicStepProcedure::begin_increment(StepProblem& problem,
                                           const IncrementTimes& times) const {
  problem.begin_dynamic_increment(times.step_time, times.total_time, times.dt, operator_);
}

}  // namespace clinch
