#include "src/solver/static_step_procedure.hpp"

namespace clinch {

StaticStepProcedure::StaticStepProcedure(const Step& step,
                                         const std::vector<double>& output_intervals)
    : StaticStepProcedure(step, step.procedure.value_or(StaticProcedure{}), output_intervals) {}

StaticStepProcedure::StaticStepProcedure(const Step& step, const StaticProcedure& procedure,
                                         const std::vector<double>& output_intervals)
    : settings_(StaticTimeSettings::of(procedure, step.max_increments, step.controls.time,
                                       output_intervals)),
      rules_{procedure.direct && procedure.no_stop, procedure.direct},
      extrapolation_(step.extrapolation) {
  settings_.follow_path_on_stop = true;
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
