// Supernodal sparse Cholesky (CHOLMOD) for symmetric positive definite tangents: the ordering is
// chosen once per pattern (the better of AMD and METIS), the numeric factorization is redone each
// iteration (ARCHITECTURE.md "Performance by design") unless the values are exactly those of the
// factor held (a linear dynamic step over fixed increments: one factorization for the step). A
// matrix that is not positive definite is reported, with its pivot, rather than factored.
#pragma once

#include <cholmod.h>

#include <vector>

#include "src/linalg/linear_solver.hpp"

namespace clinch {

class CholmodSolver final : public LinearSolver {
 public:
  CholmodSolver();
  ~CholmodSolver() override;
  CholmodSolver(const CholmodSolver&) = delete;
  CholmodSolver& operator=(const CholmodSolver&) = delete;

  const char* name() const override { return "cholmod"; }
  LinearStatus analyze(const SparseMatrix& pattern, std::string* message) override;
  LinearStatus factorize(const SparseMatrix& k, std::string* message) override;
  LinearStatus solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, std::string* message) override;
  int failed_pivot() const override { return failed_pivot_; }

  // The fill-reducing orderings the last analyze tried, with the nonzeros and flops of the
  // factor each gives, and the one it kept; for reports, tests and benchmarks.
  struct OrderingTrial {
    const char* ordering;
    double factor_nonzeros;
    double flops;
  };
  std::vector<OrderingTrial> ordering_trials() const;
  const char* ordering() const;
  // Flops of one numeric factorization with the ordering the last analyze kept.
  double predicted_flops() const;

 private:
  void release_factor();
  // Value of the pivot (Schur complement diagonal) at permuted column `minor` of a failed
  // factorization, from the valid columns left of it.
  double failed_schur_pivot(const SparseMatrix& k, int minor) const;

  cholmod_common common_;
  cholmod_factor* factor_ = nullptr;
  cholmod_dense* solution_ = nullptr;
  cholmod_dense* workspace_y_ = nullptr;
  cholmod_dense* workspace_e_ = nullptr;
  int n_ = -1;
  int nonzeros_ = 0;
  std::vector<int> diagonal_;
  std::vector<double> factored_values_;  // the values of the factor held, when factorized_
  bool factorized_ = false;
  int failed_pivot_ = -1;
};

}  // namespace clinch
