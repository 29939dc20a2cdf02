// A scalar of the damage update together with its gradient against the trial constitutive motion
// u (forward-mode differentiation). The damage tangent of behaviors.md §7.4 chains the criterion,
// the interpolated initiation point, the driving motion, the energy integral and the damage laws;
// carrying ∂/∂u through each operation gives the consistent tangent of exactly the discrete
// update that is computed, including the parts the closed forms of §7.4 leave out (an increment
// that crosses initiation, the start of the energy integral).
#pragma once

#include <cmath>

#include "base/small_types.hpp"

namespace clinch {

struct MotionSensitive {
  double value = 0;
  Vector6 gradient = Vector6::Zero();  // ∂value/∂u

  MotionSensitive() = default;
  MotionSensitive(double v) : value(v) {}  // a constant (NOLINT: implicit on purpose)
  MotionSensitive(double v, const Vector6& g) : value(v), gradient(g) {}

  // Component i of u itself.
  static MotionSensitive motion(const Vector6& u, int i) {
    MotionSensitive s(u[i]);
    s.gradient[i] = 1.0;
    return s;
  }
};

inline MotionSensitive operator+(const MotionSensitive& a, const MotionSensitive& b) {
  return {a.value + b.value, a.gradient + b.gradient};
}
inline MotionSensitive operator-(const MotionSensitive& a, const MotionSensitive& b) {
  return {a.value - b.value, a.gradient - b.gradient};
}
inline MotionSensitive operator-(const MotionSensitive& a) { return {-a.value, -a.gradient}; }
inline MotionSensitive operator*(const MotionSensitive& a, const MotionSensitive& b) {
  return {a.value * b.value, b.value * a.gradient + a.value * b.gradient};
}
inline MotionSensitive operator/(const MotionSensitive& a, const MotionSensitive& b) {
  return {a.value / b.value, (a.gradient - (a.value / b.value) * b.gradient) / b.value};
}
inline MotionSensitive exp(const MotionSensitive& a) {
  const double e = std::exp(a.value);
  return {e, e * a.gradient};
}
// The larger of two: its value and the gradient of the argument that gives it (the first on a
// tie, so that a history maximum that is not exceeded keeps a zero gradient).
inline MotionSensitive larger(const MotionSensitive& a, const MotionSensitive& b) {
  return b.value > a.value ? b : a;
}

}  // namespace clinch
