// A scalar of the damage update together with its gradient against the trial state: the
// constitutive motion u and the connector's constraint forces λ, which the FORCE criterion reads
// as part of the total force (forward-mode differentiation). The damage tangent of behaviors.md
// §7.4 chains the criterion, the interpolated initiation point, the driving motion, the energy
// integral and the damage laws; carrying the gradient through each operation gives the
// consistent tangent of exactly the discrete update that is computed, including the parts the
// closed forms of §7.4 leave out (an increment that crosses initiation, the start of the energy
// integral).
#pragma once

#include <cmath>

#include "base/small_types.hpp"

namespace clinch {

using TrialGradient = Eigen::Matrix<double, 12, 1>;  // ∂/∂u (0–5), then ∂/∂λ (6–11)

struct TrialSensitive {
  double value = 0;
  TrialGradient gradient = TrialGradient::Zero();

  TrialSensitive() = default;
  TrialSensitive(double v) : value(v) {}  // a constant (NOLINT: implicit on purpose)
  TrialSensitive(double v, const TrialGradient& g) : value(v), gradient(g) {}

  // Component i of u itself.
  static TrialSensitive motion(const Vector6& u, int i) {
    TrialSensitive s(u[i]);
    s.gradient[i] = 1.0;
    return s;
  }
  // A value that depends on u only, with ∂value/∂u = du.
  static TrialSensitive of_motion(double v, const Vector6& du) {
    TrialSensitive s(v);
    s.gradient.head<6>() = du;
    return s;
  }
  // Component i of λ itself.
  static TrialSensitive constraint_force(const Vector6& lambda, int i) {
    TrialSensitive s(lambda[i]);
    s.gradient[6 + i] = 1.0;
    return s;
  }
};

inline TrialSensitive operator+(const TrialSensitive& a, const TrialSensitive& b) {
  return {a.value + b.value, a.gradient + b.gradient};
}
inline TrialSensitive operator-(const TrialSensitive& a, const TrialSensitive& b) {
  return {a.value - b.value, a.gradient - b.gradient};
}
inline TrialSensitive operator-(const TrialSensitive& a) { return {-a.value, -a.gradient}; }
inline TrialSensitive operator*(const TrialSensitive& a, const TrialSensitive& b) {
  return {a.value * b.value, b.value * a.gradient + a.value * b.gradient};
}
inline TrialSensitive operator/(const TrialSensitive& a, const TrialSensitive& b) {
  return {a.value / b.value, (a.gradient - (a.value / b.value) * b.gradient) / b.value};
}
inline TrialSensitive exp(const TrialSensitive& a) {
  const double e = std::exp(a.value);
  return {e, e * a.gradient};
}
// The larger of two: its value and the gradient of the argument that gives it (the first on a
// tie, so that a history maximum that is not exceeded keeps a zero gradient).
inline TrialSensitive larger(const TrialSensitive& a, const TrialSensitive& b) {
  return b.value > a.value ? b : a;
}

}  // namespace clinch
