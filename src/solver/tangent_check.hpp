// `clinch run --check-tangent` (ARCHITECTURE.md testing habit 2): at the first iterate of an
// increment, compares the assembled tangent with central finite differences of the residual and
// reports the worst entries, so an analyst can see whether slow convergence comes from the
// tangent.
#pragma once

#include <string>

#include "base/jacobian_check.hpp"
#include "src/assembly/connector_system.hpp"
#include "src/solver/nonlinear_problem.hpp"

namespace clinch {

// The residual of `problem` with equation `column` moved by `step` through apply_correction
// (rotations multiplicatively under NLGEOM), for check_jacobian; each evaluation puts the state
// back, and none touches the committed history (behaviors.md §1.4).
PerturbedFunction residual_perturbation(NonlinearProblem& problem);

// The report (several lines); the state of `system` is unchanged afterwards. The whole matrix
// is compared, read through the storage of its pattern (full or symmetric upper).
std::string check_tangent(ConnectorSystem& system, int step, int increment);

}  // namespace clinch
