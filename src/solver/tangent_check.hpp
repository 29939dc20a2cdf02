// An assembled tangent against central finite differences of a NonlinearProblem's residual: the
// comparison behind `clinch run --check-tangent` (src/assembly/connector_tangent_check.hpp) and
// the tangent tests.
#pragma once

#include "base/jacobian_check.hpp"
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

}  // namespace clinch
