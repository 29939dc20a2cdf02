// The friction capacity F_lim = min(μ·F_N, F_max) of one friction definition during one local
// update (friction.md §2.2, §3, §4.1), as a function of the accumulated slip γ = γ_n + Δλ, for
// the return mappings: the contact force F_N = |g + F_int(γ)| with the contact measure g held at
// its value at the iterate, the slip rate γ̇ = Δλ/Δt of a static step (§3.3), and the slope
// ∂F_lim/∂Δλ = F_N·(∂μ/∂γ̇)/Δt + (μ + F_N·∂μ/∂F_N)·sgn(g + F_int)·dF_int/dγ (0 under the cap).
#pragma once

#include <optional>

#include "src/behavior/friction/friction_coefficient.hpp"
#include "src/behavior/piecewise_linear_table.hpp"
#include "src/behavior/yield_function.hpp"

namespace clinch {

// What a friction definition's capacity depends on besides the state: μ, F_int(γ) and F_max.
struct FrictionCapacityLaw {
  FrictionCoefficient coefficient;
  std::optional<PiecewiseLinearTable> internal_force;  // none: F_int = 0
  std::optional<double> cap;                           // TAUMAX; none: no cap
};

class FrictionCapacity {
 public:
  // `contact` = g = |N(f)| ≥ 0 at the iterate, `slip_old` = γ_n, `dt` the increment of step time.
  FrictionCapacity(const FrictionCapacityLaw& law, double contact, double slip_old, double dt)
      : law_(law), contact_(contact), slip_old_(slip_old), dt_(dt) {}

  YieldSample at(double slip) const;
  // F_N = |g + F_int(γ)| (§2.2).
  double contact_force(double slip) const;
  // ∂F_lim/∂g at γ: how the capacity follows the contact measure (§4.2).
  double contact_sensitivity(double slip) const;

 private:
  struct Sample {
    double internal = 0, internal_slope = 0;  // F_int(γ), dF_int/dγ
    double sign = 1;                          // sgn(g + F_int)
    double normal = 0;                        // F_N
    FrictionCoefficientSample mu;
    bool capped = false;
  };
  Sample sample(double slip) const;

  const FrictionCapacityLaw& law_;
  double contact_, slip_old_, dt_;
};

}  // namespace clinch
