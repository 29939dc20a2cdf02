#include "src/kinematics/connector_kinematics.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string_view>

#include "src/kinematics/rotational_measures.hpp"
#include "src/kinematics/translational_measures.hpp"
#include "src/model/connection_types.hpp"

namespace clinch {
namespace {

// Below this flexion angle (rad) α is treated as zero: its direction n and the sweep θ are
// undefined there (§2.3) and α = |α n| is not differentiable.
constexpr double kFlexionTolerance = 1e-8;
// §2.2: a run stops when |sin β| < 1e-8 (EULER); the same bound on cos β detects the gimbal
// lock of CARDAN, where β leaves (−π/2, π/2).
constexpr double kSingularSine = 1e-8;

// The θ_a and θ_b columns of the element DOF vector (§3.1): the parameters of a Jet<6>.
constexpr std::array<int, 6> kRotationColumns = {3, 4, 5, 9, 10, 11};

constexpr ComponentMask kTranslations = 0b000111;
constexpr ComponentMask kRotations = 0b111000;

void store(double value, const Jet<12>& jet, int row, bool want_hessian, KinematicsResult& out) {
  out.position[row] = value;
  out.b.row(row) = jet.g.transpose();
  if (want_hessian) out.h[row] = jet.h;
}

void store(double value, const Jet<6>& jet, int row, bool want_hessian, KinematicsResult& out) {
  out.position[row] = value;
  for (int k = 0; k < 6; ++k) out.b(row, kRotationColumns[k]) = jet.g[k];
  if (!want_hessian) return;
  Matrix12& h = out.h[row];
  h.setZero();
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) h(kRotationColumns[i], kRotationColumns[j]) = jet.h(i, j);
  }
}

// A component whose variations vanish at this state (the B row stays zero).
void store_constant(double value, int row, bool want_hessian, KinematicsResult& out) {
  out.position[row] = value;
  if (want_hessian) out.h[row].setZero();
}

double unwrap_towards(double principal, const Vector6* reference, int row) {
  return reference ? unwrap_angle(principal, (*reference)[row]) : principal;
}

}  // namespace

std::optional<ConnectorKinematics> ConnectorKinematics::create(const ConnectorSetup& setup,
                                                               std::string* error) {
  auto reject = [error](std::string message) -> std::optional<ConnectorKinematics> {
    if (error) *error = std::move(message);
    return std::nullopt;
  };
  ConnectorKinematics k;
  std::vector<const ConnectionTypeInfo*> infos;
  bool join = false;
  bool assembled = false;
  for (const std::string& name : setup.type_names) {
    const ConnectionTypeInfo* info = find_connection_type(name);
    if (!info) return reject(fmt::format("unknown connection type '{}'", name));
    if (info->support == V1Support::Converted) info = &converted_type();  // §1.5 rule 4
    if (info->support != V1Support::Supported) {
      return reject(fmt::format("connection type '{}' is not supported by clinch", info->name));
    }
    if (setup.two_d && !info->allowed_2d) {
      return reject(fmt::format("connection type '{}' is not allowed on CONN2D2", info->name));
    }
    const std::string_view n = info->name;
    Translation t = Translation::None;
    Rotation r = Rotation::None;
    if (n == "AXIAL") {
      t = Translation::Axial;
    } else if (n == "LINK") {
      t = Translation::Link;
    } else if (n == "CARTESIAN" || n == "SLOT" || n == "SLIDE-PLANE") {
      t = Translation::FrameA;
    } else if (n == "JOIN") {
      t = Translation::FrameA;
      join = true;
    } else if (n == "RADIAL-THRUST") {
      t = Translation::Radial;
    } else if (n == "PROJECTION CARTESIAN") {
      t = Translation::MidFrame;
    } else if (n == "ALIGN" || n == "CARDAN" || n == "REVOLUTE" || n == "UNIVERSAL") {
      r = Rotation::Cardan;  // §2.2: one Cardan parameterisation, different constraints
    } else if (n == "EULER") {
      r = Rotation::Euler;
    } else if (n == "ROTATION") {
      r = Rotation::RotationVector;
    } else if (n == "FLEXION-TORSION") {
      r = Rotation::FlexionTorsion;
    } else if (n == "PROJECTION FLEXION-TORSION") {
      r = Rotation::ProjectionFlexionTorsion;
    } else if (n == "BEAM" || n == "WELD" || n == "HINGE" || n == "UJOINT") {
      t = Translation::FrameA;  // JOIN + ALIGN, REVOLUTE or UNIVERSAL
      r = Rotation::Cardan;
      join = true;
    } else if (n == "CYLINDRICAL" || n == "PLANAR" || n == "TRANSLATOR") {
      t = Translation::FrameA;  // SLOT or SLIDE-PLANE + REVOLUTE or ALIGN
      r = Rotation::Cardan;
    } else if (n == "BUSHING") {
      t = Translation::MidFrame;
      r = Rotation::ProjectionFlexionTorsion;
    } else {
      return reject(fmt::format("connection type '{}' is not supported by clinch", n));
    }
    // §1.5 rule 1: one assembled type alone, or at most one translational and one rotational.
    const bool is_assembled = info->kind == ConnectionKind::Assembled;
    if ((is_assembled && !infos.empty()) || assembled ||
        (t != Translation::None && k.translation_ != Translation::None) ||
        (r != Rotation::None && k.rotation_ != Rotation::None)) {
      return reject(
          fmt::format("connection type '{}' cannot be combined with '{}'", n, infos.front()->name));
    }
    assembled = is_assembled;
    if (t != Translation::None) k.translation_ = t;
    if (r != Rotation::None) k.rotation_ = r;
    infos.push_back(info);
  }
  if (infos.empty()) return reject("the connector section names no connection type");

  const ConnectionSummary summary = summarize_connection(infos, setup.two_d);
  k.available_ = summary.available;
  k.constrained_ = summary.constrained;
  k.existing_ = static_cast<ComponentMask>(summary.available | summary.constrained);
  switch (k.translation_) {
    case Translation::None:
      break;
    case Translation::Axial:
    case Translation::Link:
      k.computed_ = 0b000001;
      break;
    case Translation::Radial:
      k.computed_ = 0b000101;
      break;
    case Translation::FrameA:
    case Translation::MidFrame:
      k.computed_ = kTranslations;
      break;
  }
  if (k.rotation_ != Rotation::None) k.computed_ |= kRotations;

  k.d0_ = setup.xb0 - setup.xa0;
  k.length_tolerance_ = setup.length_tolerance;
  k.ea0_ = setup.ea0;
  k.eb0_ = setup.eb0;
  // §2.2 JOIN: the frame of a co-rotates when node a has active rotations; a rotational part of
  // the same section activates them itself.
  k.corotating_a_ = !join || setup.rotations_a || k.rotation_ != Rotation::None;
  const double l0 = k.d0_.stableNorm();
  if (k.translation_ == Translation::Link && l0 <= setup.length_tolerance) {
    return reject("link-zero-length: LINK joins two coincident points (§2.2)");
  }
  if (k.translation_ == Translation::Axial && l0 <= setup.length_tolerance) {
    // §2.2: a fixed direction from the orientation at a, else at b.
    if (!setup.has_orientation_a && !setup.has_orientation_b) {
      return reject(
          "axial-direction-undefined: AXIAL between coincident points needs an orientation");
    }
    k.fixed_direction_ = true;
    k.direction_ = setup.has_orientation_a ? setup.ea0.col(0) : setup.eb0.col(0);
  }

  KinematicsResult initial;
  k.evaluate_exact(k.d0_, k.ea0_, k.eb0_, nullptr, false, initial);
  k.initial_position_ = initial.position;
  if (!setup.linearised) return k;
  auto linear = std::make_shared<Linearised>();
  linear->b0 = initial.b;
  linear->ok = initial.ok;
  linear->error = initial.message;
  if (k.translation_ == Translation::Radial && k.initial_position_[0] <= setup.length_tolerance &&
      has_component(k.existing_, 1)) {
    LinearNorm& norm = linear->norms.emplace_back();
    norm.row = 0;
    norm.tolerance = setup.length_tolerance;
    for (int i = 0; i < 2; ++i) {
      const Jet<12> x = frame_a_projection(k.ea0_.col(i), k.d0_, true, false);
      norm.value[i] = x.v;
      norm.b.row(i) = x.g.transpose();
    }
  }
  if (k.rotation_ == Rotation::FlexionTorsion && k.initial_position_[3] <= kFlexionTolerance) {
    LinearNorm& norm = linear->norms.emplace_back();
    norm.row = 3;
    norm.tolerance = kFlexionTolerance;
    const std::array<Jet<6>, 2> v = flexion_vector(relative_rotation_jet<6>(k.ea0_, k.eb0_, 0, 3));
    for (int i = 0; i < 2; ++i) {
      norm.value[i] = v[i].v;
      for (int c = 0; c < 6; ++c) norm.b(i, kRotationColumns[c]) = v[i].g[c];
    }
  }
  k.linearised_ = std::move(linear);
  return k;
}

void ConnectorKinematics::evaluate(const NodePose& a, const NodePose& b, bool nlgeom,
                                   const Vector6& last_converged, bool want_hessian,
                                   KinematicsResult& out) const {
  out.existing = existing_;
  out.ok = true;
  if (!out.message.empty()) out.message.clear();
  if (!nlgeom) {
    evaluate_linear(a, b, last_converged, out);
    return;
  }
  const Vector3 d = d0_ + b.u - a.u;
  const bool frames = rotation_ != Rotation::None ||
                      (translation_ != Translation::Axial && translation_ != Translation::Link);
  if (frames) {
    const Matrix3 ea = corotating_a_ ? Matrix3(a.rotation * ea0_) : ea0_;
    const Matrix3 eb = b.rotation * eb0_;
    evaluate_exact(d, ea, eb, &last_converged, want_hessian, out);
  } else {
    evaluate_exact(d, ea0_, eb0_, &last_converged, want_hessian, out);
  }
  out.change = out.position - initial_position_;
}

void ConnectorKinematics::evaluate_exact(const Vector3& d, const Matrix3& ea, const Matrix3& eb,
                                         const Vector6* reference, bool want_hessian,
                                         KinematicsResult& out) const {
  out.position.setZero();
  out.b.setZero();
  const char* failure = nullptr;
  // 2πk added to the principal torsion by §3.6; the mid frame of BUSHING turns by half of it.
  double torsion_turn = 0;

  switch (rotation_) {
    case Rotation::None:
      break;
    case Rotation::Cardan: {
      const RotationEntries<Jet<6>> r = relative_rotation_jet<6>(ea, eb, 0, 3);
      if (1.0 - r[0][2].v * r[0][2].v < kSingularSine * kSingularSine) {
        failure = "CARDAN angle beta left (-pi/2, pi/2) (gimbal lock)";
      }
      const std::array<Jet<6>, 3> angles = cardan_angles(r);
      store(unwrap_towards(angles[0].v, reference, 3), angles[0], 3, want_hessian, out);
      store(angles[1].v, angles[1], 4, want_hessian, out);
      store(unwrap_towards(angles[2].v, reference, 5), angles[2], 5, want_hessian, out);
      break;
    }
    case Rotation::Euler: {
      const RotationEntries<Jet<6>> r = relative_rotation_jet<6>(ea, eb, 0, 3);
      if (1.0 - r[2][2].v * r[2][2].v < kSingularSine * kSingularSine) {
        failure = "EULER parameterisation singular";
      }
      const std::array<Jet<6>, 3> angles = euler_angles(r);
      store(unwrap_towards(angles[0].v, reference, 3), angles[0], 3, want_hessian, out);
      store(angles[1].v, angles[1], 4, want_hessian, out);
      store(unwrap_towards(angles[2].v, reference, 5), angles[2], 5, want_hessian, out);
      break;
    }
    case Rotation::RotationVector: {
      std::array<Jet<6>, 3> phi = rotation_vector(relative_rotation_jet<6>(ea, eb, 0, 3));
      const Vector3 principal(phi[0].v, phi[1].v, phi[2].v);
      const int turns = reference ? rotation_vector_turns(principal, reference->segment<3>(3)) : 0;
      if (turns != 0) {
        // §3.6: φ + 2πk φ/|φ| is the same rotation.
        const Jet<6> norm = sqrt(phi[0] * phi[0] + phi[1] * phi[1] + phi[2] * phi[2]);
        const Jet<6> scale = 1.0 + (2.0 * std::numbers::pi * turns) / norm;
        for (Jet<6>& component : phi) component = scale * component;
      }
      for (int k = 0; k < 3; ++k) store(phi[k].v, phi[k], 3 + k, want_hessian, out);
      break;
    }
    case Rotation::FlexionTorsion: {
      const RotationEntries<Jet<6>> r = relative_rotation_jet<6>(ea, eb, 0, 3);
      const std::array<Jet<6>, 2> v = flexion_vector(r);
      const double alpha = std::hypot(v[0].v, v[1].v);
      if (alpha > kFlexionTolerance) {
        store(alpha, sqrt(v[0] * v[0] + v[1] * v[1]), 3, want_hessian, out);
        const Jet<6> sweep = atan2(v[1], v[0]);
        store(unwrap_towards(sweep.v, reference, 5), sweep, 5, want_hessian, out);
      } else {
        // §2.3: at zero flexion the sweep keeps its last converged value and dθ = 0.
        store_constant(alpha, 3, want_hessian, out);
        store_constant(reference ? (*reference)[5] : 0.0, 5, want_hessian, out);
      }
      const Jet<6> torsion = torsion_angle(r);
      store(unwrap_towards(torsion.v, reference, 4), torsion, 4, want_hessian, out);
      break;
    }
    case Rotation::ProjectionFlexionTorsion: {
      const RotationEntries<Jet<6>> r = relative_rotation_jet<6>(ea, eb, 0, 3);
      const std::array<Jet<6>, 2> v = flexion_vector(r);
      const Jet<6> torsion = torsion_angle(r);
      const double beta = unwrap_towards(torsion.v, reference, 5);
      torsion_turn = beta - torsion.v;
      // n is fixed by F(α/2, n), so α n·e_i^m = α n·Rz(β/2) e_i (§2.3).
      const Jet<6> half = (torsion + torsion_turn) * 0.5;
      const Jet<6> c = cos(half);
      const Jet<6> s = sin(half);
      const Jet<6> alpha1 = v[0] * c + v[1] * s;
      const Jet<6> alpha2 = v[1] * c - v[0] * s;
      store(alpha1.v, alpha1, 3, want_hessian, out);
      store(alpha2.v, alpha2, 4, want_hessian, out);
      store(beta, torsion, 5, want_hessian, out);
      break;
    }
  }

  switch (translation_) {
    case Translation::None:
      break;
    case Translation::Axial:
      if (fixed_direction_) {
        out.position[0] = direction_.dot(d);
        out.b.row(0).segment<3>(0) = -direction_.transpose();
        out.b.row(0).segment<3>(6) = direction_.transpose();
        if (want_hessian) out.h[0].setZero();
        break;
      }
      [[fallthrough]];
    case Translation::Link:
      if (!distance_measure(d, out.position[0], out.b, 0, want_hessian ? &out.h[0] : nullptr)) {
        failure = "connector length is zero: the AXIAL or LINK direction is undefined";
      }
      break;
    case Translation::FrameA:
      for (int i = 0; i < 3; ++i) {
        const Jet<12> x = frame_a_projection(ea.col(i), d, corotating_a_, want_hessian);
        store(x.v, x, i, want_hessian, out);
      }
      break;
    case Translation::Radial: {
      const Jet<12> x1 = frame_a_projection(ea.col(0), d, true, want_hessian);
      const Jet<12> x2 = frame_a_projection(ea.col(1), d, true, want_hessian);
      const Jet<12> x3 = frame_a_projection(ea.col(2), d, true, want_hessian);
      const double radius = std::hypot(x1.v, x2.v);
      // §2.2: e_r = 0 in B whenever r ≤ tol.
      if (radius > length_tolerance_) {
        // Scaled by the radius, so that the squares neither overflow nor underflow at any
        // finite coordinates; the derivatives are those of sqrt(x1² + x2²).
        const Jet<12> y1 = x1 / radius, y2 = x2 / radius;
        store(radius, sqrt(y1 * y1 + y2 * y2) * radius, 0, want_hessian, out);
      } else {
        store_constant(radius, 0, want_hessian, out);
      }
      store(x3.v, x3, 2, want_hessian, out);
      break;
    }
    case Translation::MidFrame: {
      const RotationEntries<Jet<12>> r = relative_rotation_jet<12>(ea, eb, 3, 9);
      const RotationEntries<Jet<12>> m = mid_frame(r, (torsion_angle(r) + torsion_turn) * 0.5);
      std::array<Jet<12>, 3> local;
      for (int j = 0; j < 3; ++j) local[j] = frame_a_projection(ea.col(j), d, true, true);
      for (int i = 0; i < 3; ++i) {
        const Jet<12> x = local[0] * m[0][i] + local[1] * m[1][i] + local[2] * m[2][i];
        store(x.v, x, i, want_hessian, out);
      }
      break;
    }
  }

  if (computed_ != existing_) {
    for (int i = 0; i < 6; ++i) {
      if (has_component(existing_, i + 1)) continue;
      out.position[i] = 0;
      out.b.row(i).setZero();
    }
  }
  if (failure) {
    out.ok = false;
    out.message = failure;
  }
}

void ConnectorKinematics::evaluate_linear(const NodePose& a, const NodePose& b,
                                          const Vector6& last_converged,
                                          KinematicsResult& out) const {
  if (!linearised_) {  // a plan built for NLGEOM throughout (a bug of its caller)
    out.ok = false;
    out.message = "small-displacement kinematics were not prepared for this connector";
    return;
  }
  const Linearised& linear = *linearised_;
  if (!linear.ok) {
    out.ok = false;
    out.message = linear.error;
  }
  Vector12 q;
  q << a.u, a.theta, b.u, b.theta;
  out.b = linear.b0;
  out.change.noalias() = linear.b0 * q;
  out.position = initial_position_ + out.change;
  for (const LinearNorm& norm : linear.norms) {
    const Eigen::Vector2d v = norm.value + norm.b * q;
    const double length = v.stableNorm();
    out.position[norm.row] = length;
    out.change[norm.row] = length - initial_position_[norm.row];
    if (length > norm.tolerance) {
      out.b.row(norm.row) = v.transpose() * norm.b / length;
    } else {
      out.b.row(norm.row).setZero();
    }
    if (norm.row != 3) continue;
    // The sweep of FLEXION-TORSION: the direction of the linearised flexion vector.
    double sweep = last_converged[5];
    out.b.row(5).setZero();
    if (length > norm.tolerance) {
      sweep = unwrap_angle(std::atan2(v[1], v[0]), last_converged[5]);
      out.b.row(5) = (v[0] * norm.b.row(1) - v[1] * norm.b.row(0)) / (length * length);
    }
    out.position[5] = sweep;
    out.change[5] = sweep - initial_position_[5];
  }
}

}  // namespace clinch
