// Sparse LU (UMFPACK) for the systems Cholesky cannot take: symmetric indefinite KKT systems with
// Lagrange multipliers (connection-types.md §3.8), softening and unsymmetric tangents
// (behaviors.md §7.4). Symbolic analysis once per pattern, numeric factorization each iteration.
#pragma once

#include <vector>

#include "src/linalg/linear_solver.hpp"

namespace clinch {

class UmfpackSolver final : public LinearSolver {
 public:
  UmfpackSolver();
  ~UmfpackSolver() override;
  UmfpackSolver(const UmfpackSolver&) = delete;
  UmfpackSolver& operator=(const UmfpackSolver&) = delete;

  const char* name() const override { return "umfpack"; }
  LinearStatus analyze(const SparseMatrix& pattern, std::string* message) override;
  LinearStatus factorize(const SparseMatrix& k, std::string* message) override;
  LinearStatus solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, std::string* message) override;
  int failed_pivot() const override { return failed_pivot_; }

 private:
  void release_numeric();
  void release_symbolic();
  // First pivot column, in pivot order, that is negligible against its column of the row-scaled
  // matrix; −1 if none.
  int negligible_pivot_column();

  std::vector<double> control_, info_;
  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  int n_ = -1;
  int input_nonzeros_ = 0;
  // UMFPACK needs the full matrix: upper storage is expanded once, and `source_[p]` is the index
  // in the caller's values of full entry p, so that factorize only gathers values.
  std::vector<int> col_ptr_, row_idx_, source_;
  std::vector<double> values_;
  // Pivot order and scaling of the last factorization, for the pivot test.
  std::vector<int> col_perm_;
  std::vector<double> u_diagonal_, row_scale_, column_max_;
  bool factorized_ = false;
  int failed_pivot_ = -1;
};

}  // namespace clinch
