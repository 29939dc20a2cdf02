// The generalized eigenproblem of a *FREQUENCY step (docs/dynamics.md "Natural frequencies"):
//   K φ = λ M φ,  λ = ω²,
// with K the symmetric tangent stiffness (upper triangle, multipliers included) and M the lumped
// mass, which is positive semi-definite: nodes without mass, multipliers and held DOFs have none.
// M is given by a factor F with M = F Fᵀ, one column per direction that carries mass (r of them).
// With a shift σ, the r × r matrix
//   C = Fᵀ (K − σM)⁻¹ F
// is symmetric and its eigenpairs (ν, z) are those of the problem: λ = σ + 1/ν and
// φ = (K − σM)⁻¹ F z / ν (then Fᵀφ = z). The directions without mass never enter the Krylov space,
// so the infinite eigenvalues of a singular M do not arise; K − σM is factorized once by the
// project's linear solver (CHOLMOD, or UMFPACK when it is indefinite), and Spectra's implicitly
// restarted Lanczos method (SymEigsSolver) finds the ν of largest magnitude: the λ nearest σ.
// When the linear solver is PETSc's (`--solver petsc`, mpirun) and the PETSc plugin was built with
// SLEPc, SLEPc's Krylov–Schur with shift-and-invert (MUMPS) finds them instead
// (src/linalg/slepc_eigensolver.hpp).
#pragma once

#include <Eigen/Core>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "src/linalg/linear_solver.hpp"
#include "src/solver/nearest_eigenpairs.hpp"

namespace clinch {

// One entry of the mass matrix over the solved equations (row ≤ column: the upper triangle of a
// symmetric matrix) and the columns of its factor F.
struct MassEntry {
  int row = 0, column = 0;
  double value = 0;
};
struct LumpedMass {
  std::vector<MassEntry> entries;
  // F column by column: the equations and values of each (one node's block, or the equations a
  // constrained node's block moves with).
  std::vector<std::vector<std::pair<int, double>>> factor;
};

// The eigenvalues wanted: those in [lower, upper], the `count` lowest of them (none: all).
struct EigenRequest {
  double shift = 0;  // σ
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  std::optional<int> count;
};

struct EigenPair {
  double eigenvalue = 0;   // λ = ω²
  Eigen::VectorXd vector;  // φ over the solved equations, Fᵀφ of unit length
};

struct EigenResult {
  std::vector<EigenPair> pairs;  // ascending eigenvalue
  int available = 0;             // r: the number of finite eigenvalues
  std::string error;             // why none could be computed (empty: success)
  int failed_equation = -1;      // the zero pivot of K − σM, when that was why
  std::string eigensolver;       // the method that ran (NearestEigenpairs::name)
};

// Asks `eigensolver` for more eigenpairs nearest σ until every wanted one is among them (those
// within the distance of the farthest found) or all result.available are found; appends them to
// result.pairs, or sets result.error.
void select_nearest(NearestEigenpairs& eigensolver, const EigenRequest& request,
                    EigenResult& result);

// Solves with `solver` already analysed on the pattern of `k`. Asks Spectra for more
// eigenvalues nearest σ until every wanted one is among them (those within the distance of the
// farthest found) or all r are found.
EigenResult solve_frequency_eigenproblem(const SparseMatrix& k, const LumpedMass& mass,
                                         const EigenRequest& request, LinearSolver& solver);

// M x over the solved equations (symmetric, from the upper-triangle entries).
Eigen::VectorXd mass_times(const LumpedMass& mass, const Eigen::VectorXd& x);

}  // namespace clinch
