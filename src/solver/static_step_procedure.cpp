#include "src/solver/static_step_procedure.hpp"

namespace clinch {

StaticStepProcedure::StaticStepProcedure(const Step& step)
    : settings_(StaticTimeSettings::of(step.procedure.value_or(StaticProcedure{}),
                                       step.max_increments, step.controls.time)),
      extrapolation_(step.extrapolation) {
  const StaticProcedure procedure = step.procedure.value_or(StaticProcedure{});
  rules_.accept_unconverged = procedure.direct && procedure.no_stop;
  rules_.fixed_increments = procedure.direct;
}

std::unique_ptr<TimeStepper> StaticStepProcedure::time_stepper() const {
  return std::make_unique<StaticTimeStepper>(settings_);
}

void StaticStepProcedure::begin_increment(StepProblem& problem, const IncrementTimes& times) const {
  const bool extrapolate = extrapolation_ && times.previous_dt > 0;
  problem.begin_increment(times.step_time, times.total_time, times.dt,
                          extrapolate ? times.dt / times.previous_dt : 0.0);
}

}  // namespace clinch
