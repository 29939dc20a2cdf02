// The automatic choice for systems expected to be symmetric positive definite
// (make_linear_solver): CHOLMOD, with two hand-overs.
// - At analysis: when CHOLMOD's fill-reducing ordering predicts a factorization of at least
//   kIterativeFromFlops flops and kIterativeFromFlopsPerEntry flops per stored entry of the
//   matrix (or cannot analyse it at all: a factor beyond its 32-bit indices), and the PETSc
//   plugin loads, CG with BoomerAMG takes the pattern. A factorization's
//   cost grows much faster than the matrix on 3-D lattices, where an AMG-preconditioned solve
//   costs a few tens of sweeps over the entries; a chain or a set of independent connectors
//   factorizes in a few flops per entry and stays with CHOLMOD. The thresholds are measured
//   (docs/parallel.md "The automatic choice"): below 10¹⁰ flops a factorization takes well under
//   a second and PETSc's start (about 0.5 s) is not won back.
// - At factorization: when CHOLMOD finds the matrix indefinite (a negative spring stiffness,
//   geometric stiffness under compression), UMFPACK takes over for good, so that a run does not
//   stop on a system LU can solve (the PETSc backend makes the same switch to MUMPS itself).
// A singular matrix is reported as such by every backend.
#pragma once

#include <memory>

#include "src/linalg/cholmod_solver.hpp"
#include "src/linalg/linear_solver.hpp"

namespace clinch {

inline constexpr double kIterativeFromFlops = 1e10;
inline constexpr double kIterativeFromFlopsPerEntry = 1000.0;

class AutomaticSpdSolver final : public LinearSolver {
 public:
  AutomaticSpdSolver();
  const char* name() const override { return active_->name(); }
  LinearStatus analyze(const SparseMatrix& pattern, std::string* message) override;
  LinearStatus factorize(const SparseMatrix& k, std::string* message) override;
  LinearStatus solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, std::string* message) override;
  int failed_pivot() const override { return active_->failed_pivot(); }
  void set_relative_tolerance(double rtol) override { active_->set_relative_tolerance(rtol); }
  std::string choice() const override { return choice_; }

 private:
  std::unique_ptr<CholmodSolver> cholesky_;
  std::unique_ptr<LinearSolver> other_;  // PETSc or UMFPACK once CHOLMOD has handed over
  LinearSolver* active_;
  std::string choice_;
};

}  // namespace clinch
