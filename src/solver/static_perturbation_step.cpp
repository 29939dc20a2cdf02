#include "src/solver/static_perturbation_step.hpp"

namespace clinch {

PerturbationSolution solve_static_perturbation(NonlinearProblem& problem, StepProblem& step,
                                               LinearSolver& solver, double total_time) {
  PerturbationSolution result;
  const int n = problem.size();
  Eigen::VectorXd base(n), perturbed(n);
  SparseMatrix k = problem.pattern();
  // An increment of no length: no rate, no extrapolation, nothing moves before the evaluations.
  step.begin_increment(0.0, total_time, 0.0, 0.0);
  EvalStatus status = problem.evaluate(base, nullptr);
  if (status.ok) {
    step.begin_increment(1.0, total_time, 0.0, 0.0);
    // With the tangent: the prescribed columns K_fp·Δ enter the residual of the free rows.
    status = problem.evaluate(perturbed, &k);
  }
  step.revert();
  if (!status.ok) {
    result.error = status.message;
    return result;
  }
  std::string message;
  if (solver.factorize(k, &message) != LinearStatus::Ok) {
    result.error = message.empty() ? "the tangent of the base state is singular" : message;
    result.failed_equation = solver.failed_pivot();
    return result;
  }
  const Eigen::VectorXd rhs = base - perturbed;
  if (solver.solve(rhs, result.response, &message) != LinearStatus::Ok) {
    result.error = message;
    return result;
  }
  return result;
}

bool evaluate_perturbed_state(NonlinearProblem& problem, StepProblem& step,
                              const Eigen::VectorXd& response, double tau, double total_time,
                              std::string& error) {
  step.revert();
  step.begin_increment(tau, total_time, 0.0, 0.0);
  problem.apply_correction(tau * response);
  Eigen::VectorXd residual(problem.size());
  const EvalStatus status = problem.evaluate(residual, nullptr);
  if (!status.ok) error = status.message;
  return status.ok;
}

}  // namespace clinch
