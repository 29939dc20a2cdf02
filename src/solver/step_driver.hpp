// The step driver (keywords.md §13–§16): runs every step of the deck through its procedure
// (procedure.hpp: the time stepper, Newton's increment rules, what an increment means), increment
// by increment as the time stepper proposes them; calls Newton for each attempt, settles the active set of stops, passes
// what the laws ask of the time step to the stepper, engages locks on converged increments, and
// tells the outputs (run_outputs.hpp: history, status file, log, progress) of each attempt,
// iteration, note and converged increment; it holds none of their writers. Each step
// assembles a symmetric tangent (CHOLMOD) or a full one (UMFPACK) as its laws and *STEP, UNSYMM
// require. A failure stops the run with the reason, the step, the increment and the time.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "src/linalg/linear_solver.hpp"
#include "src/model/model.hpp"
#include "src/output/run_outputs.hpp"
#include "src/solver/newton.hpp"
#include "src/solver/step_problem.hpp"

namespace clinch {

struct RunOptions {
  bool check_tangent = false;  // compare the tangent with finite differences each increment
  // The name of a signal that asks the run to stop, or nullptr; asked before each attempt and
  // each factorization.
  const char* (*stop_requested)() = nullptr;
};

struct RunResult {
  bool completed = false;
  std::string reason;     // why it stopped
  bool io_error = false;  // it stopped because an output could not be written
  int step = 0, increment = 0;
  double time = 0;
  int increments = 0, iterations = 0, cutbacks = 0;
  int factorizations = 0;
  double linear_seconds = 0;   // wall time in factorize + solve
  double newton_seconds = 0;   // wall time in Newton (evaluation, assembly, factorize, solve)
  double analyze_seconds = 0;  // wall time in the solvers' symbolic analyses
};

// Makes the linear solver of a storage (symmetric: upper triangle; otherwise the full pattern),
// nullptr when the solver the user chose cannot solve it. `tangent_changes`: the step that asks
// first refactorizes at every Newton iteration (NLGEOM), which the automatic choice weighs
// (automatic_solver.hpp).
using SolverFactory =
    std::function<std::unique_ptr<LinearSolver>(bool symmetric, bool tangent_changes)>;

// Runs every step of `model` on `problem` (what Newton solves) and `step_problem` (what the
// driver sets and keeps between solves), the two faces of one analysis.
RunResult run_analysis(const Model& model, NonlinearProblem& problem, StepProblem& step_problem,
                       const SolverFactory& solvers, RunOutputs& outputs,
                       const RunOptions& options);

}  // namespace clinch
