// The automatic choice of the linear solver on one process (make_linear_solver, docs/parallel.md
// "The automatic choice"): a sparse direct backend, CHOLMOD for symmetric positive definite
// systems and UMFPACK for unsymmetric ones, handed over to the PETSc backend (CG or GMRES with
// BoomerAMG) where factorizations cost more than AMG-preconditioned solves, decided from what is
// cheap to know:
// - At analysis, from a fill estimate that orders the pattern once with AMD (fill_estimate.hpp):
//   a factorization predicted at kAtOnceFlops or more, and at kAtOnceFlopsPerEntry per stored
//   entry or more, goes to PETSc at once, without the dearer ordering (METIS) CHOLMOD would try;
//   so does a pattern whose factor would not fit CHOLMOD's 32-bit indices.
// - When the tangent changes at every Newton iteration, so that every iteration factorizes: PETSc
//   takes over when one factorization costs at least kOnChangeFlops and kOnChangeFlopsPerEntry
//   per stored entry (an AMG-preconditioned solve costs a few hundred flops per entry), so that
//   its start is won back over the iterations to come. Known at analysis when the step says so
//   (NLGEOM; the estimate then decides); otherwise the second distinct factorization is the
//   evidence (CHOLMOD's own prediction decides). A linear step keeps its factor.
// Only systems without Lagrange multipliers are handed over (a KKT system needs LU: UMFPACK
// keeps it). When CHOLMOD finds the matrix indefinite (a negative spring stiffness, geometric
// stiffness under compression), UMFPACK takes over for good, so that a run does not stop on a
// system LU can solve (the PETSc backend makes the same switch to MUMPS itself). A singular
// matrix is reported as such by every backend.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "src/linalg/cholmod_solver.hpp"
#include "src/linalg/linear_solver.hpp"

namespace clinch {

inline constexpr double kAtOnceFlops = 2e10;
inline constexpr double kAtOnceFlopsPerEntry = 2000.0;
inline constexpr double kOnChangeFlops = 1e8;
inline constexpr double kOnChangeFlopsPerEntry = 1000.0;

class AutomaticSolver final : public LinearSolver {
 public:
  // `symmetric`, `positive_definite` and `tangent_changes` as for make_linear_solver.
  AutomaticSolver(bool symmetric, bool positive_definite, bool tangent_changes);
  const char* name() const override { return active_->name(); }
  LinearStatus analyze(const SparseMatrix& pattern, std::string* message) override;
  LinearStatus factorize(const SparseMatrix& k, std::string* message) override;
  LinearStatus solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, std::string* message) override;
  int failed_pivot() const override { return active_->failed_pivot(); }
  void set_relative_tolerance(double rtol) override { active_->set_relative_tolerance(rtol); }
  std::string choice() const override { return choice_; }

 private:
  // The Krylov method the PETSc backend runs on this storage: "CG" or "GMRES".
  const char* krylov_method() const;
  // Makes the PETSc backend the active one when its plugin loads; false (and the reason in
  // choice_) when it does not.
  bool hand_over_to_petsc(const std::string& cost);
  // True when `k` differs from the first matrix factorized on this pattern.
  bool tangent_changed(const SparseMatrix& k);

  const bool symmetric_;
  const bool positive_definite_;
  const bool tangent_changes_;
  std::unique_ptr<LinearSolver> direct_;
  std::unique_ptr<LinearSolver> other_;  // PETSc or UMFPACK once the direct backend has handed over
  LinearSolver* active_;
  double flops_ = 0.0;              // of one factorization with the direct backend
  bool hand_over_on_change_ = false;
  std::vector<double> first_values_;  // of the first factorization, while a change is awaited
  std::string choice_;
};

}  // namespace clinch
