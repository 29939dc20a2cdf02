// The damping law's tangent (behaviors.md §8: ∂f^v/∂u = C/Δt plus the table slopes over Δt)
// against central differences through the shared checker (§1.4), and its force against the
// closed form, for linear, coupled and tabulated damping, inside and outside the table.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "parser/deck_reader.hpp"
#include "src/behavior/damping/damping_behavior.hpp"
#include "tests/tangent/behavior_tangent_check.hpp"
#include "tests/unit/checked_deck.hpp"

namespace clinch {
namespace {

constexpr double kDt = 0.1;

struct DampingLaw {
  CheckedDeck deck;
  std::unique_ptr<Behavior> law;
};

std::unique_ptr<DampingLaw> make_law(const std::string& body) {
  auto p = std::make_unique<DampingLaw>();
  read_deck_text("b.inp", "*CONNECTOR BEHAVIOR, NAME=B, EXTRAPOLATION=LINEAR\n" + body,
                 p->deck.sources, p->deck.model, p->deck.sink);
  for (const Diagnostic& d : p->deck.sink.diagnostics()) {
    if (d.code != DiagCode::no_step) EXPECT_NE(d.severity, Severity::Error) << p->deck.dump();
  }
  p->law = make_damping_behavior(p->deck.model.behaviors.behaviors.at(0), 0b111111);
  return p;
}

BehaviorOutput integrate(const Behavior& law, const Vector6& old, const Vector6& u) {
  BehaviorOutput out;
  const Vector6 increment = u - old;
  const BehaviorInput in{old, increment, 1.0, kDt, {}, TangentRequest::Consistent};
  EXPECT_EQ(law.integrate(in, out), IntegrationStatus::Success);
  return out;
}

// §1.4 with u_s = 1e-3, every evaluation from the same converged motion `old`; k_s = c/Δt.
void expect_fd_tangent(const Behavior& law, const Vector6& old, const Vector6& u, double k_s) {
  const BehaviorOutput at = integrate(law, old, u);
  const auto force = [&](const Eigen::VectorXd& x, Eigen::VectorXd& f) {
    f = integrate(law, old, Vector6(x)).force;
    return true;
  };
  expect_fd_tangent_rule(force, u, at.tangent, 1e-3, k_s);
}

TEST(DampingTangent, LinearAndCoupledAddOnAComponent) {
  auto p = make_law("*CONNECTOR DAMPING, COMPONENT=1\n50.\n*CONNECTOR DAMPING\n"
                    "10., 1., 20., 0., 0., 30., 0., 0.\n0., 0., 0., 0., 0., 0., 0., 0.\n"
                    "0., 0., 0., 0., 40.\n");
  ASSERT_TRUE(p->law);
  Vector6 old = Vector6::Zero(), u = Vector6::Zero();
  old << 0.1, 0.0, 0.2, 0, 0, 0;
  u << 0.13, -0.01, 0.25, 0.02, -0.03, 0.01;
  const BehaviorOutput out = integrate(*p->law, old, u);
  const Vector6 v = (u - old) / kDt;
  // C11 = 50 + 10, C12 = 1, C22 = 20, C33 = 30, C66 = 40 (column-wise upper triangle, §4.3).
  EXPECT_NEAR(out.force[0], 60.0 * v[0] + 1.0 * v[1], 1e-12);
  EXPECT_NEAR(out.force[1], 1.0 * v[0] + 20.0 * v[1], 1e-12);
  EXPECT_NEAR(out.force[2], 30.0 * v[2], 1e-12);
  EXPECT_NEAR(out.force[5], 40.0 * v[5], 1e-12);
  expect_fd_tangent(*p->law, old, u, 600.0);
}

TEST(DampingTangent, TableInsideAndBeyondItsEnds) {
  auto p = make_law("*CONNECTOR DAMPING, COMPONENT=2, NONLINEAR\n-10., -1.\n0., 0.\n3., 0.2\n"
                    "7., 0.5\n");
  ASSERT_TRUE(p->law);
  for (double v : {0.1, 0.35, 0.8, -1.5}) {
    Vector6 u = Vector6::Zero();
    u[1] = v * kDt;
    const BehaviorOutput out = integrate(*p->law, Vector6::Zero(), u);
    const double expected = v < 0 ? -10.0 + 10.0 * (v + 1.0)
                            : v < 0.2 ? 15.0 * v
                                      : 3.0 + (4.0 / 0.3) * (v - 0.2);
    EXPECT_NEAR(out.force[1], expected, 1e-12) << "v = " << v;
    expect_fd_tangent(*p->law, Vector6::Zero(), u, 150.0);
  }
}

}  // namespace
}  // namespace clinch
