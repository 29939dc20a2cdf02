// Evaluation of derived components (derived-components-and-potentials.md §1.3, §1.4): values
// against closed forms written out in the test, gradients against central differences of those
// closed forms, Hessians against central differences of the returned gradient, and the
// subgradients of the §1.4 table returned exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "src/behavior/potential/derived_component.hpp"
#include "tests/tangent/potential_fixture.hpp"

namespace clinch {
namespace {

using potential_test::expect_fd_derivatives;

double mac(double x) { return x > 0 ? x : 0; }

// One derived component per operator, SIGN=NEGATIVE, negative coefficients and a name with
// several terms of different operators. A damage potential uses them all, so that every name
// is referenced (damage contexts accept any derived-component type, §1.5).
const std::string kBody =
    "*CONNECTOR DAMAGE INITIATION, CRITERION=FORCE\n-1., 1.\n"
    "*CONNECTOR POTENTIAL, EXPONENT=1.0\n"
    "nrm\nmac\nlin, , , NONE\nneg\nmulti\none\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=nrm\n1, 2, 4\n2.0, -0.5, 3.0\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=mac, OPERATOR=MACAULEY SUM\n1, 3, 6\n1.0, -2.0, 0.5\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=lin, OPERATOR=SUM\n2, 5\n1.5, -1.0\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=neg, SIGN=NEGATIVE\n3, 5\n1.0, 2.0\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=multi, OPERATOR=MACAULEY SUM\n3\n1.0\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=multi\n4, 5\n0.8, -0.8\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=multi, OPERATOR=SUM, SIGN=NEGATIVE\n1, 6\n2.0, -1.0\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=multi, OPERATOR=MACAULEY SUM, SIGN=NEGATIVE\n2\n-1.0\n"
    "*CONNECTOR DERIVED COMPONENT, NAME=one\n6\n-0.4\n";

// Independent closed forms of the derived components above (§1.3).
double closed_form(const std::string& name, const Vector6& c) {
  const double f1 = c[0], f2 = c[1], f3 = c[2], m1 = c[3], m2 = c[4], m3 = c[5];
  if (name == "nrm") return std::sqrt(4 * f1 * f1 + 0.25 * f2 * f2 + 9 * m1 * m1);
  if (name == "mac") return mac(f1) + mac(-2 * f3) + mac(0.5 * m3);
  if (name == "lin") return 1.5 * f2 - m2;
  if (name == "neg") return -std::hypot(f3, 2 * m2);
  if (name == "multi") {
    return mac(f3) + 0.8 * std::hypot(m1, m2) - (2 * f1 - m3) - mac(-f2);
  }
  if (name == "one") return 0.4 * std::fabs(m3);
  return std::numeric_limits<double>::quiet_NaN();
}

struct Fixture {
  std::unique_ptr<CheckedDeck> deck = potential_test::read_bushing_deck(kBody);
  DerivedComponent get(const char* key) const {
    return DerivedComponent::compile(potential_test::behavior_of(*deck), key);
  }
};

const char* const kNames[] = {"NRM", "MAC", "LIN", "NEG", "MULTI", "ONE"};

std::string lower(std::string s) {
  for (char& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return s;
}

TEST(DerivedComponentEval, DeckIsCleanAndMasksAndTypesAreRight) {
  Fixture f;
  ASSERT_EQ(potential_test::error_count(*f.deck), 0) << f.deck->dump();
  EXPECT_EQ(f.get("NRM").components(), 0b001011);
  EXPECT_EQ(f.get("MAC").components(), 0b100101);
  EXPECT_EQ(f.get("MULTI").components(), 0b111111);
  EXPECT_EQ(f.get("NRM").type(), DerivedType::Norm);
  EXPECT_EQ(f.get("MAC").type(), DerivedType::Macauley);
  EXPECT_EQ(f.get("LIN").type(), DerivedType::Sum);
  EXPECT_EQ(f.get("MULTI").type(), DerivedType::Mixed);
  EXPECT_TRUE(f.get("NRM").has_hessian());
  EXPECT_FALSE(f.get("MAC").has_hessian());
  EXPECT_FALSE(f.get("LIN").has_hessian());
  EXPECT_THROW(f.get("NOPE"), std::invalid_argument);
}

// Values agree with the closed forms to round-off (1e-13 relative: a few operations on
// numbers of order 10). Gradients: central differences of the closed form; Hessians: central
// differences of the returned gradient. The tolerance 1e-6 of the largest entry covers the
// truncation and round-off of the fixture's step (about 1e-10 here: the random states stay well
// away from the kinks, whose distance from a state uniform in [−10, 10] is rarely below 0.1).
TEST(DerivedComponentEval, EveryOperatorMatchesClosedFormAndFiniteDifferences) {
  Fixture f;
  ASSERT_EQ(potential_test::error_count(*f.deck), 0) << f.deck->dump();
  for (const char* key : kNames) {
    const DerivedComponent g = f.get(key);
    const std::string name = lower(key);
    for (unsigned seed : {11u, 12u, 13u, 14u, 15u}) {
      std::mt19937 rng(seed);
      const Vector6 c = potential_test::random_state(rng, 10.0);
      Vector6 grad;
      Matrix6 hess;
      const double v = g.evaluate(c, &grad, &hess);
      EXPECT_NEAR(v, closed_form(name, c), 1e-13 * std::max(1.0, std::fabs(v)))
          << name << " seed " << seed;
      EXPECT_EQ(g.value(c), v);
      expect_fd_derivatives(
          grad.transpose(), [&](const Vector6& x) { return closed_form(name, x); }, c, 1e-6, 1e-12,
          name + " gradient");
      const auto gradient = [&](const Vector6& x) {
        Vector6 gx;
        g.evaluate(x, &gx, nullptr);
        return gx;
      };
      expect_fd_derivatives(hess, gradient, c, 1e-6, 1e-12, name + " Hessian");
      EXPECT_TRUE(hess.isApprox(hess.transpose(), 1e-15)) << name;
    }
  }
}

// A one-component NORM term is |C·c_k| (§1.3): gradient C·sgn, Hessian exactly 0.
TEST(DerivedComponentEval, OneComponentNormIsAbsoluteValueWithoutCurvature) {
  Fixture f;
  const DerivedComponent g = f.get("ONE");
  Vector6 c = Vector6::Zero();
  c[5] = -3.0;
  Vector6 grad;
  Matrix6 hess;
  EXPECT_DOUBLE_EQ(g.evaluate(c, &grad, &hess), 1.2);
  EXPECT_DOUBLE_EQ(grad[5], -0.4);  // d|−0.4·m3|/dm3 at m3 = −3
  EXPECT_TRUE(hess.isZero(0.0));
  c[5] = 0.0;  // the kink: subgradient 0 (§1.4 table)
  EXPECT_EQ(g.evaluate(c, &grad, &hess), 0.0);
  EXPECT_TRUE(grad.isZero(0.0));
  EXPECT_TRUE(hess.isZero(0.0));
}

// §1.4 table: NORM with r = 0 → 0, 0, 0; MACAULEY SUM at y_j = 0 → H(0) = 0; m = 0 → all 0.
TEST(DerivedComponentEval, NonSmoothPointsReturnTheDefinedSubgradients) {
  Fixture f;
  Vector6 grad;
  Matrix6 hess;
  const Vector6 zero = Vector6::Zero();
  for (const char* key : kNames) {
    const DerivedComponent g = f.get(key);
    EXPECT_EQ(g.evaluate(zero, &grad, &hess), 0.0) << key;
    if (g.type() != DerivedType::Sum && g.type() != DerivedType::Mixed) {
      EXPECT_TRUE(grad.isZero(0.0)) << key;
    }
    EXPECT_TRUE(hess.isZero(0.0)) << key;
  }
  // multi at c = 0: only its SUM term −(2·f1 − m3) has a slope.
  f.get("MULTI").evaluate(zero, &grad, nullptr);
  Vector6 sum_slope;
  sum_slope << -2.0, 0.0, 0.0, 0.0, 0.0, 1.0;
  EXPECT_EQ(grad, sum_slope);
  // nrm at r = 0 with other components non-zero (they are not listed).
  Vector6 c;
  c << 0.0, 0.0, 5.0, 0.0, 7.0, 1.0;
  EXPECT_EQ(f.get("NRM").evaluate(c, &grad, &hess), 0.0);
  EXPECT_TRUE(grad.isZero(0.0));
  EXPECT_TRUE(hess.isZero(0.0));
  // mac with y_1 = 0 exactly and y_3 = −2·f3 > 0: only component 3 has a slope.
  c << 0.0, 0.0, -1.0, 0.0, 0.0, 0.0;
  EXPECT_EQ(f.get("MAC").evaluate(c, &grad, &hess), 2.0);
  Vector6 expected = Vector6::Zero();
  expected[2] = -2.0;
  EXPECT_EQ(grad, expected);
  // SUM is smooth: constant gradient even at c = 0, where m = 0 (the clinch reading of "m = 0 →
  // everything 0": it concerns the terms that could form 1/r, see derived_component.cpp).
  EXPECT_EQ(f.get("LIN").evaluate(zero, &grad, nullptr), 0.0);
  expected.setZero();
  expected[1] = 1.5;
  expected[4] = -1.0;
  EXPECT_EQ(grad, expected);
}

// "Zero" is relative (§1.4): r ≤ 1e-12·m with m the largest |y_j| over all terms of the name.
TEST(DerivedComponentEval, ZeroThresholdIsRelativeToTheWholeDerivedComponent) {
  Fixture f;
  const DerivedComponent multi = f.get("MULTI");
  Vector6 grad;
  Matrix6 hess;
  // NORM term r = 0.8·sqrt(2)·1e-14 against m = |2·f1| = 2: below 1e-12·m, so treated as 0.
  Vector6 c;
  c << 1.0, 0.0, 0.0, 1e-14, 1e-14, 0.0;
  EXPECT_EQ(multi.evaluate(c, &grad, &hess), -2.0);
  EXPECT_EQ(grad[3], 0.0);
  EXPECT_EQ(grad[4], 0.0);
  EXPECT_TRUE(hess.isZero(0.0));
  // The same NORM term alone at tiny absolute values is not zero: its own m is as small.
  c << 0.0, 0.0, 0.0, 3e-200, 4e-200, 0.0;
  EXPECT_DOUBLE_EQ(multi.evaluate(c, &grad, &hess), 0.8 * 5e-200);
  EXPECT_DOUBLE_EQ(grad[3], 0.8 * 0.6);
  EXPECT_DOUBLE_EQ(grad[4], 0.8 * 0.8);  // C·y/r = (−0.8)(−0.8·4e-200)/(5e-200·0.8)
}

// Only the listed components are read: NaN elsewhere leaves value and derivatives finite, and
// the gradient and Hessian are exactly zero outside the listed components.
TEST(DerivedComponentEval, NeverReadsUnlistedComponents) {
  Fixture f;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const char* key : {"NRM", "MAC", "LIN", "NEG", "ONE"}) {
    const DerivedComponent g = f.get(key);
    Vector6 c;
    c << 1.5, -2.0, -0.7, 3.0, 0.25, -1.25;
    for (int j = 0; j < 6; ++j) {
      if (!(g.components() & (1u << j))) c[j] = nan;
    }
    Vector6 grad;
    Matrix6 hess;
    EXPECT_TRUE(std::isfinite(g.evaluate(c, &grad, &hess))) << key;
    EXPECT_TRUE(grad.allFinite()) << key;
    EXPECT_TRUE(hess.allFinite()) << key;
    for (int j = 0; j < 6; ++j) {
      if (g.components() & (1u << j)) continue;
      EXPECT_EQ(grad[j], 0.0) << key;
      EXPECT_TRUE(hess.row(j).isZero(0.0) && hess.col(j).isZero(0.0)) << key;
    }
  }
}

}  // namespace
}  // namespace clinch
