// The back force of an uncoupled connector plasticity with kinematic hardening (behaviors.md
// §6.1 PARAMETERS, HALF CYCLE mapped to them by the reader; §6.2 evolution law). The uncoupled
// return mapping (§6.3) uses the backward-Euler form and its derivative.
#pragma once

namespace clinch {

// Ziegler (γ = 0) and Armstrong–Frederick back-force evolution (§6.2), integrated by backward
// Euler for an uncoupled component (§6.3): α(Δλ) = (α_n + C s Δλ)/(1 + γ Δλ).
struct KinematicHardeningLaw {
  double c = 0, gamma = 0;

  double back_force(double alpha_old, double sign, double multiplier) const {
    return (alpha_old + c * sign * multiplier) / (1.0 + gamma * multiplier);
  }
  // H_α = s·dα/dΔλ = (C − s γ α_n)/(1 + γΔλ)² (§6.3 step 4).
  double modulus(double alpha_old, double sign, double multiplier) const {
    const double d = 1.0 + gamma * multiplier;
    return (c - sign * gamma * alpha_old) / (d * d);
  }
};

}  // namespace clinch
