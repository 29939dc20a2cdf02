// The automatic choice for systems that are expected to be symmetric positive definite: CHOLMOD,
// switching once and for good to UMFPACK when a factorization finds the matrix indefinite (a
// negative spring stiffness, geometric stiffness under compression), so that a run does not stop
// on a system LU can solve. A singular matrix is reported as such by either backend.
#pragma once

#include <memory>

#include "src/linalg/linear_solver.hpp"

namespace clinch {

class FallbackSolver final : public LinearSolver {
 public:
  FallbackSolver();
  const char* name() const override { return active_->name(); }
  LinearStatus analyze(const SparseMatrix& pattern, std::string* message) override;
  LinearStatus factorize(const SparseMatrix& k, std::string* message) override;
  LinearStatus solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, std::string* message) override;
  int failed_pivot() const override { return active_->failed_pivot(); }

 private:
  std::unique_ptr<LinearSolver> cholesky_, lu_;
  LinearSolver* active_;
};

}  // namespace clinch
