#include "src/linalg/linear_solver.hpp"

#include <stdexcept>

#include "src/linalg/automatic_solver.hpp"
#include "src/linalg/cholmod_solver.hpp"
#include "src/linalg/dense_solver.hpp"
#include "src/linalg/petsc_plugin_loader.hpp"
#include "src/linalg/umfpack_solver.hpp"
#include "src/parallel/communicator.hpp"

namespace clinch {

const char* to_string(LinearStatus status) {
  switch (status) {
    case LinearStatus::Ok:
      return "ok";
    case LinearStatus::Singular:
      return "singular";
    case LinearStatus::NotPositiveDefinite:
      return "not positive definite";
    case LinearStatus::Failure:
      return "failure";
  }
  return "unknown";
}

std::unique_ptr<LinearSolver> make_linear_solver(SolverChoice choice, bool symmetric,
                                                 bool positive_definite, bool tangent_changes) {
  const bool spd = symmetric && positive_definite;
  switch (choice) {
    case SolverChoice::Automatic:
      // Under mpirun the solve is shared only by the PETSc backend; the world communicator
      // comes from the same plugin, so it has loaded.
      if (launched_on_several_ranks()) return make_petsc_solver(symmetric, positive_definite);
      return std::make_unique<AutomaticSolver>(symmetric, positive_definite, tangent_changes);
    case SolverChoice::Cholmod:
      if (!symmetric) throw std::invalid_argument("CHOLMOD needs a symmetric matrix");
      return std::make_unique<CholmodSolver>();
    case SolverChoice::Umfpack:
      return std::make_unique<UmfpackSolver>();
    case SolverChoice::Dense:
      return std::make_unique<DenseSolver>(spd ? DenseSolver::Method::Cholesky
                                               : DenseSolver::Method::Lu);
    case SolverChoice::Petsc:
      return make_petsc_solver(symmetric, positive_definite);
  }
  throw std::invalid_argument("unknown linear solver choice");
}

}  // namespace clinch
