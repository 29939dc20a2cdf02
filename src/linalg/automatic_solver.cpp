#include "src/linalg/automatic_solver.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "src/linalg/fill_estimate.hpp"
#include "src/linalg/petsc_plugin_loader.hpp"
#include "src/linalg/umfpack_solver.hpp"

namespace clinch {

AutomaticSolver::AutomaticSolver(bool symmetric, bool positive_definite, bool tangent_changes)
    : symmetric_(symmetric),
      positive_definite_(positive_definite),
      tangent_changes_(tangent_changes) {
  if (symmetric && positive_definite) {
    direct_ = std::make_unique<CholmodSolver>();
  } else {
    direct_ = std::make_unique<UmfpackSolver>();
  }
  active_ = direct_.get();
}

const char* AutomaticSolver::krylov_method() const { return symmetric_ ? "CG" : "GMRES"; }

bool AutomaticSolver::hand_over_to_petsc(const std::string& cost) {
  std::string unavailable;
  if (petsc_plugin(&unavailable) == nullptr) {
    choice_ = fmt::format("{}, but the PETSc backend is unavailable: {}", cost, unavailable);
    hand_over_on_change_ = false;
    return false;
  }
  choice_ = fmt::format("{}, so {} with BoomerAMG solves it", cost, krylov_method());
  other_ = make_petsc_solver(symmetric_, positive_definite_);
  active_ = other_.get();
  direct_.reset();
  first_values_.clear();
  first_values_.shrink_to_fit();
  return true;
}

LinearStatus AutomaticSolver::analyze(const SparseMatrix& pattern, std::string* message) {
  if (active_ != direct_.get()) return active_->analyze(pattern, message);
  hand_over_on_change_ = false;
  first_values_.clear();
  choice_.clear();
  // A KKT system with multipliers needs LU with pivoting: UMFPACK keeps it.
  if (!positive_definite_) return direct_->analyze(pattern, message);
  // An LU of a structurally symmetric matrix costs about twice its Cholesky factorization.
  const double estimate = (symmetric_ ? 1.0 : 2.0) * estimated_cholesky_flops(pattern);
  const double entries = pattern.nonzeros();
  if (estimate >= kAtOnceFlops && estimate >= kAtOnceFlopsPerEntry * entries) {
    const std::string cost =
        std::isinf(estimate)
            ? std::string("its factor would not fit CHOLMOD's 32-bit indices")
            : fmt::format("the AMD ordering predicts {:.3g} flops per factorization", estimate);
    if (hand_over_to_petsc(cost)) return active_->analyze(pattern, message);
  }
  if (tangent_changes_ && estimate >= kOnChangeFlops &&
      estimate >= kOnChangeFlopsPerEntry * entries &&
      hand_over_to_petsc(fmt::format("the tangent changes at every iteration (NLGEOM) and the "
                                     "AMD ordering predicts {:.3g} flops per factorization",
                                     estimate))) {
    return active_->analyze(pattern, message);
  }
  const LinearStatus analyzed = direct_->analyze(pattern, message);
  if (analyzed != LinearStatus::Ok) {
    if (hand_over_to_petsc(fmt::format("{} cannot analyse it ({})", direct_->name(),
                                       message != nullptr ? *message : ""))) {
      return active_->analyze(pattern, message);
    }
    return analyzed;
  }
  if (!choice_.empty()) return analyzed;  // the PETSc backend is unavailable: choice_ says why
  const auto* cholesky = dynamic_cast<const CholmodSolver*>(direct_.get());
  flops_ = cholesky != nullptr ? cholesky->predicted_flops() : estimate;
  hand_over_on_change_ = flops_ >= kOnChangeFlops && flops_ >= kOnChangeFlopsPerEntry * entries;
  const char* predictor = cholesky != nullptr ? "CHOLMOD" : "the AMD ordering";
  const char* method = krylov_method();
  // The step's log line says what the automatic choice will do, and why.
  choice_ = hand_over_on_change_
                ? fmt::format("{} predicts {:.3g} flops per factorization: {} with BoomerAMG "
                              "takes over once the tangent changes (from {:.0e} flops and {:.0f} "
                              "per stored entry)",
                              predictor, flops_, method, kOnChangeFlops, kOnChangeFlopsPerEntry)
                : fmt::format("{} predicts {:.3g} flops per factorization, below the hand-over "
                              "to {} with BoomerAMG ({:.0e} flops and {:.0f} per stored entry "
                              "once the tangent changes)",
                              predictor, flops_, method, kOnChangeFlops, kOnChangeFlopsPerEntry);
  return analyzed;
}

bool AutomaticSolver::tangent_changed(const SparseMatrix& k) {
  if (first_values_.empty()) {
    first_values_ = k.values;
    return false;
  }
  return k.values != first_values_;
}

LinearStatus AutomaticSolver::factorize(const SparseMatrix& k, std::string* message) {
  if (active_ == direct_.get() && hand_over_on_change_ && tangent_changed(k) &&
      hand_over_to_petsc(fmt::format("the tangent changed, and {:.3g} flops per factorization "
                                     "were predicted",
                                     flops_))) {
    const LinearStatus analyzed = active_->analyze(k, message);
    return analyzed == LinearStatus::Ok ? active_->factorize(k, message) : analyzed;
  }
  const LinearStatus status = active_->factorize(k, message);
  if (status != LinearStatus::NotPositiveDefinite || active_ != direct_.get() || !symmetric_) {
    return status;
  }
  other_ = std::make_unique<UmfpackSolver>();
  active_ = other_.get();
  direct_.reset();
  hand_over_on_change_ = false;
  choice_ = "CHOLMOD found the matrix indefinite, so UMFPACK solves it";
  const LinearStatus analyzed = active_->analyze(k, message);
  return analyzed == LinearStatus::Ok ? active_->factorize(k, message) : analyzed;
}

LinearStatus AutomaticSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                    std::string* message) {
  return active_->solve(b, x, message);
}

}  // namespace clinch
