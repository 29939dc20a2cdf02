// Rotary inertia under NLGEOM in a *DYNAMIC step (docs/dynamics.md "Finite rotations"): the
// energy–momentum update of Simo and Wong (1991) for a node with a rotary inertia tensor J (in
// the global axes of the reference configuration, the body's material tensor). With R₀, R₁ the
// node's rotations at the start and end of the increment, the material increment
// Θ = log(R₀ᵀR₁) is the trapezoidal rule on the material angular velocities,
//   Θ = Δt (W₀ + W₁)/2,  so  W₁ = 2Θ/Δt − W₀,
// and the balance of the spatial angular momentum π = R J W over the increment is the
// trapezoidal rule on the moments r = I − P (internal minus applied):
//   (π₁ − π₀)/Δt + (r₀ + r₁)/2 = 0.
// Without moments π₁ = π₀ exactly, and the kinetic energy ½ W·JW is conserved exactly: J W₁ is
// exp(−Θ̂) J W₀, a rotation about Θ, and (W₀ + W₁)·J(W₁ − W₀) = (2/Δt) Θ·(exp(−Θ̂) − I) J W₀ = 0.
// The rotation rows of such a node hold 2(π₁ − π₀)/Δt + r₀ + r₁ = 0, twice the balance, in place
// of the HHT α form of the other rows (dynamic_terms.hpp), whose linear path stays as it is for
// small rotations.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "src/assembly/analysis_state.hpp"
#include "src/assembly/dynamic_terms.hpp"
#include "src/assembly/increment_conditions.hpp"
#include "src/assembly/nodal_inertia.hpp"

namespace clinch {

// The node turns with finite rotations and carries rotary inertia on all three rotations.
bool has_finite_rotary_inertia(const NodeInertia& node, bool nlgeom);

// The spatial angular velocity ω₁ = R₁W₁ and acceleration R₁(W₁ − W₀)/Δt of the rotation
// equations of such nodes, at the trial rotations, from the converged state (v₀ = ω₀).
void update_finite_rotary_rates(std::span<const NodeInertia> inertia, double dt,
                                AnalysisState& state);

// Adds 2(π₁ − π₀)/Δt + r₀ to the free rotation rows of such nodes, and its derivative with
// respect to a spatial spin of R₁ (R₁ ← exp(δθ̂) R₁, as Newton corrects rotations) to the tangent:
//   (2/Δt) [−π̂₁ + (2/Δt) R₁ J T(Θ)⁻¹ R₀ᵀ],
// T(Θ) the left Jacobian of the exponential map (exp(Θ + δΘ) = exp(T(Θ)δΘ) exp(Θ)); unsymmetric,
// its symmetric part in symmetric storage. `inertia_force` gets the added moment.
void add_finite_rotary_inertia(std::span<const NodeInertia> inertia, double dt,
                               const AnalysisState& state, const IncrementConditions& conditions,
                               InertiaTarget target, Eigen::VectorXd& inertia_force,
                               ForceEntries& entries);

// ½ W·JW of such a node at the spatial angular velocity ω and rotation R (W = Rᵀω).
double finite_rotary_kinetic_energy(const NodeInertia& node, const Matrix3& rotation,
                                    const Vector3& omega);

}  // namespace clinch
