#include "src/linalg/cholmod_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "src/linalg/cholmod_view.hpp"
#include "src/linalg/pivot_checks.hpp"

namespace clinch {
namespace {

const char* ordering_name(int ordering) {
  switch (ordering) {
    case CHOLMOD_NATURAL:
      return "natural";
    case CHOLMOD_GIVEN:
      return "given";
    case CHOLMOD_AMD:
      return "AMD";
    case CHOLMOD_METIS:
      return "METIS";
    case CHOLMOD_NESDIS:
      return "NESDIS";
    case CHOLMOD_COLAMD:
      return "COLAMD";
    case CHOLMOD_POSTORDERED:
      return "postordered";
    default:
      return "unknown";
  }
}

std::string cholmod_error(const char* stage, int status) {
  return fmt::format("CHOLMOD {} failed (status {})", stage, status);
}

}  // namespace

CholmodSolver::CholmodSolver() {
  cholmod_start(&common_);
  common_.print = 0;  // statuses are returned, not printed
  common_.supernodal = CHOLMOD_SUPERNODAL;
  // Analysis happens once per pattern, so it can afford two orderings; CHOLMOD keeps the one
  // with the sparser factor (AMD usually wins on chains and small models, METIS on 3-D lattices).
  common_.nmethods = 2;
  common_.method[0].ordering = CHOLMOD_AMD;
  common_.method[1].ordering = CHOLMOD_METIS;
  // Keep the columns left of a failed pivot, from which its value is recovered.
  common_.quick_return_if_not_posdef = 0;
}

CholmodSolver::~CholmodSolver() {
  release_factor();
  cholmod_free_dense(&solution_, &common_);
  cholmod_free_dense(&workspace_y_, &common_);
  cholmod_free_dense(&workspace_e_, &common_);
  cholmod_finish(&common_);
}

void CholmodSolver::release_factor() {
  cholmod_free_factor(&factor_, &common_);
  factorized_ = false;
}

LinearStatus CholmodSolver::analyze(const SparseMatrix& pattern, std::string* message) {
  validate_pattern(pattern);
  release_factor();
  failed_pivot_ = -1;
  n_ = pattern.n;
  nonzeros_ = pattern.nonzeros();
  diagonal_ = diagonal_positions(pattern);
  if (n_ == 0) return LinearStatus::Ok;
  cholmod_sparse a = cholmod_view(pattern, CHOLMOD_PATTERN);
  factor_ = cholmod_analyze(&a, &common_);
  if (factor_ == nullptr) {
    n_ = -1;
    set_message(message, cholmod_error("analysis", common_.status));
    return LinearStatus::Failure;
  }
  return LinearStatus::Ok;
}

LinearStatus CholmodSolver::factorize(const SparseMatrix& k, std::string* message) {
  if (n_ < 0 || k.n != n_ || k.nonzeros() != nonzeros_) {
    throw std::logic_error("CholmodSolver::factorize: matrix does not match the analysed pattern");
  }
  // The same values on the same pattern give the same factor, bit for bit: keep it.
  if (factorized_ && k.values == factored_values_) return LinearStatus::Ok;
  factorized_ = false;
  failed_pivot_ = -1;
  if (n_ == 0) {
    factorized_ = true;
    return LinearStatus::Ok;
  }
  if (const int p = first_non_finite(k); p >= 0) {
    set_message(message, non_finite_message(k, p, name()));
    return LinearStatus::Failure;
  }
  cholmod_sparse a = cholmod_view(k, CHOLMOD_REAL);
  cholmod_factorize(&a, factor_, &common_);
  const int* perm = static_cast<const int*>(factor_->Perm);
  const auto diagonal = [&](int column) {
    return diagonal_[column] >= 0 ? k.values[diagonal_[column]] : 0.0;
  };
  if (common_.status == CHOLMOD_NOT_POSDEF) {
    const int minor = static_cast<int>(factor_->minor);
    failed_pivot_ = perm[minor];
    const LinearStatus status =
        classify_cholesky_failure(failed_schur_pivot(k, minor), diagonal(failed_pivot_),
                                  row_and_column_are_zero(k, failed_pivot_));
    set_message(message, pivot_message(status, failed_pivot_, name()));
    return status;
  }
  if (common_.status < CHOLMOD_OK) {
    set_message(message, cholmod_error("factorization", common_.status));
    return LinearStatus::Failure;
  }
  // Positive pivots can still be rounding residue of a singular matrix (a rigid-body mode):
  // compare each squared diagonal of L with the diagonal of A it came from.
  const int* super = static_cast<const int*>(factor_->super);
  const int* pi = static_cast<const int*>(factor_->pi);
  const int* px = static_cast<const int*>(factor_->px);
  const double* lx = static_cast<const double*>(factor_->x);
  for (std::size_t s = 0; s < factor_->nsuper; ++s) {
    const int rows = pi[s + 1] - pi[s];
    for (int j = 0; j < super[s + 1] - super[s]; ++j) {
      const double l = lx[px[s] + j * rows + j];
      const int column = perm[super[s] + j];
      if (negligible_pivot(l * l, diagonal(column))) {
        failed_pivot_ = column;
        set_message(message, pivot_message(LinearStatus::Singular, column, name()));
        return LinearStatus::Singular;
      }
    }
  }
  factored_values_ = k.values;
  factorized_ = true;
  return LinearStatus::Ok;
}

double CholmodSolver::failed_schur_pivot(const SparseMatrix& k, int minor) const {
  // Row `minor` of L left of the diagonal: the supernodes before the failed one are complete,
  // and CHOLMOD refactors the failed one up to the column before `minor`.
  const int* super = static_cast<const int*>(factor_->super);
  const int* pi = static_cast<const int*>(factor_->pi);
  const int* px = static_cast<const int*>(factor_->px);
  const int* ls = static_cast<const int*>(factor_->s);
  const double* lx = static_cast<const double*>(factor_->x);
  double sum = 0.0;
  for (std::size_t s = 0; s < factor_->nsuper && super[s] <= minor; ++s) {
    const int rows = pi[s + 1] - pi[s];
    const int* first = ls + pi[s];
    const int* row = std::find(first, first + rows, minor);
    if (row == first + rows) continue;
    const int r = static_cast<int>(row - first);
    for (int j = 0; j < std::min(super[s + 1], minor) - super[s]; ++j) {
      const double l = lx[px[s] + j * rows + r];
      sum += l * l;
    }
  }
  const int column = static_cast<const int*>(factor_->Perm)[minor];
  const double a = diagonal_[column] >= 0 ? k.values[diagonal_[column]] : 0.0;
  return a - sum;
}

LinearStatus CholmodSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                  std::string* message) {
  if (!factorized_ || b.size() != n_) {
    throw std::logic_error("CholmodSolver::solve: no factorization of this size");
  }
  x.resize(n_);
  if (n_ == 0) return LinearStatus::Ok;
  cholmod_dense rhs{};
  rhs.nrow = rhs.d = rhs.nzmax = static_cast<std::size_t>(n_);
  rhs.ncol = 1;
  rhs.x = const_cast<double*>(b.data());
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  // solve2 keeps the solution and its workspace between calls: no allocation per iteration.
  if (!cholmod_solve2(CHOLMOD_A, factor_, &rhs, nullptr, &solution_, nullptr, &workspace_y_,
                      &workspace_e_, &common_)) {
    set_message(message, cholmod_error("solve", common_.status));
    return LinearStatus::Failure;
  }
  const double* values = static_cast<const double*>(solution_->x);
  std::copy(values, values + n_, x.data());
  return LinearStatus::Ok;
}

std::vector<CholmodSolver::OrderingTrial> CholmodSolver::ordering_trials() const {
  std::vector<OrderingTrial> trials;
  for (int i = 0; i < common_.nmethods; ++i) {
    trials.push_back(
        {ordering_name(common_.method[i].ordering), common_.method[i].lnz, common_.method[i].fl});
  }
  return trials;
}

double CholmodSolver::predicted_flops() const { return common_.fl; }

const char* CholmodSolver::ordering() const {
  return factor_ == nullptr ? "none" : ordering_name(factor_->ordering);
}

}  // namespace clinch
