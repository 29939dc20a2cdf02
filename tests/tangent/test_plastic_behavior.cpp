// Connector plasticity (behaviors.md §6): the worked examples of §6.7 driven increment by
// increment through make_connector_behavior, finite-difference tangent checks (§1.4) at every
// state of §6.8, and robustness of the coupled returns on random trial states.
//
// Tolerances. The local iterations stop at |r| ≤ 1e-12·F_y (§6.3, §6.4), so results computed
// from exact fractions are checked to 1e-9 relative (three orders of margin for the round-off of
// a few increments). Values that the spec prints with 6–9 significant digits are checked to half
// a unit of the last printed digit, written as an absolute tolerance at each check.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "src/behavior/potential/connector_potential.hpp"
#include "tests/tangent/plastic_test_support.hpp"

namespace clinch {
namespace {

constexpr ComponentMask kAxial = 0x01;
constexpr ComponentMask kCartesian = 0x07;
constexpr ComponentMask kAll = 0x3F;

const std::string kAxialElastic =
    "*CONNECTOR ELASTICITY, COMPONENT=1\n"
    "1000.\n";

// §6.7 common deck: step 1 to U = 0.2 in 4 increments, step 2 to −0.2 in 8 increments.
std::vector<double> e7_path() {
  std::vector<double> u;
  for (int k : {1, 2, 3, 4, 3, 2, 1, 0, -1, -2, -3, -4}) u.push_back(0.05 * k);
  return u;
}

void expect_rel(double actual, double expected, double rel, const char* what) {
  EXPECT_NEAR(actual, expected, rel * std::max(1.0, std::abs(expected))) << what;
}

// ------------------------------------------------------------------------------------ E7

const std::string kE7 = kAxialElastic +
                        "*CONNECTOR PLASTICITY, COMPONENT=1\n"
                        "*CONNECTOR HARDENING, TYPE=ISOTROPIC\n"
                        "120., 0.\n"
                        "170., 0.1\n";

TEST(PlasticE7, AllRowsOfTheTable) {
  auto p = make_law(kE7, kAxial);
  ASSERT_TRUE(p->law);
  EXPECT_EQ(p->law->history_size(), 19);
  Driver d(*p->law);
  // (CTF1, CUP1, CUPEQ) after each increment; exact fractions from the spec's brackets.
  const double rows[12][3] = {
      {50, 0, 0},
      {100, 0, 0},
      {130, 0.02, 0.02},
      {440.0 / 3, 4.0 / 75, 4.0 / 75},
      {440.0 / 3 - 50, 4.0 / 75, 4.0 / 75},
      {440.0 / 3 - 100, 4.0 / 75, 4.0 / 75},
      {440.0 / 3 - 150, 4.0 / 75, 4.0 / 75},
      {-160.0 / 3, 4.0 / 75, 4.0 / 75},
      {-310.0 / 3, 4.0 / 75, 4.0 / 75},
      {-1340.0 / 9, 11.0 / 225, 13.0 / 225},
      {-1490.0 / 9, 7.0 / 450, 41.0 / 450},
      {-170, -0.03, 41.0 / 300},
  };
  const std::vector<double> path = e7_path();
  for (std::size_t n = 0; n < path.size(); ++n) {
    const Evaluation e = d.step(vec(path[n]));
    const BehaviorState s = d.state();
    expect_rel(e.out.force[0], rows[n][0], 1e-9, "CTF1");
    expect_rel(s.plastic_motion[0], rows[n][1], 1e-9, "CUP1");
    expect_rel(s.equivalent_plastic[0], rows[n][2], 1e-9, "CUPEQ");
    EXPECT_EQ(s.uncoupled_plastic, kAxial);
    EXPECT_FALSE(s.has_coupled_plasticity);
  }
}

// §6.8 states 1–6 on E7: u_s = F_y/k = 0.12, k_s = 1000.
TEST(PlasticTangent, E7EveryState) {
  auto p = make_law(kE7, kAxial);
  Driver d(*p->law);
  const std::vector<double> path = e7_path();
  // Check the increment into path[n] for these n: 0 elastic, 2 first yield, 3 continued
  // yielding, 4 elastic unloading, 9 and 10 reverse yielding, 11 table-end crossing (ū ends at
  // 0.1367 > 0.1 + 100h: the stencil stays on the flat branch).
  for (std::size_t n = 0; n < path.size(); ++n) {
    if (n == 0 || n == 2 || n == 3 || n == 4 || n == 9 || n == 10 || n == 11) {
      SCOPED_TRACE("increment into U = " + std::to_string(path[n]));
      d.expect_fd_tangent(vec(path[n]), 0.12, 1000, kAxial);
    }
    d.step(vec(path[n]));
  }
}

TEST(PlasticE7, TangentValues) {
  auto p = make_law(kE7, kAxial);
  Driver d(*p->law);
  d.step(vec(0.05));
  d.step(vec(0.10));
  // First yield: h = 500, D = k h/(k + h) = 1000·500/1500.
  EXPECT_NEAR(d.evaluate(vec(0.15)).out.tangent(0, 0), 1000.0 / 3, 1e-9);
  EXPECT_NEAR(d.evaluate(vec(0.10 + 1e-3)).out.tangent(0, 0), 1000.0, 1e-12);  // elastic
}

// ------------------------------------------------------------------------------------ E8

TEST(PlasticE8, LinearKinematicRows) {
  auto p = make_law(kAxialElastic +
                        "*CONNECTOR PLASTICITY, COMPONENT=1\n"
                        "*CONNECTOR HARDENING, TYPE=KINEMATIC, DEFINITION=PARAMETERS\n"
                        "110., 500., 0.\n",
                    kAxial);
  Driver d(*p->law);
  // (index into the path, CTF1, CUP1, CALPHAF1, CUPEQ); fractions: Δλ = φ^tr/(k + C).
  struct Row {
    std::size_t n;
    double f, up, alpha, ubar;
  };
  const Row rows[] = {
      {2, 370.0 / 3, 0.04 / 1.5, 40.0 / 3, 0.04 / 1.5},
      {3, 140, 0.06, 30, 0.06},
      {7, -60, 0.06, 30, 0.06},
      {8, -90, 0.04, 20, 0.08},
      {9, -320.0 / 3, 0.02 / 3, 10.0 / 3, 0.34 / 3},
      {10, -370.0 / 3, -0.08 / 3, -40.0 / 3, 0.44 / 3},
      {11, -140, -0.06, -30, 0.18},
  };
  const std::vector<double> path = e7_path();
  std::size_t r = 0;
  for (std::size_t n = 0; n < path.size(); ++n) {
    if (n == 2 || n == 3 || n == 9 || n == 10) {
      SCOPED_TRACE("E8 increment into U = " + std::to_string(path[n]));
      d.expect_fd_tangent(vec(path[n]), 0.11, 1000, kAxial);  // u_s = F_0/k
    }
    const Evaluation e = d.step(vec(path[n]));
    if (r < std::size(rows) && rows[r].n == n) {
      const BehaviorState s = d.state();
      expect_rel(e.out.force[0], rows[r].f, 1e-9, "CTF1");
      expect_rel(s.plastic_motion[0], rows[r].up, 1e-9, "CUP1");
      expect_rel(s.back_force[0], rows[r].alpha, 1e-9, "CALPHAF1");
      expect_rel(s.equivalent_plastic[0], rows[r].ubar, 1e-9, "CUPEQ");
      ++r;
    }
  }
  EXPECT_EQ(r, std::size(rows));
}

// ------------------------------------------------------------------------------ E9, E10

TEST(PlasticE9, ArmstrongFrederickOneIncrement) {
  auto p = make_law(kAxialElastic +
                        "*CONNECTOR PLASTICITY, COMPONENT=1\n"
                        "*CONNECTOR HARDENING, TYPE=KINEMATIC, DEFINITION=PARAMETERS\n"
                        "100., 2000., 20.\n",
                    kAxial);
  Driver d(*p->law);
  d.expect_fd_tangent(vec(0.3), 0.1, 1000, kAxial);
  const Evaluation e = d.step(vec(0.3));
  // Closed form: 200 Δλ² − 10 Δλ − 2 = 0.
  const double dl = (10 + std::sqrt(1700.0)) / 400;
  const double h_alpha = 2000 / ((1 + 20 * dl) * (1 + 20 * dl));
  const BehaviorState s = d.state();
  EXPECT_NEAR(s.equivalent_plastic[0], dl, 1e-12);
  EXPECT_NEAR(s.plastic_motion[0], dl, 1e-12);
  EXPECT_NEAR(e.out.force[0], 300 - 1000 * dl, 1e-9);
  EXPECT_NEAR(s.back_force[0], 2000 * dl / (1 + 20 * dl), 1e-9);
  EXPECT_NEAR(e.out.tangent(0, 0), 1000 * h_alpha / (1000 + h_alpha), 1e-9);
  // The spec's printed values, to half a unit of their last digit.
  EXPECT_NEAR(dl, 0.128077641, 5e-10);
  EXPECT_NEAR(e.out.force[0], 171.922359, 5e-7);
  EXPECT_NEAR(s.back_force[0], 71.922359, 5e-7);
  EXPECT_NEAR(h_alpha, 157.670781, 5e-7);
  EXPECT_NEAR(e.out.tangent(0, 0), 136.196562, 5e-7);
}

TEST(PlasticE10, ExponentialLawOneIncrement) {
  auto p = make_law(kAxialElastic +
                        "*CONNECTOR PLASTICITY, COMPONENT=1\n"
                        "*CONNECTOR HARDENING, TYPE=ISOTROPIC, DEFINITION=EXPONENTIAL LAW\n"
                        "100., 50., 20.\n",
                    kAxial);
  Driver d(*p->law);
  d.expect_fd_tangent(vec(0.2), 0.1, 1000, kAxial);
  const Evaluation e = d.step(vec(0.2));
  const double dl = d.state().equivalent_plastic[0];
  // Independent check of the scalar equation 200 − 1000 Δλ − F_y(Δλ) = 0.
  EXPECT_NEAR(200 - 1000 * dl - (100 + 50 * (1 - std::exp(-20 * dl))), 0.0, 1e-10);
  EXPECT_NEAR(dl, 0.0639232271, 5e-11);
  EXPECT_NEAR(e.out.force[0], 136.076773, 5e-7);
  const double h = 50 * 20 * std::exp(-20 * dl);
  EXPECT_NEAR(h, 278.464543, 5e-7);
  EXPECT_NEAR(e.out.tangent(0, 0), 217.811706, 5e-7);
}

// ----------------------------------------------------------------------------- softening

TEST(PlasticSoftening, ReturnsUniquelyAcrossBreakpointsAndBeyondTheTable) {
  // Slopes −500 and −100, both > −k = −1000 (§6.1). From the virgin state to U = 0.3 the
  // return crosses both breakpoints: on the CONSTANT branch 300 − 1000 Δλ = 40 (Δλ = 0.26); on
  // the LINEAR branch 300 − 1000 Δλ = 40 − 100 (Δλ − 0.2), Δλ = 0.8/3.
  const std::string table =
      "*CONNECTOR PLASTICITY, COMPONENT=1\n"
      "*CONNECTOR HARDENING, TYPE=ISOTROPIC{}\n"
      "100., 0.\n"
      "50., 0.1\n"
      "40., 0.2\n";
  for (const bool linear : {false, true}) {
    std::string body = table;
    body.replace(body.find("{}"), 2, linear ? ", EXTRAPOLATION=LINEAR" : "");
    auto p = make_law(kAxialElastic + body, kAxial);
    Driver d(*p->law);
    const Evaluation e = d.step(vec(0.3));
    const double dl = linear ? 0.8 / 3 : 0.26;
    EXPECT_NEAR(d.state().equivalent_plastic[0], dl, 1e-12) << "linear " << linear;
    EXPECT_NEAR(e.out.force[0], 300 - 1000 * dl, 1e-9);
    // Softening tangent k h/(k + h) with h = −100 (LINEAR), 0 (CONSTANT).
    EXPECT_NEAR(e.out.tangent(0, 0), linear ? -100000.0 / 900 : 0.0, 1e-9);
    // Inside the first (softening) segment: from U = 0.15, Δλ = 50/500 lands at ū = 0.1, the
    // breakpoint itself; U = 0.14 gives Δλ = 0.08, slope −500, D = −1000.
    Driver d2(*p->law);
    d2.expect_fd_tangent(vec(0.14), 0.1, 1000, kAxial);
    EXPECT_NEAR(d2.evaluate(vec(0.14)).out.tangent(0, 0), -1000.0, 1e-9);
    d2.expect_fd_tangent(vec(0.3), 0.1, 1000, kAxial);
  }
}

// ------------------------------------------------------------------------------ E11, E11b

const std::string kCartesianElastic =
    "*CONNECTOR ELASTICITY, COMPONENT=1\n"
    "1000.\n"
    "*CONNECTOR ELASTICITY, COMPONENT=2\n"
    "1000.\n"
    "*CONNECTOR ELASTICITY, COMPONENT=3\n"
    "1000.\n";

void expect_2x2(const Matrix6& d, double d11, double d12, double d22, double tol) {
  EXPECT_NEAR(d(0, 0), d11, tol);
  EXPECT_NEAR(d(0, 1), d12, tol);
  EXPECT_NEAR(d(1, 0), d12, tol);
  EXPECT_NEAR(d(1, 1), d22, tol);
}

TEST(PlasticE11, CircleTwoSteps) {
  auto p = make_law(kCartesianElastic +
                        "*CONNECTOR PLASTICITY\n"
                        "*CONNECTOR HARDENING, TYPE=ISOTROPIC\n"
                        "100., 0.\n"
                        "*CONNECTOR POTENTIAL\n"
                        "1, 1.\n"
                        "2, 1.\n",
                    kCartesian);
  Driver d(*p->law);
  d.expect_fd_tangent(vec(0.1, 0.1), 0.1, 1000, kCartesian);
  Evaluation e = d.step(vec(0.1, 0.1));
  BehaviorState s = d.state();
  // Radial return onto the circle of radius 100: F = 100 (1, 1)/√2.
  const double c = 100 / std::sqrt(2.0);
  EXPECT_NEAR(e.out.force[0], c, 1e-9);
  EXPECT_NEAR(e.out.force[1], c, 1e-9);
  EXPECT_NEAR(s.plastic_motion[0], 0.1 - c / 1000, 1e-12);
  EXPECT_NEAR(s.coupled_equivalent_plastic, std::sqrt(2.0) * 0.1 - 0.1, 1e-12);
  EXPECT_TRUE(s.has_coupled_plasticity);
  // D = (k F_y/|F^tr|) t tᵀ with t = (1, −1)/√2.
  const double dk = 1000 * 100 / (std::sqrt(2.0) * 100) / 2;
  expect_2x2(e.out.tangent, dk, -dk, dk, 1e-9);
  EXPECT_NEAR(dk, 353.553391, 5e-7);
  EXPECT_DOUBLE_EQ(e.out.tangent(2, 2), 1000.0);  // component 3 stays elastic

  d.expect_fd_tangent(vec(0.1, 0.2), 0.1, 1000, kCartesian);
  e = d.step(vec(0.1, 0.2));
  s = d.state();
  EXPECT_NEAR(e.out.force[0], 38.2683432, 5e-8);
  EXPECT_NEAR(e.out.force[1], 92.3879533, 5e-8);
  EXPECT_NEAR(s.plastic_motion[0], 0.0617316568, 5e-11);
  EXPECT_NEAR(s.plastic_motion[1], 0.107612047, 5e-10);
  EXPECT_NEAR(s.coupled_equivalent_plastic, 0.126197263, 5e-10);
  expect_2x2(e.out.tangent, 461.939766, -191.341716, 79.256334, 5e-7);
}

TEST(PlasticE11b, AnisotropicPotentialWithHardening) {
  auto p = make_law(kCartesianElastic +
                        "*CONNECTOR PLASTICITY\n"
                        "*CONNECTOR HARDENING, TYPE=ISOTROPIC\n"
                        "100., 0.\n"
                        "300., 1.\n"
                        "*CONNECTOR POTENTIAL\n"
                        "1, 1.\n"
                        "2, 2.\n",
                    kCartesian);
  Driver d(*p->law);
  d.expect_fd_tangent(vec(0.1, 0.1), 0.1, 1000, kCartesian);
  Evaluation e = d.step(vec(0.1, 0.1));
  BehaviorState s = d.state();
  EXPECT_NEAR(e.out.force[0], 89.9717441, 5e-8);
  EXPECT_NEAR(e.out.force[1], 97.2890395, 5e-8);
  EXPECT_NEAR(s.plastic_motion[0], 0.0100282559, 5e-11);
  EXPECT_NEAR(s.plastic_motion[1], 0.00271096051, 5e-12);
  // The spec prints CUPEQ = 0.0114001376, but its own forces give (P − 100)/200 = 0.0114001378
  // and a 30-digit solve of the same equations (mpmath findroot) gives 0.0114001378778; the
  // printed value is checked to 5e-10, the independent one to 1e-12.
  EXPECT_NEAR(s.coupled_equivalent_plastic, 0.0114001376, 5e-10);
  EXPECT_NEAR(s.coupled_equivalent_plastic, 0.0114001378778, 1e-12);
  expect_2x2(e.out.tangent, 244.350258, -191.575625, 916.889391, 5e-7);

  // §6.8 state 3 (continued yielding, non-radial).
  d.expect_fd_tangent(vec(0.15, 0.2), 0.1, 1000, kCartesian);
  e = d.step(vec(0.15, 0.2));
  s = d.state();
  EXPECT_NEAR(e.out.force[0], 83.2152709, 5e-8);
  EXPECT_NEAR(e.out.force[1], 168.549498, 5e-7);
  EXPECT_NEAR(s.plastic_motion[0], 0.0667847291, 5e-11);
  EXPECT_NEAR(s.plastic_motion[1], 0.0314505024, 5e-11);
  // Printed 0.0921784914; the 30-digit solve gives 0.0921784908789 (as above).
  EXPECT_NEAR(s.coupled_equivalent_plastic, 0.0921784914, 1e-9);
  EXPECT_NEAR(s.coupled_equivalent_plastic, 0.0921784908789, 1e-12);
  expect_2x2(e.out.tangent, 318.962043, -200.507683, 708.427055, 5e-7);
  EXPECT_EQ(e.out.force[2], 0.0);
  // P(F) = 100 + 200 ū (the spec's check value 118.435698).
  const double pf = std::hypot(e.out.force[0], e.out.force[1] / 2);
  EXPECT_NEAR(pf, 118.435698, 5e-7);
  EXPECT_NEAR(pf, 100 + 200 * s.coupled_equivalent_plastic, 1e-10 * pf);
}

// --------------------------------------------------------------------------- spot weld

// derived-components-and-potentials.md §3, with the constants of its table and a diagonal
// coupled elasticity (1e5 in translation, 1e6 in rotation) as in decks/examples/spot_weld.inp.
std::string spot_weld(const std::string& hardening) {
  return "*CONNECTOR ELASTICITY\n"
         "1.0e5, 0.0, 1.0e5, 0.0, 0.0, 1.0e5, 0.0, 0.0\n"
         "0.0, 1.0e6, 0.0, 0.0, 0.0, 0.0, 1.0e6, 0.0\n"
         "0.0, 0.0, 0.0, 0.0, 1.0e6\n"
         "*CONNECTOR PLASTICITY\n"
         "*CONNECTOR HARDENING, DEFINITION=TABULAR\n" +
         hardening +
         "*CONNECTOR POTENTIAL, EXPONENT=1.5\n"
         "normal, 0.02, , MACAULEY\n"
         "shear,  0.05, , ABS\n"
         "*CONNECTOR DERIVED COMPONENT, NAME=normal, OPERATOR=MACAULEY SUM\n"
         "3\n"
         "1.0\n"
         "*CONNECTOR DERIVED COMPONENT, NAME=normal\n"
         "4, 5\n"
         "0.799894, 0.799894\n"
         "*CONNECTOR DERIVED COMPONENT, NAME=shear\n"
         "6\n"
         "0.399947\n"
         "*CONNECTOR DERIVED COMPONENT, NAME=shear\n"
         "1, 2\n"
         "1.0, 1.0\n";
}
const Vector6 kWeldStiffness = vec(1e5, 1e5, 1e5, 1e6, 1e6, 1e6);

TEST(PlasticTangent, SpotWeldAwayFromKinks) {
  // Hardening h = 1e7 per unit ū (ū is of order 1e-4 here).
  auto p = make_law(spot_weld("40000., 0.\n50000., 0.001\n"), kAll);
  Driver d(*p->law);
  // Trial force with every term and contribution well away from zero.
  const Vector6 trial = vec(150, 80, 750, 300, 120, 200);
  const Vector6 u = trial.cwiseQuotient(kWeldStiffness);
  const Evaluation e = d.evaluate(u);
  ASSERT_EQ(e.status, IntegrationStatus::Success);
  // The returned state is away from every kink (f3 > 0, resultants non-zero).
  EXPECT_GT(e.out.force[2], 100.0);
  EXPECT_GT(std::hypot(e.out.force[0], e.out.force[1]), 10.0);
  EXPECT_GT(std::abs(e.out.force[5]), 10.0);
  EXPECT_LT(e.out.force.norm(), trial.norm());
  d.expect_fd_tangent(u, 0.4, 1e6, kAll);  // u_s ~ yield force / stiffness
  // Continued yielding from that state. A 3 % further load keeps sqrt(m1² + m2²) away from 0; a
  // 20 % one drives the moment resultant into the NORM kink (an unsuitable state, §1.4).
  d.step(u);
  const Evaluation next = d.evaluate(1.03 * u);
  EXPECT_GT(std::hypot(next.out.force[3], next.out.force[4]), 10.0);
  EXPECT_GT(next.history[12], e.history[12]);
  d.expect_fd_tangent(1.03 * u, 0.4, 1e6, kAll);
}

double weld_yield(double ubar) { return ubar >= 0.001 ? 50000 : 40000 + 1e7 * ubar; }

TEST(PlasticReturn, SpotWeldRandomTrialsConverge) {
  auto p = make_law(spot_weld("40000., 0.\n50000., 0.001\n"), kAll);
  const ConnectorPotential potential = ConnectorPotential::compile(
      p->deck.model.behaviors.behaviors[0], p->deck.model.behaviors.behaviors[0].potentials[0]);
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> small(0.0, 1.0);
  const Vector6 scale = vec(4000, 4000, 1600, 2000, 2000, 10000);
  int plastic = 0, crossed_kink = 0;
  for (int n = 0; n < 2000; ++n) {
    Vector6 trial;
    for (int i = 0; i < 6; ++i) trial[i] = scale[i] * unit(rng);
    // Every fourth trial has a small positive f3 with a large shear, so that the flow drives
    // f3 through the Macaulay kink at 0.
    if (n % 4 == 0) trial[2] = 50 * small(rng);
    Driver d(*p->law);
    const Evaluation e = d.step(trial.cwiseQuotient(kWeldStiffness));
    ASSERT_EQ(e.status, IntegrationStatus::Success) << trial.transpose();
    const BehaviorState s = d.state();
    EXPECT_GE(s.coupled_equivalent_plastic, 0.0);
    // Elastic law with the returned plastic motion: F = K (u − u^pl).
    const Vector6 elastic =
        kWeldStiffness.cwiseProduct(trial.cwiseQuotient(kWeldStiffness) - s.plastic_motion);
    EXPECT_LE((elastic - e.out.force).norm(), 1e-9 * trial.norm());
    const double fy = weld_yield(s.coupled_equivalent_plastic);
    const double pf = potential.value(e.out.force);
    if (s.coupled_equivalent_plastic > 0) {
      ++plastic;
      EXPECT_NEAR(pf, fy, 1e-10 * fy) << trial.transpose();
      if (trial[2] > 0 && e.out.force[2] <= 0) ++crossed_kink;
    } else {
      EXPECT_LE(pf, 40000.0);
      EXPECT_LE((e.out.force - trial).norm(), 1e-12 * trial.norm());  // K (trial/K) round-off
    }
  }
  EXPECT_GT(plastic, 1000);
  EXPECT_GT(crossed_kink, 10);
}

// ------------------------------------------------------------------------------------ MAX

// P = max(sqrt(f1² + f2²)/100, |f3|/50): a cylinder with curved side (Hessian of the NORM) and
// flat ends, F_y = 1 + 0.1 ū up to ū = 10, then 2.
const std::string kMaxCylinder = kCartesianElastic +
                                 "*CONNECTOR PLASTICITY\n"
                                 "*CONNECTOR HARDENING\n"
                                 "1., 0.\n"
                                 "2., 10.\n"
                                 "*CONNECTOR POTENTIAL, OPERATOR=MAX\n"
                                 "radial, 100.\n"
                                 "3, 50.\n"
                                 "*CONNECTOR DERIVED COMPONENT, NAME=radial\n"
                                 "1, 2\n"
                                 "1.0, 1.0\n";

TEST(PlasticTangent, MaxOneActiveSurface) {
  auto p = make_law(kMaxCylinder, kCartesian);
  Driver d(*p->law);
  const Vector6 u = vec(0.15, 0.06, 0.01);
  const Evaluation e = d.evaluate(u);
  ASSERT_EQ(e.status, IntegrationStatus::Success);
  const double fy = 1 + 0.1 * e.history[12];
  EXPECT_NEAR(std::hypot(e.out.force[0], e.out.force[1]) / 100, fy, 1e-10 * fy);
  EXPECT_NEAR(e.out.force[2], 10.0, 1e-9);  // the end surface is not active
  d.expect_fd_tangent(u, 0.1, 1000, kCartesian);
  d.step(u);
  d.expect_fd_tangent(vec(0.18, 0.08, 0.01), 0.1, 1000, kCartesian);  // continued yielding
}

TEST(PlasticTangent, MaxTwoActiveSurfaces) {
  auto p = make_law(kMaxCylinder, kCartesian);
  Driver d(*p->law);
  const Vector6 u = vec(0.15, 0.06, 0.12);
  const Evaluation e = d.evaluate(u);
  ASSERT_EQ(e.status, IntegrationStatus::Success);
  const double fy = 1 + 0.1 * e.history[12];
  // On the edge: both surfaces at the yield size.
  EXPECT_NEAR(std::hypot(e.out.force[0], e.out.force[1]) / 100, fy, 1e-10 * fy);
  EXPECT_NEAR(std::abs(e.out.force[2]) / 50, fy, 1e-10 * fy);
  d.expect_fd_tangent(u, 0.1, 1000, kCartesian);
}

TEST(PlasticReturn, MaxRandomTrialsConvergeIncludingCorners) {
  auto p = make_law(kMaxCylinder, kCartesian);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int corners = 0, faces = 0;
  for (int n = 0; n < 2000; ++n) {
    const Vector6 trial = vec(400 * unit(rng), 400 * unit(rng), 200 * unit(rng));
    Driver d(*p->law);
    const Evaluation e = d.step(trial / 1000);
    ASSERT_EQ(e.status, IntegrationStatus::Success) << trial.transpose();
    const double ubar = d.state().coupled_equivalent_plastic;
    EXPECT_GE(ubar, 0.0);
    const double fy = ubar < 10 ? 1 + 0.1 * ubar : 2.0;
    const double p1 = std::hypot(e.out.force[0], e.out.force[1]) / 100;
    const double p2 = std::abs(e.out.force[2]) / 50;
    if (ubar == 0) continue;
    EXPECT_NEAR(std::max(p1, p2), fy, 1e-10 * fy) << trial.transpose();
    EXPECT_LE(std::min(p1, p2), fy * (1 + 1e-10));
    if (std::abs(p1 - fy) <= 1e-10 * fy && std::abs(p2 - fy) <= 1e-10 * fy) {
      ++corners;
    } else {
      ++faces;
    }
  }
  EXPECT_GT(corners, 100);
  EXPECT_GT(faces, 100);
}

// -------------------------------------------------------- coupled K, one uncoupled plasticity

// §6.3 last paragraph: with a coupled D and one uncoupled plastic component the flow is s e_1;
// then F = F^tr − sΔλ K e_1 and the scalar equation is that of §6.3 with k = K_11.
TEST(PlasticCoupledElasticity, OneUncoupledComponentFlowsAlongE1) {
  auto p = make_law(
      "*CONNECTOR ELASTICITY\n"
      "1000., 200., 500., 0., 0., 800., 0., 0.\n"
      "0., 0., 0., 0., 0., 0., 0., 0.\n"
      "0., 0., 0., 0., 0.\n"
      "*CONNECTOR PLASTICITY, COMPONENT=1\n"
      "*CONNECTOR HARDENING, TYPE=ISOTROPIC\n"
      "10., 0.\n"
      "20., 0.1\n"
      "*CONNECTOR HARDENING, TYPE=KINEMATIC, DEFINITION=PARAMETERS\n"
      "10., 300., 5.\n",
      kCartesian);
  Driver d(*p->law);
  const Vector6 u = vec(0.02, 0.01, 0.005);
  d.expect_fd_tangent(u, 0.01, 1000, kCartesian);
  const Evaluation e = d.step(u);
  const BehaviorState s = d.state();
  Matrix6 k = Matrix6::Zero();
  k.topLeftCorner<3, 3>() << 1000, 200, 0, 200, 500, 0, 0, 0, 800;
  // Only component 1 flows, and F = K (u − u^pl) holds exactly.
  EXPECT_EQ(s.plastic_motion[1], 0.0);
  EXPECT_GT(s.plastic_motion[0], 0.0);
  EXPECT_LE((k * (u - s.plastic_motion) - e.out.force).norm(), 1e-10);
  // Yield condition |F_1 − α_1| = F_y(ū).
  const double ubar = s.equivalent_plastic[0];
  EXPECT_NEAR(std::abs(e.out.force[0] - s.back_force[0]), 10 + 100 * ubar, 1e-10);
  d.expect_fd_tangent(vec(0.03, 0.0, 0.01), 0.01, 1000, kCartesian);  // continued yielding
}

// ------------------------------------------------------------------------------- factory

TEST(PlasticBehavior, WithoutPlasticityTheElasticLawIsReturned) {
  auto p = make_law(kAxialElastic, kAxial);
  ASSERT_TRUE(p->law);
  EXPECT_EQ(p->law->history_size(), 0);
}

TEST(PlasticBehavior, NonlinearElasticComponentKeepsItsLaw) {
  auto p = make_law(kE7 +
                        "*CONNECTOR ELASTICITY, COMPONENT=2, NONLINEAR\n"
                        "-100., -0.1\n"
                        "0., 0.\n"
                        "100., 0.1\n"
                        "150., 0.2\n",
                    0x03);
  Driver d(*p->law);
  const Evaluation e = d.step(vec(0.15, 0.15));
  EXPECT_NEAR(e.out.force[0], 130.0, 1e-9);
  EXPECT_NEAR(e.out.force[1], 125.0, 1e-12);
  EXPECT_NEAR(e.out.tangent(1, 1), 500.0, 1e-12);
  EXPECT_EQ(p->law->components(), 0x03);
}

// behaviors.md §4.4 rigid-plastic: RIGID plus plasticity on component 1 and no linear elasticity
// of that kind: the rigid part is the stiff spring k_rigid = 1.0e8, then the yield force 100.
TEST(PlasticBehavior, RigidPlasticUsesTheStiffSpring) {
  auto p = make_law("*CONNECTOR ELASTICITY, COMPONENT=1, RIGID\n"
                    "*CONNECTOR PLASTICITY, COMPONENT=1\n*CONNECTOR HARDENING\n100., 0.\n",
                    0b000001);
  ASSERT_TRUE(p->law);
  Driver d(*p->law);
  EXPECT_NEAR(d.step(vec(5e-7)).out.force[0], 50.0, 1e-9);
  const Evaluation e = d.step(vec(1e-5));
  EXPECT_NEAR(e.out.force[0], 100.0, 1e-9);
  EXPECT_NEAR(d.state().plastic_motion[0], 1e-5 - 1e-6, 1e-15);
  d.expect_fd_tangent(vec(2e-5), 1e-6, 1e8, 0b000001);
}

}  // namespace
}  // namespace clinch
