#include "src/behavior/plastic/isotropic_hardening.hpp"

#include <cmath>
#include <stdexcept>

namespace clinch {

IsotropicHardeningLaw IsotropicHardeningLaw::from_plasticity(const ConnectorPlasticity& p) {
  IsotropicHardeningLaw law;
  if (p.isotropic) {
    const IsotropicHardening& iso = *p.isotropic;
    if (iso.definition == IsotropicHardening::Definition::ExponentialLaw) {
      law.kind_ = Kind::Exponential;
      law.f0_ = iso.f0;
      law.q_inf_ = iso.q_inf;
      law.b_ = iso.b;
    } else {
      law.kind_ = Kind::Tabular;
      law.table_ = PiecewiseLinearTable::from_points(iso.table, iso.extrapolation);
    }
    return law;
  }
  if (p.kinematic) return constant(p.kinematic->f0);
  throw std::invalid_argument("connector plasticity without hardening");
}

IsotropicHardeningLaw IsotropicHardeningLaw::constant(double f0) {
  IsotropicHardeningLaw law;
  law.f0_ = f0;
  return law;
}

YieldSample IsotropicHardeningLaw::exponential(double ubar) const {
  // §6.1: F_y = F_0 + Q_inf (1 − e^(−b ū)), h = Q_inf b e^(−b ū).
  const double e = std::exp(-b_ * ubar);
  return {f0_ + q_inf_ * (1.0 - e), q_inf_ * b_ * e};
}

}  // namespace clinch
