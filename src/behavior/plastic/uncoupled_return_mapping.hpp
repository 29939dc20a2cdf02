// Backward-Euler return mapping of one uncoupled connector plasticity (behaviors.md §6.3): a
// scalar equation for Δλ, solved by Newton safeguarded by bisection, with isotropic hardening
// (tables stepped across their breakpoints), kinematic hardening (Ziegler or Armstrong–Frederick)
// and the closed-form consistent modulus. The elastic-plastic behaviour calls it per component.
#pragma once

#include "src/behavior/yield_function.hpp"
#include "src/behavior/plastic/kinematic_hardening.hpp"

namespace clinch {

struct UncoupledReturnInput {
  double stiffness = 0;    // k (the diagonal term K_ii when K is coupled, §6.3 last paragraph)
  double trial_force = 0;  // F^tr = k (u − u^pl_n), or (K (u − u^pl_n))_i
  double equivalent_old = 0;  // ū_n
  double back_old = 0;        // α_n
  YieldFunction yield;  // F_y(ū), or a friction capacity F_lim(γ)
  const KinematicHardeningLaw* kinematic = nullptr;  // null: no kinematic hardening
};

struct UncoupledReturn {
  bool plastic = false;    // φ^tr > 0
  bool converged = true;
  double sign = 0;         // s = sign(ξ^tr)
  double multiplier = 0;   // Δλ
  double back = 0;         // α(Δλ)
  // k + h + H_α (plastic only). §6.3 step 4: D = k − k²/(k + h + H_α) = k (h + H_α)/(k + h + H_α);
  // with a coupled K and n = s e_i the same linearisation gives D = K − (K e_i)(K e_i)ᵀ/(that).
  double tangent_denominator = 0;
};

UncoupledReturn uncoupled_return(const UncoupledReturnInput& in);

}  // namespace clinch
