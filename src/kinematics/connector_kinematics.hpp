// Kinematics of one connector element (connection-types.md §2–§3): maps the 12 nodal DOFs
// [u_a, θ_a, u_b, θ_b] to the positions p_i of the six components, their B rows and, under
// NLGEOM=YES, their second variations H_i. Behaviours and the assembler consume the result.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/small_types.hpp"
#include "src/model/section_model.hpp"

namespace clinch {

// What the assembler gives to build the kinematics of one connector element.
struct ConnectorSetup {
  std::vector<std::string> type_names;  // canonical names as in ConnectorSection::type_names
  Vector3 xa0 = Vector3::Zero();        // initial positions (a ground end sits at the other
  Vector3 xb0 = Vector3::Zero();        // node's position, §1.2)
  Matrix3 ea0 = Matrix3::Identity();    // initial triads (columns e1 e2 e3, global components),
  Matrix3 eb0 = Matrix3::Identity();    // defaults already applied (global at a; a's at b)
  bool has_orientation_a = false;       // AXIAL direction rule (§2.2)
  bool has_orientation_b = false;
  bool rotations_a = true;  // node a has active rotation DOFs (JOIN co-rotates only then, §2.2)
  bool two_d = false;       // CONN2D2: components 1, 2, 6 only
  double length_tolerance = 1e-8;  // §2.2 tol (1e-8·max(1, bounding-box diagonal))
  // Some step runs with NLGEOM=NO: keep the linearised kinematics (about 0.6 kB per connector,
  // which a deck that is NLGEOM throughout never reads).
  bool linearised = true;
};

// Current state of one node (ground: u = 0, R = I, theta = 0).
struct NodePose {
  Vector3 u = Vector3::Zero();             // displacement
  Vector3 theta = Vector3::Zero();         // NLGEOM=NO: small rotation vector
  Matrix3 rotation = Matrix3::Identity();  // NLGEOM=YES: R
};

struct KinematicsResult {
  ComponentMask existing = 0;  // available | constrained
  Vector6 position;            // p_i (unwrapped, §3.6), 0 for non-existing components
  Vector6 change;              // c_i = p_i − p_i(0)
  Matrix6x12 b;                // row i-1 = B_i (zero rows for non-existing components)
  // H_i, written only when requested, under NLGEOM=YES and for existing components.
  std::array<Matrix12, 6> h;
  bool ok = true;  // false: a parameterisation is singular or out of its domain (message says)
  std::string message;
};

class ConnectorKinematics {
 public:
  // nullopt and *error on a setup the spec rejects (unknown or unsupported type, an invalid
  // combination, AXIAL without a direction, zero-length LINK).
  static std::optional<ConnectorKinematics> create(const ConnectorSetup& setup, std::string* error);

  ComponentMask available() const { return available_; }
  ComponentMask constrained() const { return constrained_; }
  const Vector6& initial_position() const { return initial_position_; }

  // `last_converged` holds the positions of the last converged increment; angles are unwrapped
  // towards it (§3.6) and it keeps the sweep θ at zero flexion. Pass initial_position() at the
  // start. Does not allocate unless it reports a failure.
  void evaluate(const NodePose& a, const NodePose& b, bool nlgeom, const Vector6& last_converged,
                bool want_hessian, KinematicsResult& out) const;

 private:
  // The translational and rotational families of §2.1 (an assembled type is one of each).
  enum class Translation : std::uint8_t { None, Axial, Link, FrameA, Radial, MidFrame };
  enum class Rotation : std::uint8_t {
    None,
    Cardan,
    Euler,
    RotationVector,
    FlexionTorsion,
    ProjectionFlexionTorsion
  };

  // A component that NLGEOM=NO evaluates as the norm of a linearised 2-vector because the
  // norm is not differentiable at its initial value: RADIAL-THRUST r with r0 ≤ tol (§2.2) and
  // the flexion α of FLEXION-TORSION with α0 = 0 (§2.3).
  struct LinearNorm {
    int row = -1;
    double tolerance = 0;
    Eigen::Vector2d value = Eigen::Vector2d::Zero();
    Eigen::Matrix<double, 2, 12> b = Eigen::Matrix<double, 2, 12>::Zero();
  };
  // NLGEOM=NO: positions p = p0 + B0·q, with the norms above where they apply.
  struct Linearised {
    Matrix6x12 b0 = Matrix6x12::Zero();
    bool ok = true;
    std::string error;  // why B0 could not be formed (the initial pose is singular)
    // Only where they apply (none for most connectors: 450 bytes each saved per connector).
    std::vector<LinearNorm> norms;
  };

  ConnectorKinematics() = default;
  void evaluate_exact(const Vector3& d, const Matrix3& ea, const Matrix3& eb,
                      const Vector6* reference, bool want_hessian, KinematicsResult& out) const;
  void evaluate_linear(const NodePose& a, const NodePose& b, const Vector6& last_converged,
                       KinematicsResult& out) const;

  Translation translation_ = Translation::None;
  Rotation rotation_ = Rotation::None;
  bool corotating_a_ = true;      // the frame-a projections turn with R_a
  bool fixed_direction_ = false;  // AXIAL with l0 ≤ tol: u1 = n·(d − d0)
  Vector3 direction_ = Vector3::Zero();
  Vector3 d0_ = Vector3::Zero();
  double length_tolerance_ = 1e-8;
  Matrix3 ea0_ = Matrix3::Identity();
  Matrix3 eb0_ = Matrix3::Identity();
  ComponentMask available_ = 0;
  ComponentMask constrained_ = 0;
  ComponentMask existing_ = 0;
  ComponentMask computed_ = 0;  // components the 3-D formulas produce
  Vector6 initial_position_ = Vector6::Zero();
  std::shared_ptr<const Linearised> linearised_;  // null unless ConnectorSetup::linearised
};

}  // namespace clinch
