#include "src/model/orientation_triad.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/model/model.hpp"

namespace clinch {
namespace {

Vec3 sub(const Vec3& x, const Vec3& y) { return {x[0] - y[0], x[1] - y[1], x[2] - y[2]}; }
Vec3 cross(const Vec3& x, const Vec3& y) {
  return {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
}
double norm(const Vec3& x) { return length_of(x); }
Vec3 scaled(const Vec3& x, double s) { return {x[0] * s, x[1] * s, x[2] * s}; }
Vec3 combine(double s, const Vec3& x, double t, const Vec3& y) {
  return {s * x[0] + t * y[0], s * x[1] + t * y[1], s * x[2] + t * y[2]};
}

}  // namespace

Triad rotate_about_local_axis(const Triad& triad, int axis, double angle_degrees) {
  if (angle_degrees == 0 || axis < 1 || axis > 3) return triad;
  const double theta = angle_degrees * std::numbers::pi / 180.0;
  const double c = std::cos(theta), s = std::sin(theta);
  // The two axes after `axis` in cyclic order: (2, 3) for k = 1, (3, 1) for k = 2, (1, 2) for 3.
  const int i = axis % 3;
  const int j = (axis + 1) % 3;
  Triad out = triad;
  out[i] = combine(c, triad[i], s, triad[j]);
  out[j] = combine(-s, triad[i], c, triad[j]);
  return out;
}

TriadStatus orientation_triad(const Vec3& a, const Vec3& b, const Vec3& c, int axis,
                              double angle_degrees, Triad& out) {
  const Vec3 along = sub(a, c);
  const double length = norm(along);
  // keywords.md §6 step 1: |a − c| ≤ 1e-12·max(1, |a|, |c|).
  if (!(length > 1e-12 * std::max({1.0, norm(a), norm(c)}))) return TriadStatus::PointAAtOrigin;
  const Vec3 e1 = scaled(along, 1.0 / length);
  const Vec3 in_plane = sub(b, c);
  const Vec3 w = cross(e1, in_plane);
  const double w_norm = norm(w);
  // Step 2: |w| ≤ 1e-10·|b − c| (b on the 1-axis, or b = c).
  if (!(w_norm > 1e-10 * norm(in_plane))) return TriadStatus::PointBOnAxis;
  const Vec3 e3 = scaled(w, 1.0 / w_norm);
  const Vec3 e2 = cross(e3, e1);
  out = rotate_about_local_axis(Triad{e1, e2, e3}, axis, angle_degrees);
  return TriadStatus::Ok;
}

Triad placed_triad(const Model& model, const Orientation& orientation, std::int32_t instance) {
  if (orientation.part == 0 || instance < 0 ||
      static_cast<std::size_t>(instance) >= model.instances.size()) {
    return orientation.triad;
  }
  const Instance& placed = model.instances[static_cast<std::size_t>(instance)];
  return {placed.rotate(orientation.triad[0]), placed.rotate(orientation.triad[1]),
          placed.rotate(orientation.triad[2])};
}

}  // namespace clinch
