// Finite-rotation helpers of the connector kinematics (connection-types.md §2.3, §3.2, §3.6):
// skew matrices, the rotation exponential and logarithm, and the 2πk unwrapping of angles. The
// logarithm is a template so that the same code runs on doubles and on second-order jets.
#pragma once

#include <array>
#include <cmath>
#include <numbers>

#include "src/kinematics/second_order_jet.hpp"
#include "base/small_types.hpp"

namespace clinch {

// Entries R_ij = e_i^a · e_j^b of a relative rotation (§2.3), as doubles or jets.
template <typename T>
using RotationEntries = std::array<std::array<T, 3>, 3>;

// skew(v) w = v × w.
Matrix3 skew(const Vector3& v);

// exp(v̂) (§3.2 closed form), with its Taylor series for small |v|.
Matrix3 rotation_exp(const Vector3& v);

// Principal rotation vector φ of r (|φ| ≤ π), r = exp(φ̂).
Vector3 rotation_log(const Matrix3& r);

// principal + 2πk with k chosen so that the result is closest to `reference` (§3.6).
double unwrap_angle(double principal, double reference);

// The k of φ + 2πk φ/|φ| closest to `reference` (§3.6: φ and (|φ| − 2π)φ/|φ| are one rotation).
// 0 when |φ| is too small to carry a direction.
int rotation_vector_turns(const Vector3& phi, const Vector3& reference);

// atan2(√x, w)/√x, which is θ/sin θ for x = sin²θ, w = cos θ. It is smooth at x = 0 for w > 0,
// where the direct form is 0/0: there the series Σ (−z)^n/(2n+1) / w with z = x/w² is used, so
// that jets get exact derivatives at zero relative rotation (§3.7: series, not differences).
template <typename T>
T angle_over_sine(const T& x, const T& w) {
  using std::atan2;
  using std::sqrt;
  const double wv = value_of(w);
  // Ten terms at z < 1e-2: the truncation is below 1e-20 in the value and its two derivatives.
  if (wv > 0 && value_of(x) < 1e-2 * wv * wv) {
    const T z = x / (w * w);
    constexpr int kTerms = 10;
    T sum = z * 0.0 + 1.0 / (2 * kTerms + 1);
    for (int n = kTerms - 1; n >= 0; --n) sum = 1.0 / (2 * n + 1) - z * sum;
    return sum / w;
  }
  const T s = sqrt(x);
  return atan2(s, w) / s;
}

// Principal rotation vector (components in frame a) of the rotation with entries r, through the
// unit quaternion (Shepperd's choice of the largest component keeps every square root away
// from zero), φ = 2 atan2(|v|, w) v/|v|.
template <typename T>
std::array<T, 3> rotation_vector(const RotationEntries<T>& r) {
  using std::sqrt;
  const double r11 = value_of(r[0][0]);
  const double r22 = value_of(r[1][1]);
  const double r33 = value_of(r[2][2]);
  const double trace = r11 + r22 + r33;
  T w, x, y, z;
  if (trace >= r11 && trace >= r22 && trace >= r33) {
    w = 0.5 * sqrt(1.0 + r[0][0] + r[1][1] + r[2][2]);
    const T k = 0.25 / w;
    x = (r[2][1] - r[1][2]) * k;
    y = (r[0][2] - r[2][0]) * k;
    z = (r[1][0] - r[0][1]) * k;
  } else if (r11 >= r22 && r11 >= r33) {
    x = 0.5 * sqrt(1.0 + r[0][0] - r[1][1] - r[2][2]);
    const T k = 0.25 / x;
    w = (r[2][1] - r[1][2]) * k;
    y = (r[0][1] + r[1][0]) * k;
    z = (r[0][2] + r[2][0]) * k;
  } else if (r22 >= r33) {
    y = 0.5 * sqrt(1.0 - r[0][0] + r[1][1] - r[2][2]);
    const T k = 0.25 / y;
    w = (r[0][2] - r[2][0]) * k;
    x = (r[0][1] + r[1][0]) * k;
    z = (r[1][2] + r[2][1]) * k;
  } else {
    z = 0.5 * sqrt(1.0 - r[0][0] - r[1][1] + r[2][2]);
    const T k = 0.25 / z;
    w = (r[1][0] - r[0][1]) * k;
    x = (r[0][2] + r[2][0]) * k;
    y = (r[1][2] + r[2][1]) * k;
  }
  if (value_of(w) < 0) {
    w = -w;
    x = -x;
    y = -y;
    z = -z;
  }
  const T scale = 2.0 * angle_over_sine(x * x + y * y + z * z, w);
  return {scale * x, scale * y, scale * z};
}

}  // namespace clinch
