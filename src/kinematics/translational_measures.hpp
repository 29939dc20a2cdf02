// Closed-form translational measures of connector kinematics (connection-types.md §3.3, §3.7):
// the distance |d| of AXIAL and LINK and the frame-a projection e·d of CARTESIAN, JOIN, SLOT,
// SLIDE-PLANE and RADIAL-THRUST, with their first and second variations.
#pragma once

#include "src/kinematics/second_order_jet.hpp"
#include "base/small_types.hpp"

namespace clinch {

// |d| into `value`, its B row into row `row` of `b` and, when `hessian` is given, H (§3.7
// "AXIAL, fully worked"). Returns false when |d| = 0, where the direction is undefined.
bool distance_measure(const Vector3& d, double& value, Matrix6x12& b, int row, Matrix12* hessian);

// e·d with e = R_a e0 as a jet in the 12 element parameters. When `corotating` is false the
// frame of a is fixed (JOIN without rotations at a, §2.2) and the θ_a terms vanish. The Hessian
// is filled only when `want_hessian`.
Jet<12> frame_a_projection(const Vector3& e, const Vector3& d, bool corotating, bool want_hessian);

}  // namespace clinch
