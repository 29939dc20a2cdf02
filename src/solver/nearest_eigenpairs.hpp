// The eigenpairs of K φ = λ M φ nearest a shift σ, as an eigensolver finds them
// (frequency_eigensolver.hpp): Spectra's Lanczos on Fᵀ(K − σM)⁻¹F in one process, SLEPc's
// Krylov–Schur with shift-and-invert in the PETSc plugin (docs/dynamics.md "Natural frequencies").
#pragma once

#include <Eigen/Core>
#include <string>

namespace clinch {

class NearestEigenpairs {
 public:
  virtual ~NearestEigenpairs() = default;
  // The method, for the step's log line.
  virtual std::string name() const = 0;
  // Finds at least `wanted` finite eigenpairs nearest σ (fewer only when the model has fewer);
  // false with the reason in `error`.
  virtual bool find(int wanted, std::string* error) = 0;
  virtual int found() const = 0;
  virtual double eigenvalue(int i) const = 0;
  // φ over the solved equations of the pair i, Mᵀ-normalized up to scale (the caller normalizes).
  virtual Eigen::VectorXd vector(int i) const = 0;
};

}  // namespace clinch
