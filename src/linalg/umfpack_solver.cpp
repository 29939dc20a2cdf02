#include "src/linalg/umfpack_solver.hpp"

#include <fmt/format.h>
#include <umfpack.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "src/linalg/pivot_checks.hpp"

namespace clinch {
namespace {

std::string umfpack_error(const char* stage, int status) {
  return fmt::format("UMFPACK {} failed (status {})", stage, status);
}

}  // namespace

UmfpackSolver::UmfpackSolver() : control_(UMFPACK_CONTROL), info_(UMFPACK_INFO) {
  umfpack_di_defaults(control_.data());
  // The tangents are structurally symmetric (assembled from element blocks), and their diagonal
  // pivots are good ones: the symmetric strategy orders A + Aᵀ with AMD and prefers the diagonal.
  // Left to choose from the pattern alone, UMFPACK takes its unsymmetric strategy (COLAMD), in
  // which the row of a node that thousands of connectors share, held or not, enters every
  // frontal matrix: 8.2 s per factorization instead of 0.35 s on the shared-ground friction
  // lattice with 10⁴ sliders (docs/benchmarks.md "Connector friction").
  control_[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_SYMMETRIC;
}

UmfpackSolver::~UmfpackSolver() {
  release_numeric();
  release_symbolic();
}

void UmfpackSolver::release_numeric() {
  if (numeric_ != nullptr) umfpack_di_free_numeric(&numeric_);
  factorized_ = false;
}

void UmfpackSolver::release_symbolic() {
  if (symbolic_ != nullptr) umfpack_di_free_symbolic(&symbolic_);
}

LinearStatus UmfpackSolver::analyze(const SparseMatrix& pattern, std::string* message) {
  validate_pattern(pattern);
  release_numeric();
  release_symbolic();
  failed_pivot_ = -1;
  n_ = pattern.n;
  input_nonzeros_ = pattern.nonzeros();
  // Full pattern, compressed by columns, and its gather map.
  FullPattern full = full_pattern(pattern, false);
  col_ptr_ = std::move(full.ptr);
  row_idx_ = std::move(full.idx);
  source_ = std::move(full.source);
  values_.assign(row_idx_.size(), 0.0);
  col_perm_.resize(n_);
  u_diagonal_.resize(n_);
  row_scale_.resize(n_);
  column_max_.resize(n_);
  if (n_ == 0) return LinearStatus::Ok;
  // Values are not read at analysis (null Ax): the ordering depends on the pattern only.
  const int status = umfpack_di_symbolic(n_, n_, col_ptr_.data(), row_idx_.data(), nullptr,
                                         &symbolic_, control_.data(), info_.data());
  if (status != UMFPACK_OK) {
    n_ = -1;
    set_message(message, umfpack_error("symbolic analysis", status));
    return LinearStatus::Failure;
  }
  return LinearStatus::Ok;
}

LinearStatus UmfpackSolver::factorize(const SparseMatrix& k, std::string* message) {
  if (n_ < 0 || k.n != n_ || k.nonzeros() != input_nonzeros_) {
    throw std::logic_error("UmfpackSolver::factorize: matrix does not match the analysed pattern");
  }
  release_numeric();
  failed_pivot_ = -1;
  if (n_ == 0) {
    factorized_ = true;
    return LinearStatus::Ok;
  }
  if (const int p = first_non_finite(k); p >= 0) {
    set_message(message, non_finite_message(k, p, name()));
    return LinearStatus::Failure;
  }
  for (std::size_t p = 0; p < values_.size(); ++p) values_[p] = k.values[source_[p]];
  const int status = umfpack_di_numeric(col_ptr_.data(), row_idx_.data(), values_.data(), symbolic_,
                                        &numeric_, control_.data(), info_.data());
  if (status != UMFPACK_OK && status != UMFPACK_WARNING_singular_matrix) {
    set_message(message, umfpack_error("numeric factorization", status));
    return LinearStatus::Failure;
  }
  // An exactly zero pivot (UMFPACK's warning) and a pivot left by cancellation alike.
  failed_pivot_ = negligible_pivot_column();
  if (status == UMFPACK_WARNING_singular_matrix || failed_pivot_ >= 0) {
    set_message(message, pivot_message(LinearStatus::Singular, failed_pivot_, name()));
    return LinearStatus::Singular;
  }
  factorized_ = true;
  return LinearStatus::Ok;
}

int UmfpackSolver::negligible_pivot_column() {
  int do_recip = 0;
  const int status = umfpack_di_get_numeric(nullptr, nullptr, nullptr, nullptr, nullptr, nullptr,
                                            nullptr, col_perm_.data(), u_diagonal_.data(),
                                            &do_recip, row_scale_.data(), numeric_);
  if (status != UMFPACK_OK) return -1;
  // UMFPACK factors the row-scaled matrix R A (R = diag(Rs) or its inverse), whose columns are
  // in the units of their unknown: the reference for each pivot is the largest entry of its
  // column there.
  std::fill(column_max_.begin(), column_max_.end(), 0.0);
  for (int j = 0; j < n_; ++j) {
    for (int p = col_ptr_[j]; p < col_ptr_[j + 1]; ++p) {
      const double scale = row_scale_[row_idx_[p]];
      const double entry = std::abs(do_recip ? values_[p] * scale : values_[p] / scale);
      column_max_[j] = std::max(column_max_[j], entry);
    }
  }
  for (int k = 0; k < n_; ++k) {
    const int column = col_perm_[k];
    if (negligible_pivot(u_diagonal_[k], column_max_[column])) return column;
  }
  return -1;
}

LinearStatus UmfpackSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                  std::string* message) {
  if (!factorized_ || b.size() != n_) {
    throw std::logic_error("UmfpackSolver::solve: no factorization of this size");
  }
  x.resize(n_);
  if (n_ == 0) return LinearStatus::Ok;
  const int status = umfpack_di_solve(UMFPACK_A, col_ptr_.data(), row_idx_.data(), values_.data(),
                                      x.data(), b.data(), numeric_, control_.data(), info_.data());
  if (status != UMFPACK_OK) {
    set_message(message, umfpack_error("solve", status));
    return LinearStatus::Failure;
  }
  return LinearStatus::Ok;
}

}  // namespace clinch
