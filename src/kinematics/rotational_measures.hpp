// The angle measures of the rotational connection types (connection-types.md §2.3) as functions
// of the relative rotation entries R_ij = e_i^a·e_j^b: Cardan, Euler, flexion-torsion and the
// mid frame of the PROJECTION types. Templates, evaluated on jets to get B and H (§3.7).
#pragma once

#include <array>

#include "src/kinematics/rotation_math.hpp"

namespace clinch {

// Jets of R_rel under spatial spins of both frames (§3.1): E_a(p) = exp(p̂_a) E_a, E_b likewise.
// The spin of frame a is parameter block [ia, ia + 3), that of b [ib, ib + 3). To second order
// R_ij(p) = e_iᵀ (I − â + ½â²)(I + b̂ + ½b̂²) e_j, which gives the closed forms below.
template <int N>
RotationEntries<Jet<N>> relative_rotation_jet(const Matrix3& ea, const Matrix3& eb, int ia,
                                              int ib) {
  RotationEntries<Jet<N>> r;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const Vector3 a = ea.col(i);
      const Vector3 b = eb.col(j);
      Jet<N>& entry = r[i][j];
      entry.v = a.dot(b);
      const Vector3 c = a.cross(b);
      entry.g.template segment<3>(ia) = c;
      entry.g.template segment<3>(ib) = -c;
      const Matrix3 same =
          0.5 * (a * b.transpose() + b * a.transpose()) - entry.v * Matrix3::Identity();
      const Matrix3 mixed = entry.v * Matrix3::Identity() - b * a.transpose();
      entry.h.template block<3, 3>(ia, ia) = same;
      entry.h.template block<3, 3>(ib, ib) = same;
      entry.h.template block<3, 3>(ia, ib) = mixed;
      entry.h.template block<3, 3>(ib, ia) = mixed.transpose();
    }
  }
  return r;
}

// Cardan 1-2-3 (α, β, γ): R_rel = Rx(α) Ry(β) Rz(γ), principal values (§2.3).
template <typename T>
std::array<T, 3> cardan_angles(const RotationEntries<T>& r) {
  using std::asin;
  using std::atan2;
  return {atan2(-r[1][2], r[2][2]), asin(r[0][2]), atan2(-r[0][1], r[0][0])};
}

// Euler 3-1-3 (α, β, γ): R_rel = Rz(α) Rx(β) Rz(γ), principal values (§2.3).
template <typename T>
std::array<T, 3> euler_angles(const RotationEntries<T>& r) {
  using std::acos;
  using std::atan2;
  return {atan2(r[0][2], -r[1][2]), acos(r[2][2]), atan2(r[2][0], r[2][1])};
}

// The flexion rotation vector α n in frame-a components 1, 2 (n ⟂ e3a, so component 3 is 0):
// α n = (α/sin α) e3a × e3b, which is smooth at α = 0 unlike α and n separately (§2.3).
template <typename T>
std::array<T, 2> flexion_vector(const RotationEntries<T>& r) {
  const T scale = angle_over_sine(r[0][2] * r[0][2] + r[1][2] * r[1][2], r[2][2]);
  return {-scale * r[1][2], scale * r[0][2]};
}

// Torsion β = atan2(R21 − R12, R11 + R22), regular at zero flexion (§2.3).
template <typename T>
T torsion_angle(const RotationEntries<T>& r) {
  using std::atan2;
  return atan2(r[1][0] - r[0][1], r[0][0] + r[1][1]);
}

// The mid frame E_m = E_a F(α/2, n) Rz(β/2) of the PROJECTION types (§2.3), in frame-a
// components: column i holds e_i^m. F(α/2, n) turns e3a onto the bisector m of e3a and e3b; as
// the rotation taking e3 to m it is c I + ŵ + w wᵀ/(1 + c) with w = e3 × m and c = e3·m, which
// stays regular at α = 0.
template <typename T>
RotationEntries<T> mid_frame(const RotationEntries<T>& r, const T& half_torsion) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const T m3_raw = 1.0 + r[2][2];
  const T inv_norm = 1.0 / sqrt(r[0][2] * r[0][2] + r[1][2] * r[1][2] + m3_raw * m3_raw);
  const T m1 = r[0][2] * inv_norm;
  const T m2 = r[1][2] * inv_norm;
  const T c = m3_raw * inv_norm;
  const T w1 = -m2;
  const T w2 = m1;
  const T k = 1.0 / (1.0 + c);
  const RotationEntries<T> f = {
      {{c + w1 * w1 * k, w1 * w2 * k, w2}, {w1 * w2 * k, c + w2 * w2 * k, -w1}, {-w2, w1, c}}};
  const T ch = cos(half_torsion);
  const T sh = sin(half_torsion);
  RotationEntries<T> m;
  for (int i = 0; i < 3; ++i) {
    m[i][0] = ch * f[i][0] + sh * f[i][1];
    m[i][1] = ch * f[i][1] - sh * f[i][0];
    m[i][2] = f[i][2];
  }
  return m;
}

}  // namespace clinch
