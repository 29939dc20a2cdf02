#include "src/behavior/friction/friction_capacity.hpp"

#include <cmath>

namespace clinch {

FrictionCapacity::Sample FrictionCapacity::sample(double slip) const {
  Sample s;
  if (law_.internal_force) {
    const TableSample t = law_.internal_force->evaluate(slip);
    s.internal = t.value;
    s.internal_slope = t.slope;
  }
  const double sum = contact_ + s.internal;
  s.sign = sum < 0 ? -1.0 : 1.0;
  s.normal = std::abs(sum);
  // §3.3: the slip rate of the increment; the stick test (Δλ = 0) sees rate 0.
  const double rate = dt_ > 0 ? (slip - slip_old_) / dt_ : 0.0;
  s.mu = law_.coefficient.at(rate, s.normal);
  s.capped = law_.cap && s.mu.mu * s.normal > *law_.cap;
  return s;
}

YieldSample FrictionCapacity::at(double slip) const {
  const Sample s = sample(slip);
  if (s.capped) return {*law_.cap, 0.0};
  const double rate_slope = dt_ > 0 ? s.normal * s.mu.d_rate / dt_ : 0.0;
  const double normal_slope = (s.mu.mu + s.normal * s.mu.d_force) * s.sign * s.internal_slope;
  return {s.mu.mu * s.normal, rate_slope + normal_slope};
}

double FrictionCapacity::contact_force(double slip) const { return sample(slip).normal; }

double FrictionCapacity::contact_sensitivity(double slip) const {
  const Sample s = sample(slip);
  if (s.capped) return 0.0;
  return (s.mu.mu + s.normal * s.mu.d_force) * s.sign;
}

}  // namespace clinch
