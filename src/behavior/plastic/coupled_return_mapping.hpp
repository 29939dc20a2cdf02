// Closest-point projection of a coupled connector plasticity with a SUM potential and isotropic
// hardening (behaviors.md §6.4): Newton on (F, Δλ) with a backtracking line search and Δλ ≥ 0,
// the cutting-plane algorithm as fallback, and the closed-form symmetric consistent tangent
// D = A − (A n)(A n)ᵀ/(nᵀ A n + h), A = (K⁻¹ + Δλ N2)⁻¹. Where the exact return ends on a kink
// of P (a NORM term or a Macaulay term of a derived component at zero while P > 0), the minimum-
// norm subgradient of the spec cannot satisfy the flow rule; the return then holds that group at
// zero and checks that the flow rule holds with an admissible subgradient (an active set on the
// kinks), so the returned state is the exact closest point there too.
#pragma once

#include "src/behavior/potential/connector_potential.hpp"
#include "src/behavior/yield_function.hpp"
#include "src/behavior/plastic/plastic_return_types.hpp"

namespace clinch {

// `trial` = K (u − u^pl_n) (zero in padded slots), `equivalent_old` = ū_n. The plastic motion of
// the increment is K⁻¹(F^tr − F) (§6.4 step 4), left to the caller.
CoupledReturn closest_point_return(const ElasticSpace& space, const ConnectorPotential& potential,
                                   YieldFunction yield, const Vector6& trial,
                                   double equivalent_old, bool want_tangent);

// The cutting-plane algorithm of §6.4 step 3 on its own (the fallback of closest_point_return):
// δλ = φ/(nᵀ K n + h), F ← F − δλ K n, until |φ| ≤ 1e-12·F_y. With a MAX potential it follows the
// maximising contribution, which is how the multi-surface return falls back at a corner.
CoupledReturn cutting_plane_return(const ElasticSpace& space, const ConnectorPotential& potential,
                                   YieldFunction yield, const Vector6& trial,
                                   double equivalent_old, bool want_tangent);

// §6.4 step 5 at a converged state: D = A − (A n)(A n)ᵀ/(nᵀ A n + h), A = (K⁻¹ + Δλ N2)⁻¹,
// with A restricted to the components outside `held` (kink groups the return holds at zero);
// writes D and the yield sensitivity A n/(nᵀ A n + h) into `out`.
void closest_point_tangent(const ElasticSpace& space, const Vector6& normal,
                           const Matrix6& hessian, double multiplier, double hardening,
                           ComponentMask held, CoupledReturn& out);

}  // namespace clinch
