// What the coupled return mappings of connector plasticity share (behaviors.md §6.4, §6.6): the
// linear elastic space they work in and the result they hand back to the elastic-plastic
// behaviour.
#pragma once

#include <limits>

#include "base/small_types.hpp"

namespace clinch {

// The linear elastic law F = K (u − u^pl) (§6.2) on the components with linear elasticity. The
// other slots are padded with the identity, with a zero trial force and a zero normal there, so
// that fixed-size 6×6 algebra leaves them at zero and never sees a singular matrix.
struct ElasticSpace {
  Matrix6 stiffness = Matrix6::Identity();   // K (padded)
  Matrix6 compliance = Matrix6::Identity();  // K⁻¹ (padded)
};

// The floor of the yield residuals of the returns (P(F) − F_y, or r of the uncoupled one), as a
// fraction of the trial P(F^tr): F is reached from F^tr, so its round-off, and that of P(F), is a
// few ulps of the trial. Without it a yield size far below the trial (a friction capacity from a
// contact force near zero, friction.md §4.1) asks 1e-12·F_y of a residual that double precision
// cannot reach.
constexpr double kReturnRoundOff = 64 * std::numeric_limits<double>::epsilon();

struct CoupledReturn {
  bool plastic = false;    // φ^tr > 0
  bool converged = true;
  Vector6 force = Vector6::Zero();  // F at the end of the increment
  double multiplier = 0;            // Δλ (MAX: Σ_j Δλ_j), the increment of ū (§6.2)
  Matrix6 tangent = Matrix6::Zero();  // ∂F/∂u, filled when plastic and asked for
  // ∂F/∂F_y at fixed u: how the returned force follows a change of the yield size that does not
  // come from ū (friction: the capacity through the contact force, friction.md §4.2). Filled
  // with the tangent by closest_point_return, cutting_plane_return and multi_surface_return.
  Vector6 yield_sensitivity = Vector6::Zero();
};

}  // namespace clinch
