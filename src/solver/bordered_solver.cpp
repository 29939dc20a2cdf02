#include "src/solver/bordered_solver.hpp"

namespace clinch {

LinearStatus BorderedSolver::factorize(const SparseMatrix& k, std::string* message) {
  const LinearStatus status = solver_.factorize(k, message);
  if (status != LinearStatus::Ok) return status;
  head_ = -path_.load_rate();
  return solver_.solve(head_, tangent_, message);
}

LinearStatus BorderedSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                   std::string* message) {
  head_ = b.head(b.size() - 1);
  const LinearStatus status = solver_.solve(head_, solution_, message);
  if (status != LinearStatus::Ok) return status;
  if (!path_.correction(b, solution_, tangent_, x)) {
    if (message) {
      *message = "the arc-length constraint does not cut the path's tangent (the bordered "
                 "system is singular)";
    }
    return LinearStatus::Singular;
  }
  return LinearStatus::Ok;
}

}  // namespace clinch
