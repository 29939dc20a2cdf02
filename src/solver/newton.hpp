// Newton's method for one increment (ARCHITECTURE.md principle 1): assemble, test, solve,
// update. Time incrementation and cutbacks live in the step driver; Newton only reports what
// happened, iteration by iteration, so the log, the status file and the tests read one record.
#pragma once

#include <string>
#include <vector>

#include "src/linalg/linear_solver.hpp"
#include "src/solver/convergence_criteria.hpp"
#include "src/solver/line_search.hpp"
#include "src/solver/nonlinear_problem.hpp"

namespace clinch {

struct NewtonOptions {
  int max_iterations = 16;          // I_C (keywords.md §16)
  int divergence_check_from = 4;    // I₀: two consecutive residual increases from here on diverge
  bool accept_unconverged = false;  // DIRECT=NO STOP: return the last iterate as converged
  LineSearchControls line_search;   // *CONTROLS, PARAMETERS=LINE SEARCH (off by default)
  // Asked before each factorization: non-null (a signal's name) stops the increment, Interrupted.
  const char* (*stop_requested)() = nullptr;
  // Fixed increments (DIRECT) cannot be cut back: when Newton revisits a state (a cycle, as
  // between stick and slip across a stick band narrower than its steps) it takes half the next
  // correction, which lands between the states of the cycle. With automatic incrementation the
  // attempt fails on the cycle and the increment is cut back instead.
  bool break_cycles = false;
};

enum class NewtonOutcome {
  Converged,
  Diverged,
  TooManyIterations,
  EvaluationFailed,
  SolverFailed,
  Interrupted,  // stop_requested asked to stop; the increment is unfinished
  NonFinite,    // a residual or correction entry is NaN or infinite
};

struct NewtonReport {
  NewtonOutcome outcome = NewtonOutcome::TooManyIterations;
  std::vector<IterationNorms> iterations;  // one record per evaluated state
  std::string message;                     // why it failed
  int failed_equation = -1;   // SolverFailed: the zero pivot; NonFinite: the first such entry
  double linear_seconds = 0;  // wall time in factorize + solve
  int factorizations = 0;
  bool converged() const { return outcome == NewtonOutcome::Converged; }
};

NewtonReport solve_increment(NonlinearProblem& problem, LinearSolver& solver,
                             const ConvergenceCriteria& criteria, const NewtonOptions& options);

}  // namespace clinch
