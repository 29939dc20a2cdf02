#include "src/linalg/dense_solver.hpp"

#include <cmath>
#include <stdexcept>

#include "src/linalg/pivot_checks.hpp"

namespace clinch {

LinearStatus DenseSolver::analyze(const SparseMatrix& pattern, std::string*) {
  validate_pattern(pattern);
  n_ = pattern.n;
  nonzeros_ = pattern.nonzeros();
  factorized_ = false;
  failed_pivot_ = -1;
  return LinearStatus::Ok;
}

LinearStatus DenseSolver::factorize(const SparseMatrix& k, std::string* message) {
  if (n_ < 0 || k.n != n_ || k.nonzeros() != nonzeros_) {
    throw std::logic_error("DenseSolver::factorize: matrix does not match the analysed pattern");
  }
  factorized_ = false;
  failed_pivot_ = -1;
  if (const int p = first_non_finite(k); p >= 0) {
    set_message(message, non_finite_message(k, p, name()));
    return LinearStatus::Failure;
  }
  a_.setZero(n_, n_);
  for (int j = 0; j < n_; ++j) {
    for (int p = k.col_ptr[j]; p < k.col_ptr[j + 1]; ++p) {
      const int i = k.row_idx[p];
      a_(i, j) = k.values[p];
      if (k.symmetric_upper) a_(j, i) = k.values[p];
    }
  }
  const LinearStatus status =
      method_ == Method::Cholesky ? factorize_cholesky(message) : factorize_lu(message);
  factorized_ = status == LinearStatus::Ok;
  return status;
}

LinearStatus DenseSolver::fail(LinearStatus status, int pivot, std::string* message) {
  failed_pivot_ = pivot;
  set_message(message, pivot_message(status, pivot, name()));
  return status;
}

LinearStatus DenseSolver::factorize_cholesky(std::string* message) {
  llt_.compute(a_);
  if (llt_.info() == Eigen::Success) {
    // Rounding residue of a singular matrix: L_jj² against A_jj, as for CHOLMOD.
    for (int j = 0; j < n_; ++j) {
      const double l = llt_.matrixLLT()(j, j);
      if (negligible_pivot(l * l, a_(j, j))) return fail(LinearStatus::Singular, j, message);
    }
    return LinearStatus::Ok;
  }
  // Eigen does not say where it stopped: redo the elimination column by column (left-looking,
  // on the lower triangle) up to the first non-positive pivot. Failure path only.
  Eigen::MatrixXd l = a_;
  for (int j = 0; j < n_; ++j) {
    const double pivot = a_(j, j) - l.row(j).head(j).squaredNorm();
    if (pivot <= 0.0 || negligible_pivot(pivot, a_(j, j))) {
      const bool zero_line = a_.row(j).isZero(0.0) && a_.col(j).isZero(0.0);
      return fail(classify_cholesky_failure(pivot, a_(j, j), zero_line), j, message);
    }
    l(j, j) = std::sqrt(pivot);
    const int below = n_ - j - 1;
    l.col(j).tail(below) =
        (a_.col(j).tail(below) - l.bottomLeftCorner(below, j) * l.row(j).head(j).transpose()) /
        l(j, j);
  }
  return fail(LinearStatus::NotPositiveDefinite, -1, message);
}

LinearStatus DenseSolver::factorize_lu(std::string* message) {
  // Row scaling by the largest entry makes the column test of the pivots independent of the
  // units of the equations, as UMFPACK's scaling does.
  row_scale_ = a_.cwiseAbs().rowwise().maxCoeff();
  for (int i = 0; i < n_; ++i) {
    if (row_scale_(i) == 0.0) row_scale_(i) = 1.0;
  }
  a_ = row_scale_.cwiseInverse().asDiagonal() * a_;
  lu_.compute(a_);
  const Eigen::VectorXd column_max = a_.cwiseAbs().colwise().maxCoeff().transpose();
  for (int k = 0; k < n_; ++k) {
    const int column = lu_.permutationQ().indices()(k);
    if (negligible_pivot(lu_.matrixLU()(k, k), column_max(column))) {
      return fail(LinearStatus::Singular, column, message);
    }
  }
  return LinearStatus::Ok;
}

LinearStatus DenseSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, std::string*) {
  if (!factorized_ || b.size() != n_) {
    throw std::logic_error("DenseSolver::solve: no factorization of this size");
  }
  if (method_ == Method::Cholesky) {
    x = llt_.solve(b);
  } else {
    x = lu_.solve(row_scale_.cwiseInverse().asDiagonal() * b);
  }
  return LinearStatus::Ok;
}

}  // namespace clinch
