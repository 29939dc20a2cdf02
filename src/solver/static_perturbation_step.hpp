// A *STATIC step of a *STEP, PERTURBATION (docs/perturbation.md): the linear response δ about
// the base state, the converged state of the general steps before it, which it leaves as it
// found it. K δ = r(0) − r(1), with K the tangent of the base state (the laws at a zero
// increment, as a *FREQUENCY step takes it) and r(τ) the residual there under the step's
// conditions at τ, v_base + τ·Δ: the difference removes what the base state leaves of its own
// residual, and the prescribed rows give δ = Δ on the held DOFs.
#pragma once

#include <string>

#include <Eigen/Core>

#include "src/linalg/linear_solver.hpp"
#include "src/solver/nonlinear_problem.hpp"
#include "src/solver/step_problem.hpp"

namespace clinch {

struct PerturbationSolution {
  Eigen::VectorXd response;  // δ over the solved equations
  std::string error;         // why it could not be solved (empty: success)
  int failed_equation = -1;  // the solved equation of a zero pivot, −1 if none
};

// Solves for δ with `solver` (analysed on problem.pattern() in the step's storage). The caller
// has begun the step; the state is the base state again on return.
PerturbationSolution solve_static_perturbation(NonlinearProblem& problem, StepProblem& step,
                                               LinearSolver& solver, double total_time);

// Puts the state at base + τ·δ under the conditions at τ and evaluates it, so that the outputs
// read the state there; the caller reverts. False (with `error`) when it cannot be evaluated.
bool evaluate_perturbed_state(NonlinearProblem& problem, StepProblem& step,
                              const Eigen::VectorXd& response, double tau, double total_time,
                              std::string& error);

}  // namespace clinch
