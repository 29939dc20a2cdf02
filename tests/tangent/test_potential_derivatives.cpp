// Connector potentials (derived-components-and-potentials.md §2.3–§2.5, §3): the spot-weld worked
// example against its table, the small cases of §3, gradients against central differences of
// closed forms written out in the test, Hessians against central differences of the returned
// gradient, and the conventions at the non-smooth points.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>

#include "src/behavior/potential/connector_potential.hpp"
#include "src/behavior/potential/derived_component.hpp"
#include "tests/tangent/potential_fixture.hpp"

namespace clinch {
namespace {

using potential_test::compile_potential;
using potential_test::error_count;
using potential_test::expect_close;
using potential_test::expect_fd_derivatives;
using potential_test::read_bushing_deck;

double mac(double x) { return x > 0 ? x : 0; }

Vector6 vec(double a, double b, double c, double d, double e, double f) {
  Vector6 v;
  v << a, b, c, d, e, f;
  return v;
}

// ∂P/∂c of the whole potential (i < 0) or of its contribution i: the function whose central
// differences the Hessians are checked against.
Vector6 gradient_at(const ConnectorPotential& p, const Vector6& c, int i = -1) {
  PotentialValue w;
  if (i < 0) {
    p.evaluate(c, w, false);
  } else {
    p.evaluate_contribution(i, c, w, false);
  }
  return w.gradient;
}

// --- the spot weld of §3 ---------------------------------------------------------------------

const std::string kSpotWeldParameters =
    "I_xx = 30.68\nA    = 19.63\nr_n  = sqrt(I_xx/A)\nr_s  = 2.0*r_n\nor_n = 1.0/r_n\n"
    "or_s = 1.0/r_s\nR_n  = 0.02\nR_s  = 0.05\nbeta = 1.5\n";
const std::string kSpotWeldBody =
    "*CONNECTOR PLASTICITY\n"
    "*CONNECTOR HARDENING, DEFINITION=TABULAR\n40000.0, 0.0\n"
    "*CONNECTOR POTENTIAL, EXPONENT=<beta>\n"
    "normal, <R_n>, , MACAULEY\n"
    "shear,  <R_s>, , ABS\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=normal, OPERATOR=MACAULEY SUM\n3\n1.0\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=normal\n4, 5\n<or_n>, <or_n>\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=shear\n6\n<or_s>\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=shear\n1, 2\n1.0, 1.0\n";
// The same potential on intrinsic components: component 3 plays F_n and component 1 plays F_s,
// so its gradient and Hessian at (F_s, 0, F_n, 0, 0, 0) are ∂P/∂(F_n, F_s) and the (F_n, F_s)
// Hessian of §3 directly.
const std::string kTwinBody =
    "*CONNECTOR PLASTICITY\n"
    "*CONNECTOR HARDENING, DEFINITION=TABULAR\n40000.0, 0.0\n"
    "*CONNECTOR POTENTIAL, EXPONENT=1.5\n"
    "3, 0.02, , MACAULEY\n"
    "1, 0.05, , ABS\n";

// The table of §3 is rounded to 6 significant digits: relative 5e-6. A table 0 is exact.
void expect_table(double actual, double table, const std::string& what) {
  if (table == 0) {
    EXPECT_EQ(actual, 0.0) << what;
  } else {
    EXPECT_NEAR(actual, table, 5e-6 * std::fabs(table)) << what;
  }
}

struct SpotWeldRow {
  const char* state;
  Vector6 f;
  double fn, fs, p1, p2, p, dp_dfn, dp_dfs;
  double grad[6];
};

const SpotWeldRow kSpotWeldTable[] = {
    {"A", vec(100, 0, 500, 200, 0, 0), 659.979, 100.000, 32998.9, 2000.00, 33326.4, 49.7538,
     4.89949, {4.89949, 0, 49.7538, 39.7977, 0, 0}},
    {"B", vec(300, -400, -200, 0, 150, 800), 119.984, 819.958, 5999.21, 16399.2, 18736.7, 28.2924,
     18.7109, {11.2265, -14.9687, 0, 0, 22.6309, 7.48335}},
    {"C", vec(0, 0, -100, 0, 0, 50), 0, 19.9974, 0, 399.947, 399.947, 0, 20.0000,
     {0, 0, 0, 0, 0, 7.99894}},
};

TEST(PotentialSpotWeld, TableOfSection3) {
  auto deck = read_bushing_deck(kSpotWeldBody, kSpotWeldParameters);
  ASSERT_EQ(error_count(*deck), 0) << deck->dump();
  auto twin_deck = read_bushing_deck(kTwinBody);
  ASSERT_EQ(error_count(*twin_deck), 0) << twin_deck->dump();
  const ConnectorBehavior& b = potential_test::behavior_of(*deck);
  const DerivedComponent normal = DerivedComponent::compile(b, "NORMAL");
  const DerivedComponent shear = DerivedComponent::compile(b, "SHEAR");
  const ConnectorPotential p = compile_potential(*deck);
  const ConnectorPotential twin = compile_potential(*twin_deck);
  EXPECT_EQ(p.components(), 0b111111);
  EXPECT_EQ(p.contribution_count(), 2);
  EXPECT_FALSE(p.is_max());
  EXPECT_EQ(p.exponent(), 1.5);
  EXPECT_EQ(p.type(), ContributionType::Norm);

  for (const SpotWeldRow& row : kSpotWeldTable) {
    const std::string s = std::string("state ") + row.state + " ";
    const double fn = normal.value(row.f), fs = shear.value(row.f);
    expect_table(fn, row.fn, s + "F_n");
    expect_table(fs, row.fs, s + "F_s");
    PotentialValue v, one;
    p.evaluate(row.f, v, true);
    p.evaluate_contribution(0, row.f, one, false);
    expect_table(one.value, row.p1, s + "P1");
    p.evaluate_contribution(1, row.f, one, false);
    expect_table(one.value, row.p2, s + "P2");
    expect_table(v.value, row.p, s + "P");
    EXPECT_EQ(p.value(row.f), v.value) << s;
    for (int j = 0; j < 6; ++j) expect_table(v.gradient[j], row.grad[j], s + "dP/df" + std::to_string(j + 1));
    // Euler (§2.4, table row "f·∂P/∂f"): exact identity, so only round-off: 1e-12 relative.
    EXPECT_NEAR(row.f.dot(v.gradient), v.value, 1e-12 * v.value) << s;
    EXPECT_NEAR(row.f.dot(v.gradient), row.p, 5e-6 * row.p) << s;

    PotentialValue t;
    twin.evaluate(vec(fs, 0, fn, 0, 0, 0), t, true);
    expect_table(t.value, row.p, s + "twin P");
    expect_table(t.gradient[2], row.dp_dfn, s + "dP/dF_n");
    expect_table(t.gradient[0], row.dp_dfs, s + "dP/dF_s");
    // The slopes n_i = ∂P/∂E_i that weigh the kink groups are the table's ∂P/∂F_n, ∂P/∂F_s.
    expect_table(v.slope[0], row.dp_dfn, s + "slope of normal");
    expect_table(v.slope[1], row.dp_dfs, s + "slope of shear");
  }
  // Kink groups of the spot weld: <f3>, the moment pair (m1, m2), |m3| and the force pair.
  std::vector<ComponentMask> groups;
  for (const KinkGroup& g : p.kink_groups()) groups.push_back(g.components);
  EXPECT_EQ(groups, (std::vector<ComponentMask>{0b000100, 0b011000, 0b100000, 0b000011}));
}

TEST(PotentialSpotWeld, HessianAndHomogeneityAtStatesAAndB) {
  auto deck = read_bushing_deck(kSpotWeldBody, kSpotWeldParameters);
  auto twin_deck = read_bushing_deck(kTwinBody);
  const ConnectorPotential p = compile_potential(*deck);
  const ConnectorPotential twin = compile_potential(*twin_deck);
  const double h_nn = 5.54152e-4, h_ns = -3.65728e-3, h_ss = 2.41373e-2;  // §3, state A

  // Through the chain rule at A: f3 enters only F_n (slope 1, no curvature) and f1 only F_s
  // (slope f1/r = 1 and curvature (1/r)(1 − f1²/r²) = 0 since f2 = 0), so the (f3, f1) block of
  // the 6×6 Hessian is the (F_n, F_s) Hessian.
  const Vector6 a = kSpotWeldTable[0].f;
  PotentialValue v;
  p.evaluate(a, v, true);
  expect_table(v.hessian(2, 2), h_nn, "d2P/dFn2 (chain rule)");
  expect_table(v.hessian(2, 0), h_ns, "d2P/dFndFs (chain rule)");
  expect_table(v.hessian(0, 2), h_ns, "d2P/dFsdFn (chain rule)");
  expect_table(v.hessian(0, 0), h_ss, "d2P/dFs2 (chain rule)");

  PotentialValue t;
  twin.evaluate(vec(100.000, 0, 659.979, 0, 0, 0), t, true);
  expect_table(t.hessian(2, 2), h_nn, "d2P/dFn2");
  expect_table(t.hessian(2, 0), h_ns, "d2P/dFndFs");
  expect_table(t.hessian(0, 0), h_ss, "d2P/dFs2");

  // ∂²P/∂c²·c = 0 (degree-1 homogeneity) at A and B: an exact identity, so the residual is
  // round-off of sums of ~12 products of entries of size |H|·|c|: 1e-12 of that scale.
  for (int row : {0, 1}) {
    const Vector6 c = kSpotWeldTable[row].f;
    p.evaluate(c, v, true);
    const Vector6 hc = v.hessian * c;
    const double scale = v.hessian.cwiseAbs().maxCoeff() * c.cwiseAbs().maxCoeff();
    for (int j = 0; j < 6; ++j) EXPECT_NEAR(hc[j], 0.0, 1e-12 * scale) << "row " << row;
    // §3: central differences agree with the analytic derivatives at A and B.
    expect_fd_derivatives(
        v.gradient.transpose(), [&](const Vector6& x) { return p.value(x); }, c, 1e-6, 1e-12,
        "spot weld gradient");
    const auto gradient = [&](const Vector6& x) { return gradient_at(p, x); };
    if (row == 0) {
      // m3 = 0 at A is the kink of or_s·|m3|: the gradient jumps there, so the m3 row and
      // column have no central-difference counterpart; the rest of the Hessian is smooth.
      expect_fd_derivatives(v.hessian, gradient, c, 1e-6, 1e-12, "spot weld Hessian at A",
                            0b011111);
      EXPECT_TRUE(v.hessian.row(5).isZero(0.0));
    } else {
      expect_fd_derivatives(v.hessian, gradient, c, 1e-6, 1e-12, "spot weld Hessian at B");
    }
  }
}

// State C (§3): the genuine kink sqrt(f1² + f2²) = 0 gets the centre of the subdifferential,
// P1 = 0 with β = 1.5 gives an exact zero F_n gradient, and the unbounded (F_n, F_n) Hessian
// entry is 0 (§2.5). Everything else stays finite.
TEST(PotentialSpotWeld, StateCUsesTheSubgradientConventions) {
  auto deck = read_bushing_deck(kSpotWeldBody, kSpotWeldParameters);
  const ConnectorPotential p = compile_potential(*deck);
  PotentialValue v;
  p.evaluate(kSpotWeldTable[2].f, v, true);
  EXPECT_TRUE(v.hessian.allFinite());
  for (int j : {0, 1, 2, 3, 4}) EXPECT_EQ(v.gradient[j], 0.0) << j;
  // f3 < 0 and m1 = m2 = 0: F_n does not move with f3, m1, m2 at first order, and the
  // diverging (P1/P)^(β−2) term is dropped, so those rows are 0.
  for (int j : {2, 3, 4}) EXPECT_TRUE(v.hessian.row(j).isZero(0.0)) << j;

  auto twin_deck = read_bushing_deck(kTwinBody);
  const ConnectorPotential twin = compile_potential(*twin_deck);
  twin.evaluate(vec(19.9974, 0, 0, 0, 0, 0), v, true);  // X1 = 0 exactly
  EXPECT_EQ(v.gradient[2], 0.0);
  EXPECT_EQ(v.hessian(2, 2), 0.0);
  EXPECT_EQ(v.hessian(0, 2), 0.0);
  EXPECT_TRUE(v.hessian.allFinite());
}

// --- the small extra cases of §3 ---------------------------------------------------------------

TEST(PotentialExtraCases, QuadraticWithShift) {
  auto deck = read_bushing_deck(
      "*CONNECTOR PLASTICITY\n*CONNECTOR HARDENING, DEFINITION=TABULAR\n1.0, 0.0\n"
      "*CONNECTOR POTENTIAL\n1, 100.0, , ABS, 10.0\n2, 50.0, , MACAULEY\n");
  ASSERT_EQ(error_count(*deck), 0) << deck->dump();
  const ConnectorPotential p = compile_potential(*deck);
  PotentialValue v;
  p.evaluate(vec(70, -20, 0, 0, 0, 0), v, true);
  // X1 = 0.6, X2 = −0.4 → P2 = 0, P = 0.6, ∂P/∂f = (0.01, 0): a few roundings only.
  EXPECT_NEAR(v.value, 0.6, 1e-15);
  EXPECT_NEAR(v.gradient[0], 0.01, 1e-17);
  EXPECT_EQ(v.gradient[1], 0.0);
  EXPECT_EQ(v.active, -1);
  // (1/P)[1/R1² − n1²] = 0 on the active one-contribution surface.
  EXPECT_NEAR(v.hessian(0, 0), 0.0, 1e-18);
  EXPECT_EQ(v.hessian(1, 1), 0.0);
}

TEST(PotentialExtraCases, MaxTieTakesTheLowestIndex) {
  auto deck = read_bushing_deck(
      "*CONNECTOR PLASTICITY\n*CONNECTOR HARDENING, DEFINITION=TABULAR\n1.0, 0.0\n"
      "*CONNECTOR POTENTIAL, OPERATOR=MAX\n1, 100.0\n2, 50.0\n");
  ASSERT_EQ(error_count(*deck), 0) << deck->dump();
  const ConnectorPotential p = compile_potential(*deck);
  EXPECT_TRUE(p.is_max());
  PotentialValue v;
  p.evaluate(vec(30, 15, 0, 0, 0, 0), v, true);
  EXPECT_EQ(v.active, 0);
  EXPECT_DOUBLE_EQ(v.value, 0.3);
  EXPECT_EQ(v.gradient, vec(1.0 / 100.0, 0, 0, 0, 0, 0));
  EXPECT_TRUE(v.hessian.isZero(0.0));
  // The other order of the same tie: still the first line.
  p.evaluate(vec(-30, -15, 0, 0, 0, 0), v, false);
  EXPECT_EQ(v.active, 0);
  EXPECT_EQ(v.gradient, vec(-1.0 / 100.0, 0, 0, 0, 0, 0));
}

// --- finite-difference checks ------------------------------------------------------------------

// Derived components shared by the cases below.
const std::string kDerived =
    "*CONNECTOR DERIVED COMPONENT, NAME=shear\n1, 2\n1.0, 1.0\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=shear\n6\n0.4\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=normal, OPERATOR=MACAULEY SUM\n3\n1.0\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=normal\n4, 5\n0.8, 0.8\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=twist\n4, 6\n2.0, -1.5\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=lin, OPERATOR=SUM\n2, 4\n1.0, -3.0\n";
double shear(const Vector6& c) { return std::hypot(c[0], c[1]) + 0.4 * std::fabs(c[5]); }
double normal(const Vector6& c) { return mac(c[2]) + 0.8 * std::hypot(c[3], c[4]); }
double twist(const Vector6& c) { return std::hypot(2.0 * c[3], 1.5 * c[5]); }
double lin(const Vector6& c) { return c[1] - 3.0 * c[3]; }

const std::string kPlastic =
    "*CONNECTOR PLASTICITY\n*CONNECTOR HARDENING, DEFINITION=TABULAR\n1.0, 0.0\n";
const std::string kDamage = "*CONNECTOR DAMAGE INITIATION, CRITERION=FORCE\n-1., 1.\n";

struct Case {
  const char* name;
  std::string body;  // owner + potential; kDerived is appended
  std::function<double(const Vector6&)> reference;
};

std::vector<Case> cases() {
  using std::fabs;
  using std::pow;
  return {
      {"SUM beta=1 (ABS, NORM and MACAULEY derived)",
       kPlastic + "*CONNECTOR POTENTIAL, EXPONENT=1.0\n2, 2.0\nshear, 3.0\nnormal, 0.5, , MACAULEY\n",
       [](const Vector6& c) { return fabs(c[1]) / 2 + shear(c) / 3 + mac(normal(c) / 0.5); }},
      {"SUM beta=1.5",
       kPlastic + "*CONNECTOR POTENTIAL, EXPONENT=1.5\n1, 2.0\ntwist, 1.5\nnormal, 0.5, , MACAULEY\n",
       [](const Vector6& c) {
         return pow(pow(fabs(c[0] / 2), 1.5) + pow(twist(c) / 1.5, 1.5) +
                        pow(mac(normal(c) / 0.5), 1.5),
                    1 / 1.5);
       }},
      {"SUM beta=2 with a shift",
       kPlastic + "*CONNECTOR POTENTIAL\nshear, 3.0, , ABS, 0.7\nnormal, 0.5, , MACAULEY\n5, 0.25\n",
       [](const Vector6& c) {
         return std::sqrt(pow((shear(c) - 0.7) / 3, 2) + pow(mac(normal(c) / 0.5), 2) +
                          pow(c[4] / 0.25, 2));
       }},
      {"SUM beta=3",
       kPlastic + "*CONNECTOR POTENTIAL, EXPONENT=3.0\ntwist, 1.0\n3, 0.5, , MACAULEY\n2, 2.0\n"
                  "shear, 4.0\n",
       [](const Vector6& c) {
         return std::cbrt(pow(twist(c), 3) + pow(mac(c[2] / 0.5), 3) + pow(fabs(c[1] / 2), 3) +
                          pow(shear(c) / 4, 3));
       }},
      {"SUM beta=2.5 (std::pow path)",
       kPlastic + "*CONNECTOR POTENTIAL, EXPONENT=2.5\n1, 2.0\nshear, 3.0\n",
       [](const Vector6& c) {
         return pow(pow(fabs(c[0] / 2), 2.5) + pow(shear(c) / 3, 2.5), 1 / 2.5);
       }},
      {"general alpha (damage, ABS, shifts, a negative sign)",
       kDamage + "*CONNECTOR POTENTIAL, EXPONENT=2.0\n1, 2.0, 1.5\nshear, 3.0, 3.0\n"
                 "6, 0.5, 2.5, MACAULEY\n2, 1.0, 1.7, ABS, 0.3\ntwist, 2.0, 2.0, ABS, 0.5\n"
                 "4, 8.0, 1.2, ABS, 0.0, -1.0\n",
       [](const Vector6& c) {
         const double s = pow(fabs(c[0] / 2), 1.5) + pow(shear(c) / 3, 3.0) +
                          pow(mac(c[5] / 0.5), 2.5) + pow(fabs(c[1] - 0.3), 1.7) +
                          pow((twist(c) - 0.5) / 2, 2.0) - pow(fabs(c[3] / 8), 1.2);
         return s >= 0 ? std::sqrt(s) : -std::sqrt(-s);
       }},
      {"sum-type with shifts and negative signs (beta=1)",
       kDamage + "*CONNECTOR POTENTIAL, EXPONENT=1.0\n1, 2.0, , NONE, 0.5, -1.0\n"
                 "lin, 0.5, , NONE, -1.0\n3, 4.0, , NONE, 0.0, 1.0\n2, 1.0, , ABS, 0.2, -1.0\n"
                 "twist, 2.0, , MACAULEY, 1.0, -1.0\n",
       [](const Vector6& c) {
         return -(c[0] - 0.5) / 2 + (lin(c) + 1) / 0.5 + c[2] / 4 - fabs(c[1] - 0.2) -
                mac((twist(c) - 1) / 2);
       }},
      {"MAX through derived components",
       kPlastic + "*CONNECTOR POTENTIAL, OPERATOR=MAX\n1, 2.0\nshear, 3.0\nnormal, 0.5, , MACAULEY\n"
                  "twist, 1.0\n",
       [](const Vector6& c) {
         return std::max({fabs(c[0] / 2), shear(c) / 3, mac(normal(c) / 0.5), twist(c)});
       }},
  };
}

// For every case and six fixed-seed states (components uniform in [−10, 10]): the value
// against the closed form (1e-12 relative: a few roundings of pow/sqrt), the gradient against
// central differences of the closed form and the Hessian against central differences of the
// returned gradient (1e-6 of the largest entry: the fixture's step makes truncation and
// round-off about 1e-10 away from the kinks, which the MAX case also keeps away from ties).
TEST(PotentialDerivatives, GradientAndHessianMatchCentralDifferences) {
  for (const Case& k : cases()) {
    auto deck = read_bushing_deck(k.body + kDerived);
    ASSERT_EQ(error_count(*deck), 0) << k.name << "\n" << deck->dump();
    const ConnectorPotential p = compile_potential(*deck);
    int checked = 0;
    for (unsigned seed = 21; seed < 40 && checked < 6; ++seed) {
      std::mt19937 rng(seed);
      const Vector6 c = potential_test::random_state(rng, 10.0);
      if (p.is_max()) {
        // Away from ties: the two largest contributions differ by more than 1%.
        double first = -1e300, second = -1e300;
        for (int i = 0; i < p.contribution_count(); ++i) {
          PotentialValue one;
          p.evaluate_contribution(i, c, one, false);
          if (one.value > first) {
            second = first;
            first = one.value;
          } else if (one.value > second) {
            second = one.value;
          }
        }
        if (first - second < 1e-2 * std::fabs(first)) continue;
      }
      ++checked;
      const std::string what = std::string(k.name) + " seed " + std::to_string(seed);
      PotentialValue v;
      p.evaluate(c, v, true);
      const double ref = k.reference(c);
      EXPECT_NEAR(v.value, ref, 1e-12 * std::max(1.0, std::fabs(ref))) << what;
      EXPECT_EQ(p.value(c), v.value) << what;
      expect_fd_derivatives(v.gradient.transpose(), k.reference, c, 1e-6, 1e-12,
                            what + " gradient");
      PotentialValue no_hessian;
      p.evaluate(c, no_hessian, false);
      EXPECT_EQ(no_hessian.gradient, v.gradient) << what;
      expect_fd_derivatives(
          v.hessian, [&](const Vector6& x) { return gradient_at(p, x); }, c, 1e-6, 1e-12,
          what + " Hessian");
      EXPECT_TRUE(v.hessian.isApprox(v.hessian.transpose(), 1e-14)) << what;
    }
    EXPECT_EQ(checked, 6) << k.name;
  }
}

// evaluate_contribution: s_i·P_i alone, with its gradient and Hessian, for every contribution of
// the MAX case (its surfaces of the multi-surface return) and of the general-α case; it agrees
// with evaluate on the active surface of MAX.
TEST(PotentialDerivatives, SingleContributionsMatchCentralDifferences) {
  const std::vector<Case> all = cases();
  for (const Case& k : {all[5], all[7]}) {
    auto deck = read_bushing_deck(k.body + kDerived);
    const ConnectorPotential p = compile_potential(*deck);
    for (unsigned seed : {41u, 42u, 43u}) {
      std::mt19937 rng(seed);
      const Vector6 c = potential_test::random_state(rng, 10.0);
      for (int i = 0; i < p.contribution_count(); ++i) {
        const std::string what = std::string(k.name) + " contribution " + std::to_string(i);
        PotentialValue one;
        p.evaluate_contribution(i, c, one, true);
        EXPECT_EQ(one.active, i);
        auto value = [&](const Vector6& x) {
          PotentialValue w;
          p.evaluate_contribution(i, x, w, false);
          return w.value;
        };
        expect_fd_derivatives(one.gradient.transpose(), value, c, 1e-6, 1e-12, what + " gradient");
        expect_fd_derivatives(
            one.hessian, [&](const Vector6& x) { return gradient_at(p, x, i); }, c, 1e-6, 1e-12,
            what + " Hessian");
      }
      if (p.is_max()) {
        PotentialValue v, one;
        p.evaluate(c, v, true);
        p.evaluate_contribution(v.active, c, one, true);
        EXPECT_EQ(v.value, one.value);
        EXPECT_EQ(v.gradient, one.gradient);
        // The same products in another order: a few roundings apart.
        expect_close(v.hessian, one.hessian, 1e-14, 1e-300, "MAX active surface Hessian");
      }
    }
  }
}

// §2.3: a negative base S with 1/β not an integer gives the odd extension sgn(S)|S|^(1/β); with
// 1/β an integer the real power. Values in closed form; derivatives against central differences.
TEST(PotentialDerivatives, NegativeBaseUsesTheOddExtensionOrTheRealPower) {
  struct Odd {
    const char* body;
    Vector6 c;
    double value;
    bool negative_base;
  };
  const Odd odd[] = {
      // S = 1 − 4 = −3 → −sqrt(3)
      {"*CONNECTOR POTENTIAL, EXPONENT=2.0\n1, 1.0\n2, 1.0, , ABS, 0.0, -1.0\n",
       vec(1, 2, 0, 0, 0, 0), -std::sqrt(3.0), true},
      // β = 3: S = 1 − 8 = −7 → −cbrt(7)
      {"*CONNECTOR POTENTIAL, EXPONENT=3.0\n1, 1.0\n2, 1.0, , ABS, 0.0, -1.0\n",
       vec(-1, 2, 0, 0, 0, 0), -std::cbrt(7.0), true},
      // β = 1.5: S = 1 − 8 = −7 → −7^(2/3)
      {"*CONNECTOR POTENTIAL, EXPONENT=1.5\n1, 1.0\n2, 0.25, , ABS, 0.0, -1.0\n",
       vec(1, 1, 0, 0, 0, 0), -std::pow(7.0, 2.0 / 3.0), true},
      // β = 0.5, α = 0.5: S = 1 − 2 = −1, 1/β = 2 → S² = 1
      {"*CONNECTOR POTENTIAL, EXPONENT=0.5\n1, 1.0\n2, 1.0, , ABS, 0.0, -1.0\n",
       vec(1, -4, 0, 0, 0, 0), 1.0, false},
  };
  for (const Odd& o : odd) {
    auto deck = read_bushing_deck(kDamage + o.body);
    ASSERT_EQ(error_count(*deck), 0) << deck->dump();
    const ConnectorPotential p = compile_potential(*deck);
    PotentialValue v;
    p.evaluate(o.c, v, true);
    EXPECT_NEAR(v.value, o.value, 1e-14) << o.body;
    EXPECT_EQ(v.negative_base, o.negative_base) << o.body;
    expect_fd_derivatives(
        v.gradient.transpose(), [&](const Vector6& x) { return p.value(x); }, o.c, 1e-6, 1e-12,
        std::string(o.body) + " gradient");
    expect_fd_derivatives(
        v.hessian, [&](const Vector6& x) { return gradient_at(p, x); }, o.c, 1e-6, 1e-12,
        std::string(o.body) + " Hessian");
  }
}

// --- at and near the kinks ---------------------------------------------------------------------

// P_i = 0 with β > 1 (§2.5): P is differentiable there and ∂P/∂E_i = 0. One-sided differences
// from the active side tend to 0 like h^(β−1) (h for β = 2, sqrt(h) for β = 1.5), from the
// inactive side of a MACAULEY contribution they are exactly 0. Bounds: (P(h) − P(0))/h is about
// (1/β)(h/R1)^β/(h·P^(β−1)); the checks allow 10 times that plus round-off 4ε·P/h.
TEST(PotentialKinks, OneSidedDifferencesAtAZeroContributionTendToTheReturnedZero) {
  for (double beta : {1.5, 2.0}) {
    auto deck = read_bushing_deck(kPlastic + "*CONNECTOR POTENTIAL, EXPONENT=" +
                                  std::to_string(beta) + "\n3, 0.02, , MACAULEY\n1, 0.05, , ABS\n"
                                  "2, 0.5, , ABS\n");
    ASSERT_EQ(error_count(*deck), 0) << deck->dump();
    const ConnectorPotential p = compile_potential(*deck);
    const Vector6 c = vec(20, 0, 0, 0, 0, 0);  // X1 = 0 (MACAULEY), X3 = 0 (ABS), P = 400
    PotentialValue v;
    p.evaluate(c, v, true);
    EXPECT_EQ(v.gradient[2], 0.0);
    EXPECT_EQ(v.gradient[1], 0.0);
    EXPECT_TRUE(v.hessian.allFinite());
    const double pv = v.value;
    for (double h : {1e-2, 1e-4, 1e-6}) {
      for (int j : {2, 1}) {
        const double r = j == 2 ? 0.02 : 0.5;
        const double bound = 10 * std::pow(h / r, beta) / (beta * h * std::pow(pv, beta - 1)) +
                             4 * std::numeric_limits<double>::epsilon() * pv / h;
        Vector6 cp = c;
        cp[j] += h;
        EXPECT_LE(std::fabs((p.value(cp) - pv) / h), bound) << "beta " << beta << " h " << h;
        Vector6 cm = c;
        cm[j] -= h;
        const double left = (pv - p.value(cm)) / h;
        if (j == 2) {
          EXPECT_EQ(left, 0.0);  // inactive side of the Macaulay bracket
        } else {
          EXPECT_LE(std::fabs(left), bound);  // |X| is symmetric
        }
      }
    }
    // 1 < β < 2: the unbounded diagonal term is set to 0 (§2.5); β = 2: the exact value
    // (1/P)·s_i/R_i²·H'² with H' = 0 at the kink is 0 too.
    EXPECT_EQ(v.hessian(2, 2), 0.0);
    EXPECT_EQ(v.hessian(1, 1), 0.0);
  }
}

// Where P is not differentiable the defined subgradients are returned exactly: |x| and <x> at 0
// (H' = 0), NORM at r = 0 (0), P = 0 (all zero, §2.5), a base cancelling to 0 (all zero).
TEST(PotentialKinks, DefinedSubgradientsAreReturnedExactly) {
  auto deck = read_bushing_deck(kPlastic +
                                "*CONNECTOR POTENTIAL, EXPONENT=1.0\n1, 2.0\n2, 1.0, , MACAULEY\n"
                                "shear, 3.0\n" + kDerived);
  ASSERT_EQ(error_count(*deck), 0) << deck->dump();
  const ConnectorPotential p = compile_potential(*deck);
  PotentialValue v;
  // f1 = 0 (|x| at 0), f2 = 0 (<x> at 0) and shear's NORM term at r = 0 (f1 = f2 = 0); m3 ≠ 0.
  p.evaluate(vec(0, 0, 0, 0, 0, -5), v, true);
  EXPECT_DOUBLE_EQ(v.value, 2.0 / 3.0);
  EXPECT_EQ(v.gradient, vec(0, 0, 0, 0, 0, -0.4 / 3.0));
  EXPECT_TRUE(v.hessian.isZero(0.0));

  // P = 0: value, gradient and Hessian 0, for a SUM with β ≠ 1 at c = 0 and at a state where
  // every contribution is zero without c being zero (normal's Macaulay term inactive).
  auto weld = read_bushing_deck(kSpotWeldBody, kSpotWeldParameters);
  const ConnectorPotential pw = compile_potential(*weld);
  for (const Vector6& c : {Vector6(Vector6::Zero()), vec(0, 0, -100, 0, 0, 0)}) {
    pw.evaluate(c, v, true);
    EXPECT_EQ(v.value, 0.0);
    EXPECT_TRUE(v.gradient.isZero(0.0));
    EXPECT_TRUE(v.hessian.isZero(0.0));
  }

  // A base that cancels exactly (β = 2, S = 4 − 4): value 0 and zero derivatives, the clinch
  // choice documented in connector_potential.cpp.
  auto cancel = read_bushing_deck(kDamage +
                                  "*CONNECTOR POTENTIAL, EXPONENT=2.0\n1\n2, , , ABS, 0.0, -1.0\n");
  ASSERT_EQ(error_count(*cancel), 0) << cancel->dump();
  compile_potential(*cancel).evaluate(vec(2, 2, 0, 0, 0, 0), v, true);
  EXPECT_EQ(v.value, 0.0);
  EXPECT_TRUE(v.gradient.isZero(0.0));
  EXPECT_TRUE(v.hessian.isZero(0.0));
}

// "Zero" is relative (§2.5): |X_i| ≤ 1e-12·max|X| counts as P_i = 0, so β = 1.5 does not form the
// (P_i/P)^(−1/2) ≈ 1e7 diagonal term from a round-off-sized X_i; a contribution that is small
// but above the threshold keeps its exact derivatives.
TEST(PotentialKinks, ZeroThresholdIsRelativeToTheLargestContribution) {
  auto deck =
      read_bushing_deck(kPlastic + "*CONNECTOR POTENTIAL, EXPONENT=1.5\n1, 1.0\n2, 1.0\n");
  const ConnectorPotential p = compile_potential(*deck);
  PotentialValue v;
  p.evaluate(vec(1, 1e-14, 0, 0, 0, 0), v, true);
  EXPECT_EQ(v.gradient[1], 0.0);
  EXPECT_EQ(v.hessian(1, 1), 0.0);
  EXPECT_DOUBLE_EQ(v.gradient[0], 1.0);
  p.evaluate(vec(1, 1e-6, 0, 0, 0, 0), v, true);
  // n_2 = (P_2/P)^(1/2) with P = (1 + 1e-9)^(2/3): 1e-3 to 1e-9 relative.
  EXPECT_NEAR(v.gradient[1], 1e-3, 1e-12);
  // Diagonal ((β − 1)/P)(P_2/P)^(−1/2) − rank-one: 0.5·1e3 to 1e-6 relative.
  EXPECT_NEAR(v.hessian(1, 1), 500.0, 1e-3);
}

// §2.8: only the listed components are read. NaN in every other slot leaves the result finite,
// and the gradient and Hessian are exactly 0 outside components().
TEST(PotentialComponents, NeverReadsComponentsOutsideTheUnion) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::string bodies[] = {
      kPlastic + "*CONNECTOR POTENTIAL, EXPONENT=1.5\n1, 2.0\nnormal, 0.5, , MACAULEY\n",
      kPlastic + "*CONNECTOR POTENTIAL\ntwist, 2.0\n2, 0.5\n",
      kPlastic + "*CONNECTOR POTENTIAL, OPERATOR=MAX\n1, 2.0\ntwist, 1.0\n",
      kDamage + "*CONNECTOR POTENTIAL, EXPONENT=1.0\nlin, 0.5, , NONE\n3, 2.0, , NONE\n",
  };
  const ComponentMask expected[] = {0b011101, 0b101010, 0b101001, 0b001110};
  for (int b = 0; b < 4; ++b) {
    auto deck = read_bushing_deck(bodies[b] + kDerived);
    ASSERT_EQ(error_count(*deck), 0) << deck->dump();
    const ConnectorPotential p = compile_potential(*deck);
    EXPECT_EQ(p.components(), expected[b]) << bodies[b];
    Vector6 c = vec(1.5, -2.0, 0.7, 3.0, 0.25, -1.25);
    for (int j = 0; j < 6; ++j) {
      if (!(p.components() & (1u << j))) c[j] = nan;
    }
    PotentialValue v;
    p.evaluate(c, v, true);
    EXPECT_TRUE(std::isfinite(v.value)) << bodies[b];
    EXPECT_TRUE(v.gradient.allFinite()) << bodies[b];
    EXPECT_TRUE(v.hessian.allFinite()) << bodies[b];
    EXPECT_TRUE(std::isfinite(p.value(c))) << bodies[b];
    for (int i = 0; i < p.contribution_count(); ++i) {
      PotentialValue one;
      p.evaluate_contribution(i, c, one, true);
      EXPECT_TRUE(one.gradient.allFinite() && one.hessian.allFinite()) << bodies[b];
    }
    for (int j = 0; j < 6; ++j) {
      if (p.components() & (1u << j)) continue;
      EXPECT_EQ(v.gradient[j], 0.0) << bodies[b];
      EXPECT_TRUE(v.hessian.row(j).isZero(0.0) && v.hessian.col(j).isZero(0.0)) << bodies[b];
    }
  }
}

}  // namespace
}  // namespace clinch
