// The friction coefficient μ of a *FRICTION law in a connector behaviour (friction.md §3): a
// constant, a table in the slip rate or in the contact force (piecewise linear, constant beyond
// its ends), or the static–kinetic exponential decay μ = μ_k + (μ_s − μ_k)·exp(−d_c·γ̇).
#pragma once

#include <optional>

#include "src/behavior/piecewise_linear_table.hpp"
#include "src/model/friction_model.hpp"

namespace clinch {

struct FrictionCoefficientSample {
  double mu = 0;
  double d_rate = 0;   // ∂μ/∂γ̇
  double d_force = 0;  // ∂μ/∂F_N
};

class FrictionCoefficient {
 public:
  // The law must have passed validation (μ ≥ 0, a strictly increasing dependent column).
  explicit FrictionCoefficient(const FrictionLaw& law);

  FrictionCoefficientSample at(double slip_rate, double contact_force) const;
  bool depends_on_rate() const { return decay_ || variable_ == FrictionLaw::Variable::SlipRate; }
  // The steepest weakening max(0, −∂μ/∂γ̇) over every rate: d_c·(μ_s − μ_k) for the decay
  // (friction.md §7.3), the steepest falling segment of a rate table.
  double steepest_weakening() const { return steepest_weakening_; }

 private:
  FrictionLaw::Variable variable_ = FrictionLaw::Variable::None;
  double constant_ = 0;
  std::optional<PiecewiseLinearTable> table_;
  bool decay_ = false;
  double mu_static_ = 0, mu_kinetic_ = 0, decay_coefficient_ = 0;
  double steepest_weakening_ = 0;
};

}  // namespace clinch
