// The worked examples of connection-types.md §5, one test each. Values from plain arithmetic are
// compared to 1e-12 relative; values that pass through trigonometric chains (exp, atan2, asin)
// to 1e-9, as §5 prescribes. Quantities that are zero by construction are compared to an
// absolute 1e-14 (a few ulps of the unit-sized inputs).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "src/kinematics/connector_kinematics.hpp"
#include "src/kinematics/rotation_math.hpp"

namespace clinch {
namespace {

constexpr double kExact = 1e-12;
constexpr double kTrig = 1e-9;
constexpr double kZero = 1e-14;

// ORI30 of §5: rotated 30° about global Z.
Matrix3 ori30() {
  Matrix3 e;
  e << 0.8660254037844387, -0.5, 0, 0.5, 0.8660254037844387, 0, 0, 0, 1;
  return e;
}

void expect_rel(double actual, double expected, double tolerance) {
  EXPECT_NEAR(actual, expected, tolerance * std::max(1.0, std::abs(expected)));
}

ConnectorKinematics make(const ConnectorSetup& setup) {
  std::string error;
  std::optional<ConnectorKinematics> k = ConnectorKinematics::create(setup, &error);
  EXPECT_TRUE(k.has_value()) << error;
  return *k;
}

KinematicsResult run(const ConnectorKinematics& k, const NodePose& a, const NodePose& b,
                     bool nlgeom, bool hessian = false) {
  KinematicsResult out;
  k.evaluate(a, b, nlgeom, k.initial_position(), hessian, out);
  EXPECT_TRUE(out.ok) << out.message;
  return out;
}

ConnectorSetup example_51(const char* type, bool orientation) {
  ConnectorSetup s;
  s.type_names = {type};
  s.xa0 = Vector3(0, 0, 0);
  s.xb0 = Vector3(1, 0, 0);
  if (orientation) {
    s.ea0 = s.eb0 = ori30();
    s.has_orientation_a = true;
  }
  return s;
}

TEST(KinematicsExamples, CartesianCasesAAndB) {
  const ConnectorKinematics k = make(example_51("CARTESIAN", true));
  expect_rel(k.initial_position()[0], 0.8660254037844387, kExact);
  expect_rel(k.initial_position()[1], -0.5, kExact);
  EXPECT_NEAR(k.initial_position()[2], 0, kZero);
  NodePose a, b;
  b.u = Vector3(0.1, 0.2, 0.05);
  KinematicsResult r = run(k, a, b, false);
  expect_rel(r.change[0], 0.18660254037844387, kExact);
  expect_rel(r.change[1], 0.12320508075688777, kExact);
  expect_rel(r.change[2], 0.05, kExact);

  a.theta = Vector3(0, 0, 0.01);
  r = run(k, a, b, false);
  expect_rel(r.change[0], 0.18160254037844387, kExact);
  expect_rel(r.change[1], 0.11454482671904339, kExact);
  expect_rel(r.change[2], 0.05, kExact);

  a.rotation = rotation_exp(a.theta);
  r = run(k, a, b, true);
  expect_rel(r.change[0], 0.18278202302623725, kTrig);
  expect_rel(r.change[1], 0.11269781634133713, kTrig);
  expect_rel(r.change[2], 0.05, kTrig);
  EXPECT_EQ(r.existing, 0b000111);
}

TEST(KinematicsExamples, CartesianB0Rows) {
  const ConnectorKinematics k = make(example_51("CARTESIAN", true));
  const KinematicsResult r = run(k, NodePose{}, NodePose{}, false);
  const double c = 0.8660254037844387;
  Matrix6x12 expected = Matrix6x12::Zero();
  expected.row(0) << -c, -0.5, 0, 0, 0, -0.5, c, 0.5, 0, 0, 0, 0;
  expected.row(1) << 0.5, -c, 0, 0, 0, -c, -0.5, c, 0, 0, 0, 0;
  expected.row(2) << 0, 0, -1, 0, 1, 0, 0, 0, 1, 0, 0, 0;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 12; ++j) EXPECT_NEAR(r.b(i, j), expected(i, j), kExact) << i << "," << j;
  }
}

TEST(KinematicsExamples, AxialExactAndTangent) {
  const ConnectorKinematics k = make(example_51("AXIAL", false));
  NodePose a, b;
  b.u = Vector3(0.1, 0.2, 0.05);
  expect_rel(run(k, a, b, false).change[0], 0.1, kExact);
  const KinematicsResult r = run(k, a, b, true, true);
  expect_rel(r.change[0], 0.11915146427996959, kExact);
  EXPECT_EQ(r.existing, 0b000001);

  // K = k BᵀB + f H on the (u_a, u_b) blocks must equal [K_d −K_d; −K_d K_d] of §3.7.
  const double stiffness = 1000;
  const double force = stiffness * r.change[0];
  expect_rel(force, 119.15146427996959, kExact);
  const double length = 1.1191514642799696;
  expect_rel(force / length, 106.46589678245944, kExact);
  const Vector3 q = Vector3(1.1, 0.2, 0.05) / length;
  const Matrix3 kd = stiffness * q * q.transpose() +
                     106.46589678245944 * (Matrix3::Identity() - q * q.transpose());
  const Matrix12 ke = stiffness * r.b.row(0).transpose() * r.b.row(0) + force * r.h[0];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const double scale = kExact * stiffness;
      EXPECT_NEAR(ke(6 + i, 6 + j), kd(i, j), scale);
      EXPECT_NEAR(ke(i, j), kd(i, j), scale);
      EXPECT_NEAR(ke(i, 6 + j), -kd(i, j), scale);
      EXPECT_NEAR(ke(6 + i, j), -kd(i, j), scale);
      EXPECT_NEAR(ke(3 + i, 3 + j), 0, kZero);
    }
  }
}

TEST(KinematicsExamples, SlotResiduals) {
  const ConnectorKinematics k = make(example_51("SLOT", true));
  EXPECT_EQ(k.available(), 0b000001);
  EXPECT_EQ(k.constrained(), 0b000110);
  NodePose a, b;
  b.u = Vector3(0.1, 0.2, 0.05);
  const KinematicsResult r = run(k, a, b, false);
  expect_rel(r.change[0], 0.18660254037844387, kExact);
  expect_rel(r.change[1], 0.12320508075688777, kExact);
  expect_rel(r.change[2], 0.05, kExact);
}

// §5.2: CARDAN and ROTATION with ORI30 at a, node b turned about global X by t.
struct RotationRow {
  double t;
  std::array<double, 3> linear, cardan, rotation;
};

TEST(KinematicsExamples, CardanAndRotationTable) {
  const RotationRow rows[] = {
      {0.3,
       {0.25980762113533160, -0.15, 0},
       {0.26174700590426947, -0.14830313118757030, 0.01955575930681060},
       {0.25980762113533157, -0.15, 0}},
      {1.2,
       {1.03923048454132650, -0.6, 0},
       {1.14883758162471450, -0.48478658167115746, 0.31736587564870680},
       {1.03923048454132630, -0.6, 0}},
  };
  ConnectorSetup setup;
  setup.ea0 = setup.eb0 = ori30();
  setup.has_orientation_a = true;
  setup.type_names = {"CARDAN"};
  const ConnectorKinematics cardan = make(setup);
  setup.type_names = {"ROTATION"};
  const ConnectorKinematics rotation = make(setup);
  for (const RotationRow& row : rows) {
    NodePose a, b;
    b.theta = Vector3(row.t, 0, 0);
    b.rotation = rotation_exp(b.theta);
    const KinematicsResult linear = run(cardan, a, b, false);
    const KinematicsResult exact = run(cardan, a, b, true);
    const KinematicsResult phi = run(rotation, a, b, true);
    for (int k = 0; k < 3; ++k) {
      expect_rel(linear.change[3 + k], row.linear[k], kExact);
      expect_rel(exact.change[3 + k], row.cardan[k], kTrig);
      expect_rel(phi.change[3 + k], row.rotation[k], kTrig);
    }
  }
}

Matrix3 hinge_z() {
  Matrix3 e;
  e.col(0) = Vector3(0, 0, 1);
  e.col(1) = Vector3(1, 0, 0);
  e.col(2) = Vector3(0, 1, 0);
  return e;
}

TEST(KinematicsExamples, Hinge) {
  ConnectorSetup setup;
  setup.type_names = {"HINGE"};
  setup.ea0 = setup.eb0 = hinge_z();
  setup.has_orientation_a = true;
  const ConnectorKinematics k = make(setup);
  EXPECT_EQ(k.available(), 0b001000);
  EXPECT_EQ(k.constrained(), 0b110111);

  NodePose a, b;
  b.theta = Vector3(0, 0, 0.5);
  b.rotation = rotation_exp(b.theta);
  for (bool nlgeom : {false, true}) {
    const KinematicsResult r = run(k, a, b, nlgeom);
    expect_rel(r.change[3], 0.5, nlgeom ? kTrig : kExact);
    for (int i : {0, 1, 2, 4, 5}) EXPECT_NEAR(r.change[i], 0, kZero) << i;
  }

  b.theta = Vector3(0.01, 0, 0.5);
  const KinematicsResult r = run(k, a, b, false);
  expect_rel(r.change[3], 0.5, kExact);
  expect_rel(r.change[4], 0.01, kExact);
  EXPECT_NEAR(r.change[5], 0, kZero);
  for (int i : {0, 1, 2}) EXPECT_NEAR(r.change[i], 0, kZero);
  const double row4[12] = {0, 0, 0, 0, 0, -1, 0, 0, 0, 0, 0, 1};
  for (int j = 0; j < 12; ++j) EXPECT_NEAR(r.b(3, j), row4[j], kExact) << j;
}

TEST(KinematicsExamples, WeldWithOffset) {
  ConnectorSetup setup;
  setup.type_names = {"WELD"};
  setup.xb0 = Vector3(0, 0, 1);
  setup.rotations_a = false;  // WELD activates the rotations of a itself (through ALIGN)
  const ConnectorKinematics k = make(setup);
  EXPECT_EQ(k.constrained(), 0b111111);
  NodePose a, b;
  a.theta = Vector3(0.01, 0, 0);
  b.u = Vector3(0, -0.01, 0);
  b.theta = a.theta;
  KinematicsResult r = run(k, a, b, false);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(r.change[i], 0, kZero) << i;
  b.u = Vector3::Zero();
  r = run(k, a, b, false);
  expect_rel(r.change[1], 0.01, kExact);
}

TEST(KinematicsExamples, AxialRigidSwing) {
  const ConnectorKinematics k = make(example_51("AXIAL", false));
  NodePose a, b;
  b.u = Vector3(-1, 1, 0);
  EXPECT_NEAR(run(k, a, b, true).change[0], 0, kZero);
  expect_rel(run(k, a, b, false).change[0], -1.0, kExact);
}

TEST(KinematicsExamples, CartesianWithRotatingNodeA) {
  const ConnectorKinematics k = make(example_51("CARTESIAN", true));
  NodePose a, b;
  a.theta = Vector3(0, 0, std::numbers::pi / 2);
  a.rotation = rotation_exp(a.theta);
  b.u = Vector3(-1, 1, 0);
  const KinematicsResult exact = run(k, a, b, true);
  // The rigid rotation of d0 by π/2 passes through cos(π/2) ≈ 6e-17: trigonometric tolerance.
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(exact.change[i], 0, kTrig) << i;
  const KinematicsResult linear = run(k, a, b, false);
  expect_rel(linear.change[0], -1.1514235671818869, kExact);
  expect_rel(linear.change[1], 0.005675880608775108, kExact);
  EXPECT_NEAR(linear.change[2], 0, kZero);
}

TEST(KinematicsExamples, CardanTwoAxisRotation) {
  ConnectorSetup setup;
  setup.type_names = {"CARDAN"};
  const ConnectorKinematics k = make(setup);
  NodePose a, b;
  b.theta = (std::numbers::pi / 2) * Vector3(1, 1, 0) / std::sqrt(2.0);
  b.rotation = rotation_exp(b.theta);
  const KinematicsResult exact = run(k, a, b, true);
  expect_rel(exact.change[3], 1.5707963267948966, kTrig);
  expect_rel(exact.change[4], 0.7853981633974484, kTrig);
  expect_rel(exact.change[5], -0.7853981633974483, kTrig);
  const KinematicsResult linear = run(k, a, b, false);
  expect_rel(linear.change[3], 1.1107207345395915, kExact);
  expect_rel(linear.change[4], 1.1107207345395915, kExact);
  EXPECT_NEAR(linear.change[5], 0, kZero);
}

Matrix3 rx(double t) { return rotation_exp(Vector3(t, 0, 0)); }
Matrix3 rz(double t) { return rotation_exp(Vector3(0, 0, t)); }

TEST(KinematicsExamples, FlexionTorsionAndProjection) {
  ConnectorSetup setup;
  setup.has_orientation_a = true;  // the global axes, given explicitly (§5.5)
  NodePose a, b;
  b.theta = rotation_log(rx(0.3) * rz(0.5));
  b.rotation = rotation_exp(b.theta);

  setup.type_names = {"FLEXION-TORSION"};
  const KinematicsResult ft = run(make(setup), a, b, true);
  expect_rel(ft.change[3], 0.3, kTrig);
  expect_rel(ft.change[4], 0.5, kTrig);
  EXPECT_NEAR(ft.change[5], 0, kTrig);

  setup.type_names = {"PROJECTION FLEXION-TORSION"};
  const KinematicsResult pft = run(make(setup), a, b, true);
  expect_rel(pft.change[3], 0.2906737265131934, kTrig);
  expect_rel(pft.change[4], -0.07422118777635688, kTrig);
  expect_rel(pft.change[5], 0.5, kTrig);
}

TEST(KinematicsExamples, RejectedSetups) {
  std::string error;
  ConnectorSetup setup;
  setup.type_names = {"AXIAL"};  // coincident nodes, no orientation (§2.2)
  EXPECT_FALSE(ConnectorKinematics::create(setup, &error));
  EXPECT_NE(error.find("axial-direction-undefined"), std::string::npos) << error;
  setup.type_names = {"LINK"};
  EXPECT_FALSE(ConnectorKinematics::create(setup, &error));
  EXPECT_NE(error.find("link-zero-length"), std::string::npos) << error;
  setup.type_names = {"CVJOINT"};
  EXPECT_FALSE(ConnectorKinematics::create(setup, &error));
  EXPECT_NE(error.find("not supported by clinch"), std::string::npos) << error;
  setup.type_names = {"SLOT", "CARTESIAN"};
  EXPECT_FALSE(ConnectorKinematics::create(setup, &error));
  setup.type_names = {"HINGE", "CARDAN"};
  EXPECT_FALSE(ConnectorKinematics::create(setup, &error));
  setup.type_names = {"HINGE"};
  setup.two_d = true;
  EXPECT_FALSE(ConnectorKinematics::create(setup, &error));
}

TEST(KinematicsExamples, EulerSingularAtAlignedFrames) {
  ConnectorSetup setup;
  setup.type_names = {"EULER"};
  const std::optional<ConnectorKinematics> k = ConnectorKinematics::create(setup, nullptr);
  ASSERT_TRUE(k);
  KinematicsResult out;
  k->evaluate(NodePose{}, NodePose{}, true, k->initial_position(), false, out);
  EXPECT_FALSE(out.ok);
  EXPECT_NE(out.message.find("EULER parameterisation singular"), std::string::npos);
}

TEST(KinematicsExamples, AxialFixedDirectionAtGround) {
  // A ground end sits on the live node (l0 = 0): u1 = n·(d − d0) with n = e1 at a (§2.2).
  ConnectorSetup setup;
  setup.type_names = {"AXIAL"};
  setup.xa0 = setup.xb0 = Vector3(2, 3, 4);
  setup.ea0 = setup.eb0 = ori30();
  setup.has_orientation_a = true;
  const ConnectorKinematics k = make(setup);
  NodePose a, b;
  b.u = Vector3(0.1, 0.2, 0.05);
  for (bool nlgeom : {false, true}) {
    expect_rel(run(k, a, b, nlgeom).change[0], 0.18660254037844387, kExact);
  }
}

TEST(KinematicsExamples, TwoDimensionalMasks) {
  ConnectorSetup setup;
  setup.two_d = true;
  setup.xb0 = Vector3(1, 0, 0);
  setup.type_names = {"CARTESIAN", "ROTATION"};
  const ConnectorKinematics k = make(setup);
  NodePose a, b;
  b.u = Vector3(0.1, 0.2, 0);
  b.theta = Vector3(0, 0, 2.5);
  b.rotation = rotation_exp(b.theta);
  const KinematicsResult r = run(k, a, b, true);
  EXPECT_EQ(r.existing, 0b100011);
  expect_rel(r.change[0], 0.1, kExact);
  expect_rel(r.change[1], 0.2, kExact);
  expect_rel(r.change[5], 2.5, kTrig);
  for (int i : {2, 3, 4}) {
    EXPECT_EQ(r.position[i], 0);
    EXPECT_EQ(r.b.row(i).norm(), 0);
  }
}

}  // namespace
}  // namespace clinch
