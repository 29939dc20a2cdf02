// Coupled returns that end on a kink of the spot-weld potential (derived-components-and-
// potentials.md §3, §1.4): the moment resultant of `normal` driven to zero, and the Macaulay term
// <f3> driven to zero, while the rest keeps yielding. The exact closest point holds the group at
// zero with a subgradient inside the subdifferential; with the shear measure at zero,
// P = F_n/R_n and the returns have closed forms (worked out in each test). The consistent tangent
// is checked by finite differences there (behaviors.md §1.4): the held group stays at zero under
// the stencil, because its subgradient is strictly inside the admissible set.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/tangent/plastic_test_support.hpp"

namespace clinch {
namespace {

// k = 1e5 on all six components, F_y = 40000 + 1e7 ū (behaviors.md §6.1 table), R_n = 0.02,
// R_s = 0.05, β = 1.5; or_n = 1/sqrt(30.68/19.63).
const char* const kSpotWeld =
    "*CONNECTOR ELASTICITY, COMPONENT=1\n1.0e5\n*CONNECTOR ELASTICITY, COMPONENT=2\n1.0e5\n"
    "*CONNECTOR ELASTICITY, COMPONENT=3\n1.0e5\n*CONNECTOR ELASTICITY, COMPONENT=4\n1.0e5\n"
    "*CONNECTOR ELASTICITY, COMPONENT=5\n1.0e5\n*CONNECTOR ELASTICITY, COMPONENT=6\n1.0e5\n"
    "*CONNECTOR PLASTICITY\n*CONNECTOR HARDENING\n40000., 0.\n1040000., 0.1\n"
    "*CONNECTOR POTENTIAL, EXPONENT=1.5\nnormal, 0.02, , MACAULEY, ,\nshear, 0.05, , ABS, ,\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=normal, OPERATOR=MACAULEY SUM\n3\n1.0\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=normal\n4, 5\n0.79989420015, 0.79989420015\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=shear\n6\n0.39994710008\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=shear\n1, 2\n1.0, 1.0\n";
constexpr double kK = 1e5, kRn = 0.02, kOrN = 0.79989420015, kFy0 = 40000, kH = 1e7;

// Relative accuracy of the return (1e-12 stopping tests of §6.4) on values of order 1e3, with
// margin for the closed forms' own round-off.
constexpr double kForceTolerance = 1e-8;

TEST(PlasticKink, MomentResultantHeldAtZero) {
  auto p = make_law(kSpotWeld, 0b111111);
  Driver driver(*p->law);
  // Trial: f3 = 2000, (m1, m2) = (200, 100). Holding m = 0: F_n = f3 = 2000 − k Δλ/R_n,
  // P = F_n/R_n = F_y gives Δλ = (2000/R_n − F_y0)/(k/R_n² + h). The moment's subgradient needs
  // |m^tr| ≤ k Δλ or_n/R_n (= 923 here, against |m^tr| = 224): admissible, so m stays at zero.
  const Vector6 u = vec(0, 0, 0.02, 0.002, 0.001, 0);
  const Evaluation e = driver.step(u);
  const double dl = (2000 / kRn - kFy0) / (kK / (kRn * kRn) + kH);
  ASSERT_LT(std::hypot(200.0, 100.0), kK * dl * kOrN / kRn);
  EXPECT_NEAR(e.out.force[2], 2000 - kK * dl / kRn, kForceTolerance * 2000);
  EXPECT_EQ(e.out.force[3], 0.0);
  EXPECT_EQ(e.out.force[4], 0.0);
  const BehaviorState s = driver.state();
  EXPECT_NEAR(s.coupled_equivalent_plastic, dl, 1e-12 * dl / 1e-4);
  // The whole moment trial became plastic motion: u^pl = u on components 4 and 5.
  EXPECT_NEAR(s.plastic_motion[3], 0.002, 1e-14);
  EXPECT_NEAR(s.plastic_motion[4], 0.001, 1e-14);
}

TEST(PlasticKink, MacauleyTermHeldAtZero) {
  auto p = make_law(kSpotWeld, 0b111111);
  Driver driver(*p->law);
  // Trial: f3 = 100, m1 = 2000. Holding f3 = 0: F_n = or_n (2000 − k Δλ or_n/R_n), and
  // P = F_n/R_n = F_y gives Δλ = (or_n 2000/R_n − F_y0)/(k or_n²/R_n² + h). The Macaulay
  // subgradient needs 0 ≤ f3^tr ≤ k Δλ/R_n (= 1176 against 100): admissible.
  const Vector6 u = vec(0, 0, 0.001, 0.02, 0, 0);
  const Evaluation e = driver.step(u);
  const double dl = (kOrN * 2000 / kRn - kFy0) / (kK * kOrN * kOrN / (kRn * kRn) + kH);
  ASSERT_LT(100.0, kK * dl / kRn);
  EXPECT_EQ(e.out.force[2], 0.0);
  EXPECT_NEAR(e.out.force[3], 2000 - kK * dl * kOrN / kRn, kForceTolerance * 2000);
  EXPECT_NEAR(driver.state().coupled_equivalent_plastic, dl, 1e-12 * dl / 1e-4);
  EXPECT_NEAR(driver.state().plastic_motion[2], 0.001, 1e-14);
}

TEST(PlasticKink, MomentResultantThatStaysAboveTheKink) {
  auto p = make_law(kSpotWeld, 0b111111);
  Driver driver(*p->law);
  // Trial f3 = 2000, m1 = 2000: both shrink, F_n = (2000 − kΔλ/R_n) + or_n (2000 − kΔλ or_n/R_n),
  // linear in Δλ, and m1 = 2000 − kΔλ or_n/R_n stays positive.
  const Vector6 u = vec(0, 0, 0.02, 0.02, 0, 0);
  const Evaluation e = driver.step(u);
  const double dl = ((2000 + kOrN * 2000) / kRn - kFy0) /
                    (kK * (1 + kOrN * kOrN) / (kRn * kRn) + kH);
  EXPECT_NEAR(e.out.force[2], 2000 - kK * dl / kRn, kForceTolerance * 2000);
  EXPECT_NEAR(e.out.force[3], 2000 - kK * dl * kOrN / kRn, kForceTolerance * 2000);
  EXPECT_GT(e.out.force[3], 0.0);
}

// Finite-difference tangents at the held states, from the virgin state and after a committed
// plastic increment (continued yielding on the kink). Where the shear measure is exactly zero,
// the columns of components 1, 2 and 6 are left out: there the shear contribution P_2 = 0 and
// the diverging Hessian term is set to 0 by the convention of §2.5, so the tangent is
// deliberately inexact in those directions (behaviors.md §6.8, "avoid"). The third state has
// shear and is checked in every column.
TEST(PlasticKink, TangentWithAHeldGroupMatchesFiniteDifferences) {
  struct Case {
    Vector6 u;
    ComponentMask columns;
  };
  for (const Case& c : {Case{vec(0, 0, 0.02, 0.002, 0.001, 0), 0b011100},
                        Case{vec(0, 0, 0.001, 0.02, 0, 0), 0b011100},
                        Case{vec(0.001, 0.0005, 0.02, 0.002, 0.001, 0.0004), 0b111111}}) {
    auto p = make_law(kSpotWeld, 0b111111);
    Driver driver(*p->law);
    driver.expect_fd_tangent(c.u, 0.4, kK, c.columns);
    driver.step(0.5 * c.u);
    driver.expect_fd_tangent(c.u, 0.4, kK, c.columns);
  }
}

}  // namespace
}  // namespace clinch

namespace clinch {
namespace {

// A MAX potential (behaviors.md §6.6): the face |f1| ≤ 150 cut by the circle r/1.2 ≤ 150
// (r = sqrt(f1² + f2²)), perfectly plastic, k = (1000, 1500, 800). The trial (600, 450, 16)
// violates |f1|, |f2| and the circle: three surfaces in the (f1, f2) plane, so their normals are
// dependent, and the return must drop one and end at the corner of the face and the circle:
// f1 = 150, f2 = sqrt(180² − 150²). The multipliers follow from K⁻¹(F^tr − F) = Δλ_1 e_1 +
// Δλ_2 F/(1.2 r) (both positive: a genuine corner), and ū = Δλ_1 + Δλ_2 (§6.6).
TEST(PlasticCorner, ThreeViolatedSurfacesReturnToTheCorner) {
  const char* body =
      "*CONNECTOR ELASTICITY, COMPONENT=1\n1000.\n*CONNECTOR ELASTICITY, COMPONENT=2\n1500.\n"
      "*CONNECTOR ELASTICITY, COMPONENT=3\n800.\n*CONNECTOR PLASTICITY\n"
      "*CONNECTOR HARDENING\n150., 0.\n*CONNECTOR POTENTIAL, OPERATOR=MAX\n1, 1., , ABS, ,\n"
      "2, 1., , ABS, ,\nradial, 1.2, , ABS, ,\n3, 0.8, , ABS, ,\n"
      "*CONNECTOR DERIVED COMPONENT, NAME=radial\n1, 2\n1.0, 1.0\n";
  auto p = make_law(body, 0b000111);
  Driver driver(*p->law);
  const Vector6 u = vec(0.6, 0.3, 0.02);
  driver.expect_fd_tangent(u, 0.1, 1500, 0b000111);
  const Evaluation e = driver.step(u);
  const double f2 = std::sqrt(180.0 * 180.0 - 150.0 * 150.0);
  EXPECT_NEAR(e.out.force[0], 150.0, 1e-9);
  EXPECT_NEAR(e.out.force[1], f2, 1e-9);
  EXPECT_NEAR(e.out.force[2], 16.0, 1e-12);  // component 3 stays elastic
  const double dl_circle = (450.0 - f2) / 1500.0 * (1.2 * 180.0) / f2;
  const double dl_face = (600.0 - 150.0) / 1000.0 - dl_circle * 150.0 / (1.2 * 180.0);
  ASSERT_GT(dl_face, 0.0);
  EXPECT_NEAR(driver.state().coupled_equivalent_plastic, dl_face + dl_circle, 1e-10);
}

}  // namespace
}  // namespace clinch
