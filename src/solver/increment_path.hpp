// Following the equilibrium path inside one increment of a *STATIC step (docs/riks.md "Inside a
// *STATIC increment"). Where no increment at a point of the step converges (a snap-back under
// displacement control: past the peak of a softening connector in series with a softer spring,
// the driven motion no longer determines the state, and the equilibrium at the increment's end
// lies on a far branch that Newton cannot reach from the near one; or a model of several
// connectors whose Newton fails together where each alone converges), the step's values are ramped
// from the increment's start to its end by a parameter λ (time t₀ + λ Δt) and the path is
// followed in λ by the arc-length method of a Riks step (arc_length_problem.hpp): λ may fall
// and rise again through the snap-back. Once a point passes λ = 1, the increment's end is solved
// directly from the point before it. The points on the way are committed (the laws' history
// follows the path) but are not increments of the step: only the end is.
#pragma once

#include <functional>
#include <string>

#include "src/linalg/linear_solver.hpp"
#include "src/model/history_model.hpp"
#include "src/solver/newton.hpp"
#include "src/solver/nonlinear_problem.hpp"
#include "src/solver/step_problem.hpp"
#include "src/solver/time_stepper.hpp"

namespace clinch {

// The increment: it starts at `step_time` of the step (`total_time` of the analysis) and is `dt`
// long. Where a load changes in it, the path counts only while λ rises: a point where it falls
// is past a limit point under that load, which a static step does not jump (the follower then
// fails, saying so).
struct IncrementSpan {
  double step_time = 0.0;
  double total_time = 0.0;
  double dt = 0.0;
  bool loads_change = false;
};

struct IncrementPathResult {
  bool converged = false;  // the state at the increment's end, not committed
  int points = 0;          // converged points on the way, committed
  double lowest = 0.0;     // the least λ the path went back to
  std::string reason;      // why it failed
  std::string note;        // under a load that passed a limit point: what the state says of it
  NewtonReport last;       // the solve at the increment's end (or the last failed one)
};

// Solves the current increment on the given problem and solver (the step driver's attempt: Newton
// with the stop active set, its iterations logged) and says how it ended, as the step driver
// tells its stepper (with a law's request for a smaller increment).
struct PathPoint {
  NewtonReport report;
  AttemptOutcome outcome;
};
using IncrementSolve = std::function<PathPoint(NonlinearProblem&, LinearSolver&)>;

IncrementPathResult follow_increment_path(NonlinearProblem& problem, StepProblem& step,
                                          LinearSolver& solver, const IncrementSpan& span,
                                          const TimeIncrementationControls& controls,
                                          const IncrementSolve& solve);

}  // namespace clinch
