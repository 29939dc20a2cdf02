// The damage law of one *CONNECTOR DAMAGE EVOLUTION (behaviors.md §7.2): the mechanism's damage
// d_m as a function of the post-initiation motion κ (TYPE=MOTION: LINEAR, EXPONENTIAL, TABULAR)
// or of the work W done after initiation (TYPE=ENERGY), with its gradient.
#pragma once

#include <optional>

#include "src/behavior/damage/trial_sensitive.hpp"
#include "src/behavior/piecewise_linear_table.hpp"
#include "src/model/behavior_model.hpp"

namespace clinch {

class DamageEvolutionLaw {
 public:
  // `plastic`: the mechanism initiates on PLASTIC MOTION (d = 1 − g instead of the force shape).
  DamageEvolutionLaw(const DamageEvolution& evolution, bool plastic);

  bool energy_based() const { return type_ == DamageEvolution::Type::Energy; }

  // d_m from κ = max δ and m_0, the initiation measure (s_0 u_0,i or P_e(u_0)); ENERGY reads W
  // only. Not yet clamped by the history (the caller keeps d_m from decreasing).
  TrialSensitive damage(const TrialSensitive& kappa, const TrialSensitive& initiation_measure,
                        const TrialSensitive& work) const;

 private:
  // g(κ), the remaining fraction of the initiation force (LINEAR, EXPONENTIAL).
  TrialSensitive remaining_fraction(const TrialSensitive& kappa) const;

  DamageEvolution::Type type_;
  DamageEvolution::Softening softening_;
  bool plastic_;
  double failure_motion_ = 0, exponent_ = 0, fracture_energy_ = 0;
  std::optional<PiecewiseLinearTable> table_;  // TABULAR: d(δ)
};

}  // namespace clinch
