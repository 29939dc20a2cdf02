#include "src/solver/time_stepper.hpp"

#include "src/solver/static_time_stepper.hpp"

namespace clinch {

std::unique_ptr<TimeStepper> time_stepper_for(const Step& step) {
  return std::make_unique<StaticTimeStepper>(StaticTimeSettings::of(
      step.procedure.value_or(StaticProcedure{}), step.max_increments, step.controls.time));
}

}  // namespace clinch
