#include "src/solver/tangent_check.hpp"

namespace clinch {

JacobianReport check_assembled_tangent(NonlinearProblem& problem, const SparseMatrix& k,
                                       const Eigen::VectorXd& steps, bool symmetric_part) {
  const auto residual = [&problem](int column, double step, Eigen::VectorXd& value) {
    Eigen::VectorXd move = Eigen::VectorXd::Zero(problem.size());
    move[column] = step;
    problem.apply_correction(move);
    value.resize(problem.size());
    const bool ok = problem.evaluate(value, nullptr).ok;
    move[column] = -step;
    problem.apply_correction(move);
    return ok;
  };
  JacobianCheckOptions options;
  options.compare_row = [&steps](int i) { return steps[i] != 0; };
  options.symmetric_part = symmetric_part;
  return check_jacobian(
      residual, problem.size(), steps, [&k](int row, int column) { return entry(k, row, column); },
      options);
}

}  // namespace clinch
