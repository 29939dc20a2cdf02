// The linear solver Newton sees (ARCHITECTURE.md "Key interfaces"): analyze the sparsity pattern
// once per step structure, factorize every iteration, solve. Numerical trouble (a zero or
// negative pivot, a non-finite entry) is a status naming the equation at fault, so that the
// caller can name the node and dof (connection-types.md §1.1).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>

#include "src/linalg/sparse_matrix.hpp"

namespace clinch {

enum class LinearStatus { Ok, Singular, NotPositiveDefinite, Failure };

const char* to_string(LinearStatus status);

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  // "cholmod", "umfpack", "dense" or "petsc".
  virtual const char* name() const = 0;
  // Symbolic analysis (ordering, elimination tree) of the pattern; values are not read. Once
  // per pattern. A malformed pattern throws std::invalid_argument (a bug of its builder).
  virtual LinearStatus analyze(const SparseMatrix& pattern, std::string* message) = 0;
  // Numeric factorization of a matrix with the analysed pattern, every iteration.
  virtual LinearStatus factorize(const SparseMatrix& k, std::string* message) = 0;
  // Solves with the last successful factorization (calling it without one is a bug and throws
  // std::logic_error). `x` may not alias `b`.
  virtual LinearStatus solve(const Eigen::VectorXd& b, Eigen::VectorXd& x,
                             std::string* message) = 0;
  // Row/column of the zero or negative pivot reported by the last failed factorize, −1 if
  // unknown or if the last factorize succeeded.
  virtual int failed_pivot() const = 0;
  // Relative residual ‖b − Ax‖ ≤ rtol ‖b‖ that later solves need reach, for an inexact Newton
  // method that solves loosely far from the solution. Iterative backends stop there (PETSc CG:
  // 1e-10 until set); direct backends solve to round-off whatever is asked and ignore it.
  virtual void set_relative_tolerance(double /*rtol*/) {}
  // Why an automatic choice took the backend it did, after analyze, for the step's log line;
  // empty when there was no choice to explain.
  virtual std::string choice() const { return {}; }
};

enum class SolverChoice { Automatic, Cholmod, Umfpack, Dense, Petsc };

// Automatic: the PETSc backend under mpirun with several ranks; else CHOLMOD for symmetric
// positive definite systems and UMFPACK for the others (symmetric indefinite KKT systems with
// Lagrange multipliers, connection-types.md §3.8; softening and unsymmetric tangents,
// behaviors.md §7.4), handing over to the PETSc backend where factorizations cost more than
// AMG-preconditioned solves, and from CHOLMOD to UMFPACK when the matrix is found indefinite
// (automatic_solver.hpp). Dense: Cholesky when symmetric and positive definite, LU otherwise.
// Petsc: CG with BoomerAMG when symmetric and positive definite, GMRES with BoomerAMG when
// unsymmetric without multipliers, MUMPS LU otherwise (petsc_solver.hpp), from the plugin
// libclinch_petsc.so (petsc_plugin_loader.hpp); when the plugin cannot be loaded, a solver whose
// every operation fails with the reason. Asking for CHOLMOD on an unsymmetric system throws
// std::invalid_argument.
// `tangent_changes`: the matrix will change at every Newton iteration (the automatic choice
// weighs factorizations against iterative solves from the start).
std::unique_ptr<LinearSolver> make_linear_solver(SolverChoice choice, bool symmetric,
                                                 bool positive_definite,
                                                 bool tangent_changes = false);

}  // namespace clinch
