// Finite-difference checks of the friction law's consistent tangent (friction.md §4.2) through
// the shared checker (behaviors.md §1.4): against the motion u and against the connector's
// constraint forces λ, with a linear elastic law below it in the stack, so that a contact force
// read from an elastic component or from a multiplier is checked through the chain rule too.
// States: sticking, slipping, just past the stick–slip transition (both sides of the check stay
// on the slip side: one-sided at the kink), reversed, at zero and near-zero contact force,
// rate-dependent, with F_int(γ), with the TAUMAX cap, and with coupled (SUM and MAX) potentials.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "base/jacobian_check.hpp"
#include "parser/deck_reader.hpp"
#include "src/behavior/friction/friction_behavior.hpp"
#include "tests/unit/checked_deck.hpp"

namespace clinch {
namespace {

constexpr ComponentMask kAll = 0b111111;

Vector6 vec(double a, double b = 0, double c = 0, double d = 0, double e = 0, double f = 0) {
  Vector6 v;
  v << a, b, c, d, e, f;
  return v;
}

// One friction definition read from a behaviour block, integrated on its own with an elastic law
// `below` (force K_e u) under it and constraint forces λ; commit() makes a trial state the
// converged one.
class FrictionDriver {
 public:
  FrictionDriver(const std::string& body, ComponentMask available, ComponentMask constrained,
                 const Vector6& below, double dt = 1.0)
      : below_(below.asDiagonal()), dt_(dt) {
    read_deck_text("b.inp", "*CONNECTOR BEHAVIOR, NAME=B\n" + body, deck_.sources, deck_.model,
                   deck_.sink);
    for (const Diagnostic& d : deck_.sink.diagnostics()) {
      if (d.code != DiagCode::no_step) EXPECT_NE(d.severity, Severity::Error) << deck_.dump();
    }
    ConnectorBehavior& b = deck_.model.behaviors.behaviors.at(0);
    // A predefined definition takes J from the connection type of a section (friction.md
    // §2.3), which a behaviour block alone does not have: the free translations here.
    FrictionDefinition& f = b.frictions.at(0);
    if (f.predefined) {
      f.friction_components = static_cast<ComponentMask>(available & ~constrained & 0b111);
    }
    law_ = make_friction_behavior(b, 0, available, constrained);
    committed_.assign(law_->history_size(), 0.0);
  }
  struct Result {
    IntegrationStatus status = IntegrationStatus::Failure;
    BehaviorOutput out;
    std::vector<double> history;
  };

  Result evaluate(const Vector6& u, const Vector6& lambda,
                  TangentRequest t = TangentRequest::Consistent) const {
    Result r;
    r.history.assign(committed_.size(), std::nan(""));
    r.out.history_new = r.history;
    const Vector6 force_below = below_ * u;
    const Matrix6 force_tangent_below = Matrix6::Zero();
    const Vector6 increment = u - motion_;
    const BehaviorInput in{motion_,      increment, 0.0,         dt_, committed_, t,
                           &force_below, &below_,   &force_tangent_below, &lambda};
    r.status = law_->integrate(in, r.out);
    return r;
  }
  void commit(const Vector6& u, const Vector6& lambda) {
    const Result r = evaluate(u, lambda);
    ASSERT_EQ(r.status, IntegrationStatus::Success) << r.out.message;
    committed_ = r.history;
    motion_ = u;
  }
  double history(const char* output, int component, const Result& r) const {
    const int slot = history_slot(law_->history_layout(), output, component);
    return slot >= 0 ? r.history[static_cast<std::size_t>(slot)] : std::nan("");
  }

  // behaviors.md §1.4 on x = (u, λ): the analytic [∂f/∂u | ∂f/∂λ] against central differences
  // with h = 1e-6·max(|x|∞, 1e-3) (u) and 1e-6·max(|λ|∞, 1) (λ); passes when
  // max|D − D_fd| ≤ 1e-5·max|D| + 1e-8·k_s with k_s the stick stiffness.
  void expect_fd_tangent(const Vector6& u, const Vector6& lambda, double k_s,
                         bool expect_slip) const {
    const Result at = evaluate(u, lambda);
    ASSERT_EQ(at.status, IntegrationStatus::Success) << at.out.message;
    int slot = -1;
    for (int i = 1; i <= 6 && slot < 0; ++i) slot = history_slot(law_->history_layout(), "CSLIPST", i);
    ASSERT_GE(slot, 0);
    EXPECT_EQ(at.history[static_cast<std::size_t>(slot)], expect_slip ? 1.0 : 0.0);
    Eigen::VectorXd x(12);
    x << u, lambda;
    const auto force = [this](const Eigen::VectorXd& y, Eigen::VectorXd& f) {
      const Result r = evaluate(Vector6(y.head<6>()), Vector6(y.tail<6>()), TangentRequest::None);
      f = r.out.force;
      return r.status == IntegrationStatus::Success;
    };
    Eigen::VectorXd steps(12);
    for (int j = 0; j < 6; ++j) {
      steps[j] = tangent_check_step(u.cwiseAbs().maxCoeff(), 1e-3);
      steps[6 + j] = 1e-6 * std::max(lambda.cwiseAbs().maxCoeff(), 1.0);
    }
    Eigen::MatrixXd analytic(6, 12);
    analytic << at.out.tangent, at.out.force_tangent;
    const JacobianReport report = check_jacobian(perturb_additively(force, x), steps, analytic);
    EXPECT_TRUE(report.meets_tangent_rule(k_s)) << "u = " << u.transpose()
                                                << ", λ = " << lambda.transpose() << "\n"
                                                << report;
  }
  const Behavior& law() const { return *law_; }

 private:
  CheckedDeck deck_;
  std::unique_ptr<Behavior> law_;
  Matrix6 below_;
  double dt_;
  std::vector<double> committed_;
  Vector6 motion_ = Vector6::Zero();
};

constexpr double kStick = 1.0e4;
// SLOT on CONN3D2: J = {1}, F_N = sqrt(f2² + f3²) from the multipliers of 2 and 3 (§2.3).
constexpr ComponentMask kSlotAvailable = 0b111001, kSlotConstrained = 0b000110;
const std::string kSlot =
    "*CONNECTOR FRICTION, PREDEFINED, STICK STIFFNESS=1.0e4\n*FRICTION\n0.3\n";

TEST(FrictionTangent, SlotStickingAndSlippingAgainstMotionAndMultipliers) {
  FrictionDriver d(kSlot, kSlotAvailable, kSlotConstrained, Vector6::Zero());
  const Vector6 lambda = vec(0, -800, 300);  // F_N = 854.4, F_lim = 256.3: slip at u1 = 0.0256
  d.expect_fd_tangent(vec(0.01), lambda, kStick, false);
  d.expect_fd_tangent(vec(0.05), lambda, kStick, true);
  d.expect_fd_tangent(vec(-0.05), lambda, kStick, true);
  const FrictionDriver::Result r = d.evaluate(vec(0.05), lambda);
  // Slipping: ∂f1/∂λ2 = μ·sgn(f1)·λ2/F_N (the unsymmetric entry of §7.1), f1 = μ F_N.
  const double fn = std::hypot(800.0, 300.0);
  EXPECT_NEAR(r.out.force[0], 0.3 * fn, 1e-9 * fn);
  EXPECT_NEAR(r.out.force_tangent(0, 1), 0.3 * -800.0 / fn, 1e-12);
  EXPECT_NEAR(r.out.tangent(0, 0), 0.0, 1e-9);
}

TEST(FrictionTangent, SlotJustPastTheTransitionAndAfterAReversal) {
  FrictionDriver d(kSlot, kSlotAvailable, kSlotConstrained, Vector6::Zero());
  const Vector6 lambda = vec(0, -1000);  // F_lim = 300, onset at u1 = 0.03
  // Φ_tr = ±1e-3 F_lim: the central differences (h ≈ 3e-8, 3e-4 of F_lim) stay on one side.
  d.expect_fd_tangent(vec(0.03 * (1 + 1e-3)), lambda, kStick, true);
  d.expect_fd_tangent(vec(0.03 * (1 - 1e-3)), lambda, kStick, false);
  d.commit(vec(0.1), lambda);                       // slipped to u_s = 0.07
  d.expect_fd_tangent(vec(0.09), lambda, kStick, false);   // reversal: stick again
  d.expect_fd_tangent(vec(0.0), lambda, kStick, true);     // and slip the other way
  const FrictionDriver::Result r = d.evaluate(vec(0.0), lambda);
  EXPECT_NEAR(r.out.force[0], -300.0, 1e-9);
  EXPECT_NEAR(d.history("CASU", 1, r), 0.07 + 0.04, 1e-12);
}

// §4.1 step 5 and §4.2 at F_N = 0 and near it (SLOT, μ = 0.3, k = 1e4):
// - F_N = 0, at rest (u = u_s): no capacity, so no stick range: f = 0, tangent 0, CSLIPST 0;
// - F_N = 0, moving: f = 0, all motion is slip (CASU = u1), tangent 0; against λ the central
//   difference straddles the kink of |λ| and gives 0, the subgradient of §4.2;
// - F_N = 1e-16, a constraint reaction of round-off size: its capacity, 3e-17, is below the stick
//   test's resolution 1e-12·|f_tr| (step 3), so it is none: f = 0 exactly;
// - F_N = 1e-3 (above the differences' λ step 1e-6): sticking within the stick range F_lim/k =
//   3e-8, and slipping with f1 = F_lim = 3e-4 and ∂f1/∂λ2 = −μ.
TEST(FrictionTangent, SlotAtZeroAndNearZeroContactForce) {
  FrictionDriver d(kSlot, kSlotAvailable, kSlotConstrained, Vector6::Zero());
  d.expect_fd_tangent(vec(0.0), Vector6::Zero(), kStick, false);
  const FrictionDriver::Result rest = d.evaluate(vec(0.0), Vector6::Zero());
  EXPECT_EQ(rest.out.force[0], 0.0);
  EXPECT_EQ(rest.out.tangent(0, 0), 0.0);
  d.expect_fd_tangent(vec(0.01), Vector6::Zero(), kStick, true);
  const FrictionDriver::Result moving = d.evaluate(vec(0.01), Vector6::Zero());
  EXPECT_EQ(moving.out.force[0], 0.0);
  EXPECT_EQ(moving.out.tangent(0, 0), 0.0);
  EXPECT_EQ(moving.out.force_tangent(0, 1), 0.0);
  EXPECT_NEAR(d.history("CASU", 1, moving), 0.01, 1e-15);
  EXPECT_EQ(d.history("CNF", 1, moving), 0.0);

  const Vector6 round_off = vec(0, 1e-16);
  d.expect_fd_tangent(vec(0.01), round_off, kStick, true);
  const FrictionDriver::Result tiny = d.evaluate(vec(0.01), round_off);
  ASSERT_EQ(tiny.status, IntegrationStatus::Success) << tiny.out.message;
  EXPECT_EQ(tiny.out.force[0], 0.0);

  const Vector6 near_zero = vec(0, -1e-3);
  d.expect_fd_tangent(vec(1e-8), near_zero, kStick, false);
  d.expect_fd_tangent(vec(0.01), near_zero, kStick, true);
  d.expect_fd_tangent(vec(-0.01), near_zero, kStick, true);
  const FrictionDriver::Result slip = d.evaluate(vec(0.01), near_zero);
  EXPECT_NEAR(slip.out.force[0], 3e-4, 1e-18);  // to a few ulps of 3e-4
  EXPECT_NEAR(slip.out.force_tangent(0, 1), -0.3, 1e-12);
}

// SLOT on CONN2D2 (components 1, 2, 6; J = {1}, F_N = |f2| from the multiplier of 2, §2.3) in the
// states of the verification case cae_friction_slot_series at its increment 39, where the normal
// force changes sign inside the increment: slipping forward at N = −7.7 (committed), then the
// states a Newton iteration and its line search pass through as the multiplier moves to +14.3
// (μ = 0.3, k = 1e4): sticking at the full step, slipping forward with N of either sign, and
// slipping backward; ∂f1/∂λ2 = μ·sgn(f1)·sgn(λ2) in slip (§4.2).
TEST(FrictionTangent, Conn2d2SlotWhileTheNormalForceChangesSign) {
  constexpr ComponentMask available = 0b100011, constrained = 0b000010;
  FrictionDriver d(kSlot, available, constrained, Vector6::Zero());
  d.commit(vec(0.01), vec(0, -7.7));  // F_lim = 2.31: u_s = 0.01 − 2.31e-4
  const Vector6 forward = vec(0.0101), backward = vec(0.0097);  // f_tr = 3.31 and −0.69
  d.expect_fd_tangent(forward, vec(0, 14.3), kStick, false);    // F_lim = 4.29: sticks
  d.expect_fd_tangent(forward, vec(0, 5.0), kStick, true);      // F_lim = 1.5: slips
  d.expect_fd_tangent(forward, vec(0, -5.0), kStick, true);
  d.expect_fd_tangent(backward, vec(0, 1.0), kStick, true);  // F_lim = 0.3: slips back
  EXPECT_NEAR(d.evaluate(forward, vec(0, 5.0)).out.force_tangent(0, 1), 0.3, 1e-12);
  EXPECT_NEAR(d.evaluate(forward, vec(0, -5.0)).out.force_tangent(0, 1), -0.3, 1e-12);
  EXPECT_NEAR(d.evaluate(backward, vec(0, 1.0)).out.force_tangent(0, 1), -0.3, 1e-12);
  EXPECT_NEAR(d.evaluate(backward, vec(0, 1.0)).out.force[0], -0.3, 1e-12);
}

// The same through the closest-point return of a coupled potential (CONTACT FORCE from a
// derived component of a multiplier, §2.1 form 3): no capacity at F_N = 0, and at F_N = 1e-6,
// whose capacity 2e-7 is 1e-9 of the trial force, the return still converges (its residuals
// stop at round-off of the trial, not at 1e-12·F_lim) and the force lies on the surface.
TEST(FrictionTangent, CoupledPotentialAtZeroAndNearZeroContactForce) {
  FrictionDriver d("*CONNECTOR FRICTION, CONTACT FORCE=press, STICK STIFFNESS=1.0e4\n"
                   "*CONNECTOR POTENTIAL\n2, 1.\n3, 2.\n*FRICTION\n0.2\n"
                   "*CONNECTOR DERIVED COMPONENT, NAME=press\n1\n1.0\n",
                   kAll, 0, Vector6::Zero());
  const Vector6 u = vec(0, 0.03, -0.02);
  d.expect_fd_tangent(vec(0.0), Vector6::Zero(), kStick, false);
  d.expect_fd_tangent(u, Vector6::Zero(), kStick, true);
  const FrictionDriver::Result none = d.evaluate(u, Vector6::Zero());
  EXPECT_EQ(none.out.force.norm(), 0.0);
  const Vector6 near_zero = vec(-1e-6);
  const FrictionDriver::Result r = d.evaluate(u, near_zero);
  ASSERT_EQ(r.status, IntegrationStatus::Success) << r.out.message;
  // P(f) = sqrt(f2² + (f3/2)²) = F_lim = 2e-7, to the return's floor 64ε·P(f_tr) ≈ 3e-12.
  EXPECT_NEAR(std::hypot(r.out.force[1], r.out.force[2] / 2), 2e-7, 1e-11);
}

// CONTACT FORCE=1 on an elastic component (k_e = 2000 below the friction): F_N = k_e·u1, so the
// friction force depends on u1 through the law below (the chain rule through tangent_below).
TEST(FrictionTangent, ContactForceFromAnElasticComponent) {
  FrictionDriver d("*CONNECTOR FRICTION, COMPONENT=2, CONTACT FORCE=1, STICK STIFFNESS=1.0e4\n"
                   "*FRICTION\n0.25\n",
                   kAll, 0, vec(2000.0));
  d.expect_fd_tangent(vec(-0.3, 0.004), Vector6::Zero(), kStick, false);
  d.expect_fd_tangent(vec(-0.3, 0.04), Vector6::Zero(), kStick, true);
  const FrictionDriver::Result r = d.evaluate(vec(-0.3, 0.04), Vector6::Zero());
  EXPECT_NEAR(r.out.force[1], 0.25 * 600.0, 1e-9);
  EXPECT_NEAR(r.out.tangent(1, 0), 0.25 * -2000.0, 1e-9);  // ∂(μ|k_e u1|)/∂u1, u1 < 0
  EXPECT_EQ(r.out.tangent(0, 1), 0.0);                      // no reverse coupling
}

TEST(FrictionTangent, ExponentialDecayAtASlipRate) {
  // §7.3 with Δt = 0.1: velocity weakening, the tangent k h/(k + h) < 0.
  FrictionDriver d("*CONNECTOR FRICTION, COMPONENT=1, STICK STIFFNESS=1.0e5\n1000.0\n"
                   "*FRICTION, EXPONENTIAL DECAY\n0.4, 0.2, 2.0\n",
                   kAll, 0, Vector6::Zero(), 0.1);
  d.expect_fd_tangent(vec(0.02), Vector6::Zero(), 1e5, true);
  const FrictionDriver::Result r = d.evaluate(vec(0.02), Vector6::Zero());
  EXPECT_NEAR(r.out.force[0], 343.601, 1e-3);
  EXPECT_NEAR(r.out.tangent(0, 0), -2956.94, 1e-2);
  d.commit(vec(0.02), Vector6::Zero());
  d.expect_fd_tangent(vec(0.04), Vector6::Zero(), 1e5, true);
  d.expect_fd_tangent(vec(0.015), Vector6::Zero(), 1e5, false);  // unloading: stick
  d.expect_fd_tangent(vec(0.0), Vector6::Zero(), 1e5, true);     // reversed: slip back
}

// A press fit (§2.4): F_int(γ) from a table, crossed at its breakpoints, together with a contact
// force from a multiplier; and the TAUMAX cap, under which the capacity ignores F_N.
TEST(FrictionTangent, InternalForceTableAndCap) {
  FrictionDriver d("*CONNECTOR FRICTION, COMPONENT=1, CONTACT FORCE=2, STICK STIFFNESS=1.0e4\n"
                   "100., 0.\n300., 0.02\n350., 0.1\n*FRICTION\n0.5\n",
                   kAll, 0, Vector6::Zero());
  d.expect_fd_tangent(vec(0.03), vec(0, 50), kStick, true);
  d.expect_fd_tangent(vec(0.1), vec(0, -50), kStick, true);
  FrictionDriver capped("*CONNECTOR FRICTION, COMPONENT=1, CONTACT FORCE=2, STICK STIFFNESS=1.0e4\n"
                        "*FRICTION, TAUMAX=120.\n0.5\n",
                        kAll, 0, Vector6::Zero());
  capped.expect_fd_tangent(vec(0.05), vec(0, 400), kStick, true);
  const FrictionDriver::Result r = capped.evaluate(vec(0.05), vec(0, 400));
  EXPECT_NEAR(r.out.force[0], 120.0, 1e-9);
  EXPECT_EQ(r.out.force_tangent(0, 1), 0.0);
}

// Coupled friction through a potential (§2.1 form 3): an elliptic SUM potential (closest-point
// return) with the contact force from a derived component of the multiplier and an elastic
// component, and a MAX potential (multi-surface return) on one face.
TEST(FrictionTangent, CoupledPotentialsWithADerivedContactForce) {
  const std::string sum_body =
      "*CONNECTOR FRICTION, CONTACT FORCE=press, STICK STIFFNESS=1.0e4\n*CONNECTOR POTENTIAL\n"
      "2, 1.\n3, 2.\n*FRICTION\n0.2\n"
      "*CONNECTOR DERIVED COMPONENT, NAME=press\n1, 4\n1.0, 0.5\n";
  FrictionDriver sum(sum_body, kAll, 0, vec(0, 0, 0, 300.0));
  const Vector6 lambda = vec(-500);
  sum.expect_fd_tangent(vec(0, 0.001, 0.0005, 0.2), lambda, kStick, false);
  sum.expect_fd_tangent(vec(0, 0.03, -0.02, 0.2), lambda, kStick, true);
  sum.commit(vec(0, 0.03, -0.02, 0.2), lambda);
  sum.expect_fd_tangent(vec(0, -0.02, 0.01, 0.1), lambda, kStick, true);
  const std::string max_body =
      "*CONNECTOR FRICTION, CONTACT FORCE=1, STICK STIFFNESS=1.0e4\n"
      "*CONNECTOR POTENTIAL, OPERATOR=MAX\n2, 1.\n3, 2.\n*FRICTION\n0.2\n";
  FrictionDriver max(max_body, kAll, 0, Vector6::Zero());
  max.expect_fd_tangent(vec(0, 0.04, 0.001), lambda, kStick, true);
}

// μ tabulated (§3.2) against the contact force, μ(F_N) = 0.4 − 0.1·(F_N − 100)/400 on
// [100, 500], and against the slip rate, μ(γ̇) = 0.3 − 0.1·γ̇ on [0, 1] (Δt = 0.1): the slipping
// force equals μ·F_N at the root, and the tangent carries ∂μ/∂F_N (through λ2) and ∂μ/∂γ̇.
TEST(FrictionTangent, TabulatedCoefficients) {
  FrictionDriver by_force("*CONNECTOR FRICTION, COMPONENT=1, CONTACT FORCE=2, "
                          "STICK STIFFNESS=1.0e4\n*FRICTION\n0.4, , 100.\n0.3, , 500.\n",
                          kAll, 0, Vector6::Zero());
  by_force.expect_fd_tangent(vec(0.05), vec(0, -300), kStick, true);
  const FrictionDriver::Result r = by_force.evaluate(vec(0.05), vec(0, -300));
  EXPECT_NEAR(r.out.force[0], 0.35 * 300.0, 1e-9);
  // ∂(μ F_N)/∂λ2 = −(μ + F_N ∂μ/∂F_N) = −(0.35 − 300/4000)
  EXPECT_NEAR(r.out.force_tangent(0, 1), -(0.35 - 300.0 / 4000.0), 1e-12);
  FrictionDriver by_rate("*CONNECTOR FRICTION, COMPONENT=1, CONTACT FORCE=2, "
                         "STICK STIFFNESS=1.0e4\n*FRICTION\n0.3, 0.\n0.2, 1.\n",
                         kAll, 0, Vector6::Zero(), 0.1);
  by_rate.expect_fd_tangent(vec(0.05), vec(0, 1000), kStick, true);
  const FrictionDriver::Result q = by_rate.evaluate(vec(0.05), vec(0, 1000));
  // Slip: 1e4(0.05 − Δγ) = 1000(0.3 − 0.1·Δγ/0.1) ⇒ Δγ = 200/9000.
  const double dg = 200.0 / 9000.0;
  EXPECT_NEAR(q.out.force[0], 1e4 * (0.05 - dg), 1e-9);
  EXPECT_NEAR(by_rate.history("CASU", 1, q), dg, 1e-15);
}

}  // namespace
}  // namespace clinch
