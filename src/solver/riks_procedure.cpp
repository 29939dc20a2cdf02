#include "src/solver/riks_procedure.hpp"

namespace clinch {

RiksProcedure::RiksProcedure(const Step& step) : step_(step), procedure_(*step.procedure) {}

NonlinearProblem& RiksProcedure::newton_problem(NonlinearProblem& problem, StepProblem& step) {
  step_problem_ = &step;
  path_ = std::make_unique<ArcLengthProblem>(problem, step);
  path_->begin_step();
  return *path_;
}

LinearSolver& RiksProcedure::newton_solver(LinearSolver& solver) {
  solver_ = std::make_unique<BorderedSolver>(solver, *path_);
  return *solver_;
}

std::unique_ptr<TimeStepper> RiksProcedure::time_stepper() const {
  auto stepper = std::make_unique<ArcLengthStepper>(procedure_, step_.max_increments,
                                                    step_.controls.time, *path_, *step_problem_);
  stepper_ = stepper.get();
  return stepper;
}

void RiksProcedure::begin_increment(StepProblem& problem, const IncrementTimes& times) const {
  // From the converged state at its λ, without extrapolation: the predictor is the path's.
  problem.begin_increment(path_->load_factor() * period(), times.total_time, times.dt, 0.0);
  path_->begin_increment(times.dt);
}

std::string RiksProcedure::end_reason() const {
  return stepper_ ? stepper_->end_reason() : std::string();
}

}  // namespace clinch
