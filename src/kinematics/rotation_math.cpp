#include "src/kinematics/rotation_math.hpp"

namespace clinch {

Matrix3 skew(const Vector3& v) {
  Matrix3 m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

Matrix3 rotation_exp(const Vector3& v) {
  const double t2 = v.squaredNorm();
  double a, b;  // sin t / t and (1 − cos t)/t²
  // Below t² = 1e-8 two series terms are exact to rounding (the next ones are O(t⁴) ≈ 1e-16).
  if (t2 < 1e-8) {
    a = 1.0 - t2 / 6.0;
    b = 0.5 - t2 / 24.0;
  } else {
    const double t = std::sqrt(t2);
    a = std::sin(t) / t;
    b = (1.0 - std::cos(t)) / t2;
  }
  const Matrix3 k = skew(v);
  return Matrix3::Identity() + a * k + b * k * k;
}

Vector3 rotation_log(const Matrix3& r) {
  RotationEntries<double> entries;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) entries[i][j] = r(i, j);
  }
  const std::array<double, 3> phi = rotation_vector(entries);
  return {phi[0], phi[1], phi[2]};
}

double unwrap_angle(double principal, double reference) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  return principal + kTwoPi * std::round((reference - principal) / kTwoPi);
}

int rotation_vector_turns(const Vector3& phi, const Vector3& reference) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  const double norm = phi.norm();
  // Below 1e-6 rad the direction of φ is dominated by round-off; no turn is added.
  if (norm < 1e-6) return 0;
  // |φ + 2πk u − φ_ref|² is a parabola in k with its minimum at (u·φ_ref − |φ|)/(2π).
  return static_cast<int>(std::round((phi.dot(reference) / norm - norm) / kTwoPi));
}

}  // namespace clinch
