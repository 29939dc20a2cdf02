#include "src/behavior/damage/sensitive_potential.hpp"

namespace clinch {

TrialSensitive evaluate_potential(const ConnectorPotential& potential, const SensitiveVector& x) {
  Vector6 values;
  for (int j = 0; j < 6; ++j) values[j] = x[static_cast<std::size_t>(j)].value;
  PotentialValue p;
  potential.evaluate(values, p, false);
  TrialSensitive v(p.value);
  for (int j = 0; j < 6; ++j) {
    if (p.gradient[j] != 0) v.gradient += p.gradient[j] * x[static_cast<std::size_t>(j)].gradient;
  }
  return v;
}

SensitiveVector constant_vector(const Vector6& x) {
  SensitiveVector v;
  for (int j = 0; j < 6; ++j) v[static_cast<std::size_t>(j)] = TrialSensitive(x[j]);
  return v;
}

SensitiveVector motion_vector(const Vector6& u) {
  SensitiveVector v;
  for (int j = 0; j < 6; ++j) v[static_cast<std::size_t>(j)] = TrialSensitive::motion(u, j);
  return v;
}

}  // namespace clinch
