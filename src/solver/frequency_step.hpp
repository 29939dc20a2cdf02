// A *FREQUENCY step (docs/dynamics.md "Natural frequencies"): a linear perturbation step about the
// base state, the converged state of the steps before it, which it leaves as it found it. Its
// stiffness is the symmetric tangent there (the laws at a zero increment, the held DOFs decoupled
// as in a Newton iteration), its mass the lumped nodal inertia of the free DOFs; the eigenpairs
// come from frequency_eigensolver.hpp. The data line's range and shift are chosen as
// docs/decisions.md "Natural frequencies" says.
#pragma once

#include <string>
#include <vector>

#include "src/linalg/linear_solver.hpp"
#include "src/model/history_model.hpp"
#include "src/output/modes_file.hpp"
#include "src/solver/nonlinear_problem.hpp"
#include "src/solver/step_problem.hpp"

namespace clinch {

struct FrequencyStepResult {
  std::vector<ModeRecord> modes;   // ascending eigenvalue, numbered from 1
  std::vector<std::string> notes;  // for the log: fewer modes than asked, negative eigenvalues
  std::string error;               // why no eigenvalue could be computed (empty: success)
  int failed_equation = -1;        // a solved equation the error is about, −1 if none
};

// The request of `procedure` in eigenvalues λ = (2π f)²: the shift, the range and the count. The
// default shift is −10⁻⁶ of the largest K_ii/M_ii over the DOFs with mass (`scale`), so that the
// zero eigenvalues of a mechanism are found and K − σM stays regular.
EigenRequest eigen_request(const FrequencyProcedure& procedure, double scale);

// Evaluates the tangent of `problem` at its current state (the caller starts an increment of no
// length at the converged state first, and reverts after) and extracts the modes with `solver`,
// analysed on problem.pattern() in symmetric storage.
FrequencyStepResult solve_frequency_step(const FrequencyProcedure& procedure,
                                         NonlinearProblem& problem, const FrequencyModel& model,
                                         LinearSolver& solver);

}  // namespace clinch
