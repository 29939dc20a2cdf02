#include "src/solver/bordered_solver.hpp"

namespace clinch {

LinearStatus BorderedSolver::factorize(const SparseMatrix& k, std::string* message) {
  whole_ = false;
  const LinearStatus status = solver_.factorize(k, message);
  if (status == LinearStatus::Singular || status == LinearStatus::NotPositiveDefinite) {
    // The predictor continues the last increment without solving anything; the corrections
    // solve the whole bordered matrix, which the constraint makes regular, and so does a held
    // predictor, whose constraint is linear.
    if (path_.predicting() && !path_.holding()) {
      whole_ = true;
      return LinearStatus::Ok;
    }
    return factorize_whole(k, message);
  }
  if (status != LinearStatus::Ok) return status;
  head_ = -path_.load_rate();
  return solver_.solve(head_, tangent_, message);
}

LinearStatus BorderedSolver::factorize_whole(const SparseMatrix& k, std::string* message) {
  if (k.partial()) {
    // A run whose laws can soften holds the whole tangent (whole_tangent_need.hpp); another one
    // meets a singular tangent on a followed path only where its own model is singular.
    if (message) {
      *message =
          "the tangent is singular on the path, and a distributed run that assembles its "
          "tangent by rows cannot solve the bordered matrix whole (run it on one process)";
    }
    return LinearStatus::Singular;
  }
  const int n = k.n;
  if (!whole_solver_ || bordered_.n != n + 1) {
    // Full storage: K's entries by columns (both triangles of upper storage), the row ∂g/∂q
    // under every column, and the column ∂r/∂λ, ∂g/∂λ in full.
    k_full_ = full_pattern(k, false);
    bordered_ = SparseMatrix{};
    bordered_.n = n + 1;
    bordered_.col_ptr.assign(static_cast<std::size_t>(n) + 2, 0);
    for (int j = 0; j < n; ++j) {
      const int count = k_full_.ptr[j + 1] - k_full_.ptr[j] + 1;
      bordered_.col_ptr[j + 1] = bordered_.col_ptr[j] + count;
      for (int p = k_full_.ptr[j]; p < k_full_.ptr[j + 1]; ++p) {
        bordered_.row_idx.push_back(k_full_.idx[static_cast<std::size_t>(p)]);
      }
      bordered_.row_idx.push_back(n);
    }
    for (int i = 0; i <= n; ++i) bordered_.row_idx.push_back(i);
    bordered_.col_ptr[n + 1] = bordered_.col_ptr[n] + n + 1;
    bordered_.values.assign(bordered_.row_idx.size(), 0.0);
    whole_solver_ = make_linear_solver(SolverChoice::Umfpack, false, false);
    const LinearStatus analysed = whole_solver_->analyze(bordered_, message);
    if (analysed != LinearStatus::Ok) return analysed;
  }
  std::size_t at = 0;
  for (int j = 0; j < n; ++j) {
    for (int p = k_full_.ptr[j]; p < k_full_.ptr[j + 1]; ++p) {
      bordered_.values[at++] = k.values[static_cast<std::size_t>(k_full_.source[p])];
    }
    bordered_.values[at++] = path_.constraint_gradient(j);
  }
  const Eigen::VectorXd& rate = path_.load_rate();
  for (int i = 0; i < n; ++i) bordered_.values[at++] = rate[i];
  bordered_.values[at] = path_.constraint_gradient(n);
  whole_ = true;
  return whole_solver_->factorize(bordered_, message);
}

LinearStatus BorderedSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                   std::string* message) {
  if (whole_ && path_.predicting() && !path_.holding()) {
    const Eigen::VectorXd none = Eigen::VectorXd::Zero(b.size() - 1);
    if (path_.correction(b, none, none, x)) return LinearStatus::Ok;
  } else if (whole_) {
    return whole_solver_->solve(b, x, message);
  } else {
    head_ = b.head(b.size() - 1);
    const LinearStatus status = solver_.solve(head_, solution_, message);
    if (status != LinearStatus::Ok) return status;
    if (path_.correction(b, solution_, tangent_, x)) return LinearStatus::Ok;
  }
  if (message) {
    *message =
        "the arc-length constraint does not cut the path's tangent (the bordered "
        "system is singular)";
  }
  return LinearStatus::Singular;
}

}  // namespace clinch
