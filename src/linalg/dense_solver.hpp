// Dense reference backend (Eigen) for tests and tiny systems: Cholesky for symmetric positive
// definite matrices, full-pivoting LU otherwise. It applies the same pivot tests as the sparse
// backends, so that backend parity can be checked on every system (ARCHITECTURE.md, testing
// habit 7).
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "src/linalg/linear_solver.hpp"

namespace clinch {

class DenseSolver final : public LinearSolver {
 public:
  enum class Method { Cholesky, Lu };
  explicit DenseSolver(Method method) : method_(method) {}

  const char* name() const override { return "dense"; }
  LinearStatus analyze(const SparseMatrix& pattern, std::string* message) override;
  LinearStatus factorize(const SparseMatrix& k, std::string* message) override;
  LinearStatus solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, std::string* message) override;
  int failed_pivot() const override { return failed_pivot_; }

 private:
  LinearStatus factorize_cholesky(std::string* message);
  LinearStatus factorize_lu(std::string* message);
  LinearStatus fail(LinearStatus status, int pivot, std::string* message);

  Method method_;
  int n_ = -1;
  int nonzeros_ = 0;
  Eigen::MatrixXd a_;
  Eigen::VectorXd row_scale_;
  Eigen::LLT<Eigen::MatrixXd> llt_;
  Eigen::FullPivLU<Eigen::MatrixXd> lu_;
  bool factorized_ = false;
  int failed_pivot_ = -1;
};

}  // namespace clinch
