// The linear solver of a Riks increment (docs/riks.md): the problem's tangent K factorized by the
// step's solver, and the border of the arc-length constraint eliminated around it
// (arc_length_problem.hpp). Each factorization also solves K v = −∂r/∂λ, the tangent of the path
// per unit λ; each solve then costs one more substitution, K a = −r, and a scalar for δλ.
//
// Where K itself is singular while the bordered matrix is not (a perfectly plastic plateau: no
// stiffness along the flow, which the constraint fixes), the elimination cannot be done; the
// whole bordered matrix [K, ∂r/∂λ; ∂g/∂q, ∂g/∂λ] is then assembled in full storage and factorized
// by UMFPACK, its pattern analysed once per step. The predictor needs no factorization there:
// it continues the last increment.
#pragma once

#include <Eigen/Core>
#include <memory>

#include "src/linalg/linear_solver.hpp"
#include "src/linalg/sparse_matrix.hpp"
#include "src/solver/arc_length_problem.hpp"

namespace clinch {

class BorderedSolver final : public LinearSolver {
 public:
  BorderedSolver(LinearSolver& solver, ArcLengthProblem& path) : solver_(solver), path_(path) {}

  const char* name() const override { return solver_.name(); }
  LinearStatus analyze(const SparseMatrix& pattern, std::string* message) override {
    return solver_.analyze(pattern, message);
  }
  LinearStatus factorize(const SparseMatrix& k, std::string* message) override;
  LinearStatus solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, std::string* message) override;
  int failed_pivot() const override { return whole_ ? -1 : solver_.failed_pivot(); }
  void set_relative_tolerance(double rtol) override { solver_.set_relative_tolerance(rtol); }
  std::string choice() const override { return solver_.choice(); }

 private:
  LinearStatus factorize_whole(const SparseMatrix& k, std::string* message);

  LinearSolver& solver_;
  ArcLengthProblem& path_;
  Eigen::VectorXd tangent_;  // v
  Eigen::VectorXd head_, solution_;
  // The whole bordered matrix, used while K is singular.
  bool whole_ = false;
  FullPattern k_full_;
  SparseMatrix bordered_;
  std::unique_ptr<LinearSolver> whole_solver_;
};

}  // namespace clinch
