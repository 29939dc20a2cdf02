#include "src/kinematics/translational_measures.hpp"

#include "src/kinematics/rotation_math.hpp"

namespace clinch {

bool distance_measure(const Vector3& d, double& value, Matrix6x12& b, int row, Matrix12* hessian) {
  const double length = d.stableNorm();
  value = length;
  if (length == 0.0) return false;
  const Vector3 q = d / length;
  b.row(row).segment<3>(0) = -q.transpose();
  b.row(row).segment<3>(6) = q.transpose();
  if (hessian) {
    // δ²c = (1/L) δdᵀ(I − q qᵀ) δd with δd = δu_b − δu_a.
    const Matrix3 k = (Matrix3::Identity() - q * q.transpose()) / length;
    Matrix12& h = *hessian;
    h.setZero();
    h.block<3, 3>(0, 0) = k;
    h.block<3, 3>(6, 6) = k;
    h.block<3, 3>(0, 6) = -k;
    h.block<3, 3>(6, 0) = -k;
  }
  return true;
}

Jet<12> frame_a_projection(const Vector3& e, const Vector3& d, bool corotating, bool want_hessian) {
  Jet<12> c;
  c.v = e.dot(d);
  c.g.segment<3>(0) = -e;
  c.g.segment<3>(6) = e;
  if (!corotating) return c;
  c.g.segment<3>(3) = e.cross(d);
  if (want_hessian) {
    // §3.7 frame-a projection: H_θθ = ½(e dᵀ + d eᵀ) − (e·d) I, H_θd = ê with δd = δu_b − δu_a.
    const Matrix3 e_hat = skew(e);
    c.h.block<3, 3>(3, 3) =
        0.5 * (e * d.transpose() + d * e.transpose()) - c.v * Matrix3::Identity();
    c.h.block<3, 3>(3, 6) = e_hat;
    c.h.block<3, 3>(6, 3) = e_hat.transpose();
    c.h.block<3, 3>(3, 0) = -e_hat;
    c.h.block<3, 3>(0, 3) = -e_hat.transpose();
  }
  return c;
}

}  // namespace clinch
