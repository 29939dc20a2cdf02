// The *STATIC, RIKS procedure (docs/riks.md): the modified Riks method. The step's values are a
// pattern that the load proportionality factor λ scales, P₀ + λ(P_ref − P₀); λ is an unknown
// beside the state, found with it on a sphere of radius Δl in the scaled load-displacement space
// (arc_length_problem.hpp), and Δl is controlled as the time increment of *STATIC is
// (arc_length_stepper.hpp). Newton solves the bordered system with the step's own solver
// (bordered_solver.hpp).
#pragma once

#include <memory>

#include "src/model/history_model.hpp"
#include "src/solver/arc_length_problem.hpp"
#include "src/solver/arc_length_stepper.hpp"
#include "src/solver/bordered_solver.hpp"
#include "src/solver/procedure.hpp"

namespace clinch {

class RiksProcedure final : public Procedure {
 public:
  explicit RiksProcedure(const Step& step);

  // The period of the step's ramps (the *STATIC period field is not on a Riks data line: 1).
  double period() const override { return 1.0; }
  std::unique_ptr<TimeStepper> time_stepper() const override;
  IncrementRules increment_rules() const override { return {false, procedure_.direct}; }
  void begin_increment(StepProblem& problem, const IncrementTimes& times) const override;
  NonlinearProblem& newton_problem(NonlinearProblem& problem, StepProblem& step) override;
  LinearSolver& newton_solver(LinearSolver& solver) override;
  std::string end_reason() const override;

 private:
  const Step& step_;
  const StaticProcedure& procedure_;
  std::unique_ptr<ArcLengthProblem> path_;
  std::unique_ptr<BorderedSolver> solver_;
  StepProblem* step_problem_ = nullptr;
  mutable ArcLengthStepper* stepper_ = nullptr;  // the last one time_stepper() made
};

}  // namespace clinch
