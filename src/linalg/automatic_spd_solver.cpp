#include "src/linalg/automatic_spd_solver.hpp"

#include <fmt/format.h>

#include <limits>
#include <string>

#include "src/linalg/petsc_plugin_loader.hpp"
#include "src/linalg/umfpack_solver.hpp"

namespace clinch {

AutomaticSpdSolver::AutomaticSpdSolver()
    : cholesky_(std::make_unique<CholmodSolver>()), active_(cholesky_.get()) {}

LinearStatus AutomaticSpdSolver::analyze(const SparseMatrix& pattern, std::string* message) {
  if (active_ != cholesky_.get()) return active_->analyze(pattern, message);
  const LinearStatus analyzed = cholesky_->analyze(pattern, message);
  // A factor too large for CHOLMOD's 32-bit indices (status CHOLMOD_TOO_LARGE) is the costliest
  // case of all.
  const double flops = analyzed == LinearStatus::Ok
                           ? cholesky_->predicted_flops()
                           : std::numeric_limits<double>::infinity();
  const bool costly = flops >= kIterativeFromFlops &&
                      flops >= kIterativeFromFlopsPerEntry * pattern.nonzeros();
  if (!costly) {
    // The step's log line says why CHOLMOD stays (docs/parallel.md "The automatic choice").
    if (analyzed == LinearStatus::Ok) {
      choice_ = fmt::format("CHOLMOD predicts {:.3g} flops, below the hand-over to CG with "
                            "BoomerAMG ({:.0e} flops and {:.0f} per stored entry)",
                            flops, kIterativeFromFlops, kIterativeFromFlopsPerEntry);
    }
    return analyzed;
  }
  const std::string cost =
      analyzed == LinearStatus::Ok
          ? fmt::format("CHOLMOD predicts {:.3g} flops per factorization", flops)
          : fmt::format("CHOLMOD cannot analyse it ({})", message != nullptr ? *message : "");
  std::string unavailable;
  if (petsc_plugin(&unavailable) == nullptr) {
    choice_ = fmt::format("{}, but the PETSc backend is unavailable: {}", cost, unavailable);
    return analyzed;
  }
  choice_ = fmt::format("{}, so CG with BoomerAMG solves it", cost);
  other_ = make_petsc_solver(true, true);
  active_ = other_.get();
  cholesky_.reset();
  return active_->analyze(pattern, message);
}

LinearStatus AutomaticSpdSolver::factorize(const SparseMatrix& k, std::string* message) {
  const LinearStatus status = active_->factorize(k, message);
  if (status != LinearStatus::NotPositiveDefinite || active_ != cholesky_.get()) return status;
  other_ = std::make_unique<UmfpackSolver>();
  active_ = other_.get();
  cholesky_.reset();
  const LinearStatus analyzed = active_->analyze(k, message);
  return analyzed == LinearStatus::Ok ? active_->factorize(k, message) : analyzed;
}

LinearStatus AutomaticSpdSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                       std::string* message) {
  return active_->solve(b, x, message);
}

}  // namespace clinch
