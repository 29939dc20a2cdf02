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

// The assembled tangent `k` (the values at the current state) against central differences of
// the residual of `problem`, equation j moved by steps[j] through apply_correction (rotations
// multiplicatively under NLGEOM); an equation with a zero step (prescribed) is neither
// differenced nor compared. `k` is read whole: directly from a full pattern, mirrored from
// symmetric-upper storage. With `symmetric_part`, compared with ½(J + Jᵀ) of the differences J.
// Each evaluation restarts from the current state and leaves it there up to round-off (x + h − h);
// none touches the committed history (behaviors.md §1.4).
JacobianReport check_assembled_tangent(NonlinearProblem& problem, const SparseMatrix& k,
                                       const Eigen::VectorXd& steps, bool symmetric_part = false);

// The report (several lines); the state of `system` is restored exactly afterwards (conditions,
// prescribed predictor and results included), so a checked run gives the same history as an
// unchecked one. The whole matrix is compared, prescribed DOFs included (it is checked without the
// increment's conditions), read through the storage of its pattern (full or symmetric upper).
std::string check_tangent(ConnectorSystem& system, int step, int increment);

}  // namespace clinch
