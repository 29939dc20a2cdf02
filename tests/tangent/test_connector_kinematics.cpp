// Finite-difference checks of connector kinematics (connection-types.md §3.7): for every v1 type
// and a few basic pairs, in both regimes, at seeded random poses away from singularities, B is
// compared with central differences of the positions and H with central differences of B.
// Rotations are perturbed multiplicatively (R ← exp(h ê_k) R), matching the spatial spins of B.
// Branch tracking (§3.6) is checked along rotations driven past π.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "base/jacobian_check.hpp"
#include "src/kinematics/connector_kinematics.hpp"
#include "src/kinematics/rotation_math.hpp"

namespace clinch {
namespace {

// §3.7: relative error below 1e-6 for B and 1e-4 for H. With h = 1e-6 the central difference
// of a position has truncation O(h²) ≈ 1e-12 and round-off ≈ 1e-16/h = 1e-10; with h = 1e-5
// for H (differences of B) the truncation is ≈ 1e-10 and the round-off ≈ 1e-11. Both sit far
// below the bounds.
constexpr double kStepB = 1e-6;
constexpr double kStepH = 1e-5;
constexpr double kToleranceB = 1e-6;
constexpr double kToleranceH = 1e-4;
constexpr int kPoses = 4;

// Initial relative orientation of the frames: generic (b turned away from a), aligned
// (e_b0 = e_a0), or generic with node b on the axis e3 of a (RADIAL-THRUST r0 = 0).
enum class Layout { Generic, Aligned, OnAxis };

struct Case {
  std::string name;
  std::vector<std::string> types;
  Layout layout = Layout::Generic;
  bool rotations_a = true;
};

std::ostream& operator<<(std::ostream& os, const Case& c) { return os << c.name; }

Vector3 random_vector(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return Vector3(u(rng), u(rng), u(rng));
}

ConnectorSetup random_setup(const Case& c, std::mt19937& rng) {
  ConnectorSetup s;
  s.type_names = c.types;
  s.rotations_a = c.rotations_a;
  s.has_orientation_a = true;
  s.ea0 = rotation_exp(random_vector(rng, 2.0));
  // A fixed turn of 0.6 rad about e1 and 0.4 rad about e3 keeps the Cardan β, the Euler β and
  // the flexion α well inside their regular domains for the random poses below.
  s.eb0 = c.layout == Layout::Aligned
              ? s.ea0
              : Matrix3(s.ea0 * rotation_exp(Vector3(0.6, 0, 0)) *
                        rotation_exp(Vector3(0, 0, 0.4)) * rotation_exp(random_vector(rng, 0.1)));
  s.xa0 = random_vector(rng, 1.0);
  const Vector3 offset = c.layout == Layout::OnAxis
                             ? Vector3(0, 0, 0.8)
                             : Vector3(0.9, 0.5, 0.7) + random_vector(rng, 0.2);
  s.xb0 = s.xa0 + s.ea0 * offset;
  return s;
}

struct Pose {
  NodePose a, b;
};

Pose random_pose(std::mt19937& rng, bool nlgeom) {
  Pose p;
  p.a.u = random_vector(rng, 0.2);
  p.b.u = random_vector(rng, 0.2);
  p.a.theta = random_vector(rng, 0.3);
  p.b.theta = random_vector(rng, 0.3);
  if (nlgeom) {
    p.a.rotation = rotation_exp(p.a.theta);
    p.b.rotation = rotation_exp(p.b.theta);
  }
  return p;
}

// Perturbs DOF j (0…11, order u_a, θ_a, u_b, θ_b) by s: additively for displacements and
// small rotations, multiplicatively for NLGEOM rotations.
Pose perturbed(const Pose& p, int j, double s, bool nlgeom) {
  Pose q = p;
  NodePose& node = j < 6 ? q.a : q.b;
  const int k = j % 3;
  Vector3 e = Vector3::Zero();
  e[k] = s;
  if (j % 6 < 3) {
    node.u += e;
  } else if (nlgeom) {
    node.rotation = rotation_exp(e) * node.rotation;
  } else {
    node.theta += e;
  }
  return q;
}

double relative_error(const Eigen::MatrixXd& actual, const Eigen::MatrixXd& expected) {
  const double scale = std::max(1.0, expected.cwiseAbs().maxCoeff());
  return (actual - expected).cwiseAbs().maxCoeff() / scale;
}

KinematicsResult eval(const ConnectorKinematics& k, const Pose& p, bool nlgeom, const Vector6& last,
                      bool hessian) {
  KinematicsResult out;
  k.evaluate(p.a, p.b, nlgeom, last, hessian, out);
  EXPECT_TRUE(out.ok) << out.message;
  return out;
}

// The finite-difference derivatives of `quantity` (of the kinematics at a pose) with respect to
// the 12 DOFs, perturbed as `perturbed` does, each evaluation unwrapped towards `last`.
template <typename Quantity>
JacobianReport check_against_differences(const ConnectorKinematics& k, const Pose& p, bool nlgeom,
                                         const Vector6& last, double step,
                                         const Eigen::Ref<const Eigen::MatrixXd>& analytic,
                                         Quantity quantity) {
  const auto f = [&](int j, double s, Eigen::VectorXd& value) {
    const KinematicsResult out = eval(k, perturbed(p, j, s, nlgeom), nlgeom, last, false);
    value = quantity(out);
    return out.ok;
  };
  return check_jacobian(f, Vector12::Constant(step), analytic);
}

// B against central differences of the positions (unwrapped towards the base state).
void check_b(const ConnectorKinematics& k, const Pose& p, bool nlgeom) {
  const KinematicsResult base = eval(k, p, nlgeom, k.initial_position(), false);
  const JacobianReport report =
      check_against_differences(k, p, nlgeom, base.position, kStepB, base.b,
                                [](const KinematicsResult& out) { return out.position; });
  EXPECT_LT(report.max_error, kToleranceB * std::max(1.0, report.largest_numeric)) << "B\n"
                                                                                   << report;
}

// H_i against central differences of B_i. Under multiplicative rotation updates the
// difference of B along a spin of node n is H − ½ skew(B_i,θn) on that node's θθ block (§3.7
// non-symmetric correction), so that term is added to the expectation.
void check_h(const ConnectorKinematics& k, const Pose& p) {
  const KinematicsResult base = eval(k, p, true, k.initial_position(), true);
  for (int i = 0; i < 6; ++i) {
    if (!has_component(base.existing, i + 1)) continue;
    Matrix12 expected = base.h[i];
    for (int node : {3, 9}) {
      const Vector3 spin_row = base.b.row(i).segment<3>(node).transpose();
      expected.block<3, 3>(node, node) -= 0.5 * skew(spin_row);
    }
    const JacobianReport report = check_against_differences(
        k, p, true, base.position, kStepH, expected,
        [i](const KinematicsResult& out) { return Vector12(out.b.row(i).transpose()); });
    EXPECT_LT(report.max_error, kToleranceH * std::max(1.0, report.largest_numeric))
        << "component " << i + 1 << "\n"
        << report;
    EXPECT_LT(relative_error(base.h[i], base.h[i].transpose()), 1e-12) << "H not symmetric";
  }
}

class ConnectorTangent : public ::testing::TestWithParam<Case> {
 protected:
  ConnectorKinematics make(std::mt19937& rng) {
    std::string error;
    std::optional<ConnectorKinematics> k =
        ConnectorKinematics::create(random_setup(GetParam(), rng), &error);
    EXPECT_TRUE(k) << error;
    return *k;
  }
};

TEST_P(ConnectorTangent, LinearRegimeBMatchesDifferences) {
  std::mt19937 rng(20240611);
  const ConnectorKinematics k = make(rng);
  for (int n = 0; n < kPoses; ++n) check_b(k, random_pose(rng, false), false);
}

TEST_P(ConnectorTangent, LinearRegimeB0IsExactBAtRest) {
  // §3.4: B0 is the B of §3.3 evaluated at q = 0.
  std::mt19937 rng(7);
  const ConnectorKinematics k = make(rng);
  const Pose rest;
  const KinematicsResult linear = eval(k, rest, false, k.initial_position(), false);
  const KinematicsResult exact = eval(k, rest, true, k.initial_position(), false);
  // Both are the same closed forms and jets at the same state: equal up to round-off.
  EXPECT_LT(relative_error(linear.b, exact.b), 1e-12);
  EXPECT_LT(relative_error(exact.change, Vector6::Zero()), 1e-12);
}

TEST_P(ConnectorTangent, NlgeomBMatchesDifferences) {
  std::mt19937 rng(1312);
  const ConnectorKinematics k = make(rng);
  for (int n = 0; n < kPoses; ++n) check_b(k, random_pose(rng, true), true);
}

TEST_P(ConnectorTangent, NlgeomHMatchesDifferencesOfB) {
  std::mt19937 rng(4242);
  const ConnectorKinematics k = make(rng);
  for (int n = 0; n < kPoses; ++n) check_h(k, random_pose(rng, true));
}

std::vector<Case> all_cases() {
  std::vector<Case> cases;
  for (const char* type : {"AXIAL",
                           "CARTESIAN",
                           "JOIN",
                           "LINK",
                           "SLOT",
                           "SLIDE-PLANE",
                           "RADIAL-THRUST",
                           "PROJECTION CARTESIAN",
                           "ALIGN",
                           "CARDAN",
                           "EULER",
                           "ROTATION",
                           "REVOLUTE",
                           "UNIVERSAL",
                           "FLEXION-TORSION",
                           "PROJECTION FLEXION-TORSION",
                           "BEAM",
                           "WELD",
                           "BUSHING",
                           "CYLINDRICAL",
                           "HINGE",
                           "PLANAR",
                           "TRANSLATOR",
                           "UJOINT"}) {
    std::string name = type;
    std::replace_if(
        name.begin(), name.end(), [](char ch) { return ch == ' ' || ch == '-'; }, '_');
    cases.push_back({name, {type}});
  }
  cases.push_back({"JOIN_without_rotations_at_a", {"JOIN"}, Layout::Generic, false});
  cases.push_back({"SLOT_REVOLUTE", {"SLOT", "REVOLUTE"}});
  cases.push_back({"CARTESIAN_CARDAN", {"CARTESIAN", "CARDAN"}});
  cases.push_back({"AXIAL_ROTATION", {"AXIAL", "ROTATION"}});
  cases.push_back({"RADIAL_THRUST_FLEXION_TORSION", {"RADIAL-THRUST", "FLEXION-TORSION"}});
  cases.push_back({"RADIAL_THRUST_on_axis", {"RADIAL-THRUST"}, Layout::OnAxis});
  cases.push_back({"FLEXION_TORSION_aligned", {"FLEXION-TORSION"}, Layout::Aligned});
  cases.push_back({"ROTATION_aligned", {"ROTATION"}, Layout::Aligned});
  cases.push_back({"CARDAN_aligned", {"CARDAN"}, Layout::Aligned});
  cases.push_back({"BUSHING_aligned", {"BUSHING"}, Layout::Aligned});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(AllTypes, ConnectorTangent, ::testing::ValuesIn(all_cases()),
                         [](const auto& info) { return info.param.name; });

// At zero relative rotation the rotation-vector log and the flexion vector go through their
// series branches (§3.7): the jets must still match differences there.
TEST(ConnectorTangentAtRest, SeriesBranchesMatchDifferences) {
  for (const char* type : {"ROTATION", "PROJECTION FLEXION-TORSION", "BUSHING", "CARDAN"}) {
    ConnectorSetup setup;
    setup.type_names = {type};
    setup.has_orientation_a = true;
    setup.xb0 = Vector3(0.3, -0.2, 0.9);
    const std::optional<ConnectorKinematics> k = ConnectorKinematics::create(setup, nullptr);
    ASSERT_TRUE(k) << type;
    Pose p;
    const Matrix3 common = rotation_exp(Vector3(0.2, -0.7, 0.4));
    p.a.rotation = p.b.rotation = common;  // a common rotation leaves R_rel = I
    SCOPED_TRACE(type);
    check_b(*k, p, true);
    check_h(*k, p);
  }
}

// §3.6: α of CARDAN driven past π about the shared axis e1 stays continuous (α = t).
TEST(ConnectorBranchTracking, CardanAlphaPastPi) {
  ConnectorSetup setup;
  setup.type_names = {"CARDAN"};
  setup.ea0 = setup.eb0 = rotation_exp(Vector3(0.3, 0.1, -0.2));
  const std::optional<ConnectorKinematics> k = ConnectorKinematics::create(setup, nullptr);
  ASSERT_TRUE(k);
  Vector6 last = k->initial_position();
  for (double t = 0.25; t <= 7.0; t += 0.25) {
    NodePose a, b;
    b.rotation = rotation_exp(t * setup.ea0.col(0));
    KinematicsResult out;
    k->evaluate(a, b, true, last, false, out);
    ASSERT_TRUE(out.ok);
    // The chain exp → atan2 loses a few ulps per step: trigonometric tolerance of §5.
    EXPECT_NEAR(out.change[3], t, 1e-9) << t;
    EXPECT_NEAR(out.change[4], 0, 1e-9) << t;
    EXPECT_NEAR(out.change[5], 0, 1e-9) << t;
    last = out.position;
  }
}

// §3.6: the rotation vector and the torsion angles are unwrapped the same way.
TEST(ConnectorBranchTracking, RotationVectorAndTorsionPastPi) {
  for (const char* type : {"ROTATION", "FLEXION-TORSION", "PROJECTION FLEXION-TORSION"}) {
    ConnectorSetup setup;
    setup.type_names = {type};
    setup.has_orientation_a = true;
    const std::optional<ConnectorKinematics> k = ConnectorKinematics::create(setup, nullptr);
    ASSERT_TRUE(k);
    Vector6 last = k->initial_position();
    // Torsion index: ROTATION φ3 (component 6), FLEXION-TORSION β (5), PROJECTION β (6).
    const int torsion = std::string(type) == "FLEXION-TORSION" ? 4 : 5;
    for (double t = 0.3; t <= 8.0; t += 0.3) {
      NodePose a, b;
      b.rotation = rotation_exp(Vector3(0, 0, t));
      KinematicsResult out;
      k->evaluate(a, b, true, last, false, out);
      ASSERT_TRUE(out.ok);
      EXPECT_NEAR(out.change[torsion], t, 1e-9) << type << " t = " << t;
      last = out.position;
    }
  }
}

// §2.3: at zero flexion the sweep keeps its last converged value.
TEST(ConnectorBranchTracking, SweepKeptAtZeroFlexion) {
  ConnectorSetup setup;
  setup.type_names = {"FLEXION-TORSION"};
  setup.has_orientation_a = true;
  const std::optional<ConnectorKinematics> k = ConnectorKinematics::create(setup, nullptr);
  ASSERT_TRUE(k);
  NodePose a, b;
  b.rotation = rotation_exp(Vector3(0, 0.2, 0));  // flexion about e2: sweep π/2
  KinematicsResult out;
  k->evaluate(a, b, true, k->initial_position(), false, out);
  EXPECT_NEAR(out.position[5], std::numbers::pi / 2, 1e-12);
  const Vector6 last = out.position;
  b.rotation = rotation_exp(Vector3(0, 0, 0.1));  // torsion only: zero flexion
  k->evaluate(a, b, true, last, true, out);
  EXPECT_NEAR(out.position[3], 0, 1e-15);
  EXPECT_EQ(out.position[5], last[5]);
  EXPECT_EQ(out.b.row(5).norm(), 0);
}

}  // namespace
}  // namespace clinch
