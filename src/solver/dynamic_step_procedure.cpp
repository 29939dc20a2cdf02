#include "src/solver/dynamic_step_procedure.hpp"

#include <fmt/format.h>

namespace clinch {

std::optional<HalfIncrementTolerance> HalfIncrementTolerance::of(
    const DynamicProcedure& procedure) {
  using Application = DynamicProcedure::Application;
  if (procedure.haftol) return HalfIncrementTolerance{procedure.haftol, 0.0};
  switch (procedure.application) {
    case Application::TransientFidelity:
      return HalfIncrementTolerance{std::nullopt, 0.01};
    case Application::ModerateDissipation:
      return HalfIncrementTolerance{std::nullopt, 0.1};
    case Application::QuasiStatic:
      break;
  }
  return std::nullopt;
}

DynamicStepProcedure::DynamicStepProcedure(const Step& step,
                                           const std::vector<double>& output_intervals)
    : settings_(StaticTimeSettings::of(step.procedure.value_or(StaticProcedure{}),
                                       step.max_increments, step.controls.time, output_intervals)),
      rules_{settings_.direct && step.procedure && step.procedure->no_stop, settings_.direct},
      operator_(step.dynamic.value_or(DynamicProcedure{})) {
  if (!settings_.direct) tolerance_ = HalfIncrementTolerance::of(operator_);
  if (tolerance_) settings_.accuracy = AccuracyControls{};
}

std::unique_ptr<TimeStepper> DynamicStepProcedure::time_stepper() const {
  return std::make_unique<StaticTimeStepper>(settings_);
}

void DynamicStepProcedure::begin_increment(StepProblem& problem,
                                           const IncrementTimes& times) const {
  problem.begin_dynamic_increment(times.step_time, times.total_time, times.dt, operator_);
}

IncrementAccuracy DynamicStepProcedure::check_increment(StepProblem& problem,
                                                        const IncrementTimes& times,
                                                        double average_force) const {
  IncrementAccuracy out;
  if (!tolerance_) return out;
  const StepProblem::HalfIncrementResidual r =
      problem.half_increment_residual(times.step_time, times.total_time, times.dt);
  if (!r.error.empty()) {
    // The state halfway cannot be evaluated: the increment is too large to trust.
    out.ratio = settings_.controls.dc;
    out.message = fmt::format("the state halfway through the increment cannot be evaluated ({})",
                              r.error);
    return out;
  }
  const double tolerance = tolerance_->value(average_force);
  // No force anywhere (q̄ = 0): nothing to measure the residual against.
  out.accuracy = tolerance > 0.0 ? r.value / tolerance : 0.0;
  out.message = fmt::format("half-increment residual {:.4g}{} (tolerance {:.4g})", r.value,
                            r.dof.empty() ? "" : " at " + r.dof, tolerance);
  if (out.accuracy > 1.0) out.ratio = settings_.accuracy->da / out.accuracy;
  return out;
}

}  // namespace clinch
