#include "src/linalg/fallback_solver.hpp"

#include "src/linalg/cholmod_solver.hpp"
#include "src/linalg/umfpack_solver.hpp"

namespace clinch {

FallbackSolver::FallbackSolver()
    : cholesky_(std::make_unique<CholmodSolver>()), active_(cholesky_.get()) {}

LinearStatus FallbackSolver::analyze(const SparseMatrix& pattern, std::string* message) {
  return active_->analyze(pattern, message);
}

LinearStatus FallbackSolver::factorize(const SparseMatrix& k, std::string* message) {
  const LinearStatus status = active_->factorize(k, message);
  if (status != LinearStatus::NotPositiveDefinite || active_ != cholesky_.get()) return status;
  lu_ = std::make_unique<UmfpackSolver>();
  active_ = lu_.get();
  cholesky_.reset();
  const LinearStatus analyzed = active_->analyze(k, message);
  return analyzed == LinearStatus::Ok ? active_->factorize(k, message) : analyzed;
}

LinearStatus FallbackSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                   std::string* message) {
  return active_->solve(b, x, message);
}

}  // namespace clinch
