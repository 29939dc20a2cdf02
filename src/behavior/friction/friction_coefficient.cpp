#include "src/behavior/friction/friction_coefficient.hpp"

#include <algorithm>
#include <cmath>

namespace clinch {

FrictionCoefficient::FrictionCoefficient(const FrictionLaw& law)
    : variable_(law.variable), decay_(law.exponential_decay) {
  if (decay_) {
    mu_static_ = law.mu_static;
    mu_kinetic_ = law.mu_kinetic;
    decay_coefficient_ = law.decay;
    steepest_weakening_ = std::max(0.0, decay_coefficient_ * (mu_static_ - mu_kinetic_));
    return;
  }
  constant_ = law.mu.empty() ? 0.0 : law.mu.front();
  // §3.2: a table depends on one column; beyond its ends μ is constant.
  if (variable_ == FrictionLaw::Variable::SlipRate) {
    table_.emplace(law.slip_rate, law.mu, Extrapolation::Constant);
    for (std::size_t k = 0; k + 1 < law.mu.size(); ++k) {
      const double slope = (law.mu[k + 1] - law.mu[k]) / (law.slip_rate[k + 1] - law.slip_rate[k]);
      steepest_weakening_ = std::max(steepest_weakening_, -slope);
    }
  } else if (variable_ == FrictionLaw::Variable::ContactForce) {
    table_.emplace(law.contact_force, law.mu, Extrapolation::Constant);
  }
}

FrictionCoefficientSample FrictionCoefficient::at(double slip_rate, double contact_force) const {
  if (decay_) {
    const double e = std::exp(-decay_coefficient_ * slip_rate);
    return {mu_kinetic_ + (mu_static_ - mu_kinetic_) * e,
            -decay_coefficient_ * (mu_static_ - mu_kinetic_) * e, 0.0};
  }
  if (!table_) return {constant_, 0.0, 0.0};
  const bool rate = variable_ == FrictionLaw::Variable::SlipRate;
  const TableSample s = table_->evaluate(rate ? slip_rate : contact_force);
  return {s.value, rate ? s.slope : 0.0, rate ? 0.0 : s.slope};
}

}  // namespace clinch
