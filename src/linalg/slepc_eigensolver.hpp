// SLEPc's eigensolver for a *FREQUENCY step run with PETSc (`--solver petsc`, mpirun): the
// generalized Hermitian problem K φ = λ M φ (EPS_GHEP), Krylov–Schur with the shift-and-invert
// spectral transformation (STSINVERT) around σ, K − σM factorized by MUMPS LU (it may be
// indefinite: multipliers, a shift above the lowest eigenvalue). The Krylov space is built with the
// M inner product, so the directions without mass (M singular) never enter it and the infinite
// eigenvalues do not arise; SLEPc's purification (on by default) removes what rounding leaves of
// them from the vectors. Every rank passes the whole matrices and receives the whole vectors, as
// with PetscSolver; each holds its share of the rows.
#pragma once

#include <string>
#include <vector>

#include "src/solver/frequency_eigensolver.hpp"

typedef struct _p_EPS* EPS;
typedef struct _p_Mat* Mat;

namespace clinch {

class SlepcEigensolver final : public NearestEigenpairs {
 public:
  // find() fails only when SLEPc did not converge; fewer pairs than wanted with convergence
  // means the model has no more finite eigenvalues.
  // Throws std::runtime_error when SLEPc cannot start or the matrices cannot be built.
  SlepcEigensolver(const SparseMatrix& k, const LumpedMass& mass, double shift);
  ~SlepcEigensolver() override;
  SlepcEigensolver(const SlepcEigensolver&) = delete;
  SlepcEigensolver& operator=(const SlepcEigensolver&) = delete;

  std::string name() const override;
  bool find(int wanted, std::string* error) override;
  int found() const override { return static_cast<int>(eigenvalues_.size()); }
  double eigenvalue(int i) const override { return eigenvalues_[static_cast<std::size_t>(i)]; }
  Eigen::VectorXd vector(int i) const override { return vectors_[static_cast<std::size_t>(i)]; }

 private:
  int solve(int wanted);

  int n_ = 0;
  double shift_ = 0;
  Mat stiffness_ = nullptr, mass_ = nullptr;
  EPS eps_ = nullptr;
  bool converged_ = false;  // the last EPSSolve's reason was a convergence
  std::string reason_;      // its EPSConvergedReason, for messages
  std::vector<double> eigenvalues_;
  std::vector<Eigen::VectorXd> vectors_;
};

}  // namespace clinch
