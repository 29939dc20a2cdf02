// Finite-difference checks of the damage tangent (behaviors.md §7.4, §7.6) through the shared
// checker of §1.4, on the whole law stack of a behaviour (elastic-plastic law, then damage), so
// that the degraded force (1 − d) f^eff and its unsymmetric tangent (1 − d) D^eff − f^eff ⊗ ∂d/∂u
// are checked together. States: before initiation, the increment that crosses initiation (r_n < 1
// < r on both sides of the stencil), softening on the envelope, unloading and reloading below it,
// fully damaged and deleted; uncoupled and coupled criteria, every evolution law, PLASTIC MOTION,
// several mechanisms with MAXIMUM and MULTIPLICATIVE degradation and AFFECTED COMPONENTS.
//
// Tolerance: the rule of §1.4, max|D − D_fd| ≤ 1e-5·max|D| + 1e-8·k_s with k_s = 1000. The
// damage update is a smooth function of u away from the kinks §7.6 lists (initiation point,
// κ at its history maximum, d reaching 1, table breakpoints, the 0.99 switch of ENERGY), so
// central differences with h = 1e-6·max(|u|, u_s) are accurate to O(h²) ≈ 1e-12 relative; the
// rule leaves a margin of 10⁷ over that and still catches any missing term (the smallest term
// checked, f^eff ∂d/∂u through the interpolated initiation point, is of order 10² here).
// Closed-form tangents printed by the spec (−450, −505.448546, −608.440320, −800) are checked to
// half a unit of their last printed digit.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "parser/deck_reader.hpp"
#include "src/behavior/connector_laws.hpp"
#include "tests/tangent/behavior_tangent_check.hpp"
#include "tests/unit/checked_deck.hpp"

namespace clinch {
namespace {

constexpr ComponentMask kAxial = 0x01;
constexpr ComponentMask kCartesian = 0x07;
constexpr double kStiffness = 1000;  // k_s of every deck here

Vector6 vec(double a, double b = 0, double c = 0) {
  Vector6 v = Vector6::Zero();
  v[0] = a;
  v[1] = b;
  v[2] = c;
  return v;
}

struct StackResult {
  Vector6 force = Vector6::Zero();
  Matrix6 tangent = Matrix6::Zero();
  Matrix6 force_tangent = Matrix6::Zero();  // against the constraint forces λ
  std::vector<std::vector<double>> history;
  bool ok = true;
  double dt_ratio = std::numeric_limits<double>::infinity();
};

// The law stack of behaviour block `body`, evaluated as the connector element does (each law
// reads the force and tangent of those before it), with commit() making a trial state the
// converged one.
class StackDriver {
 public:
  StackDriver(const std::string& body, ComponentMask available,
              const DamageControls& controls = {}) {
    read_deck_text("b.inp", "*CONNECTOR BEHAVIOR, NAME=B\n" + body, deck_.sources, deck_.model,
                   deck_.sink);
    for (const Diagnostic& d : deck_.sink.diagnostics()) {
      if (d.code != DiagCode::no_step) {
        EXPECT_NE(d.severity, Severity::Error) << deck_.dump();
      }
    }
    laws_ = make_connector_laws(deck_.model.behaviors.behaviors.at(0), available, 0, controls);
    for (const auto& law : laws_) committed_.emplace_back(law->history_size(), 0.0);
  }

  StackResult evaluate(const Vector6& u, double dt = 1.0,
                       const Vector6& lambda = Vector6::Zero()) const {
    StackResult r;
    bool first = true;
    for (std::size_t l = 0; l < laws_.size(); ++l) {
      r.history.emplace_back(laws_[l]->history_size(), std::nan(""));
      BehaviorOutput out;
      out.history_new = r.history.back();
      const Vector6 increment = u - motion_;
      const BehaviorInput in{
          motion_,
          increment,
          1.0,
          dt,
          committed_[l],
          TangentRequest::Consistent,
          first ? nullptr : &r.force,
          first ? nullptr : &r.tangent,
          first ? nullptr : &r.force_tangent,
          &lambda,
          first ? std::span<const double>() : r.history[l - 1],
          first ? std::span<const HistoryVariable>() : laws_[l - 1]->history_layout()};
      r.ok = r.ok && laws_[l]->integrate(in, out) != IntegrationStatus::Failure;
      r.force += out.force;
      r.tangent += out.tangent;
      if (laws_[l]->needs_connector_forces()) r.force_tangent += out.force_tangent;
      r.dt_ratio = std::min(r.dt_ratio, out.suggested_dt_ratio);
      first = false;
    }
    return r;
  }
  StackResult commit(const Vector6& u, double dt = 1.0) {
    StackResult r = evaluate(u, dt);
    EXPECT_TRUE(r.ok);
    for (const auto& h : r.history) {
      for (double v : h) EXPECT_FALSE(std::isnan(v));
    }
    committed_ = r.history;
    motion_ = u;
    return r;
  }
  // A named output of the committed history (CDMG, CDIF, …), 0 when no law holds it.
  double output(const char* name, int component) const {
    for (std::size_t l = 0; l < laws_.size(); ++l) {
      const int slot = history_slot(laws_[l]->history_layout(), name, component);
      if (slot >= 0) return committed_[l][static_cast<std::size_t>(slot)];
    }
    return 0.0;
  }
  // §1.4 against the constraint forces at (u, λ): the FORCE criterion reads the total force
  // f^eff + λ, so the initiation point moves with λ. f_s: the force scale of the step h.
  void expect_fd_constraint_tangent(const Vector6& u, const Vector6& lambda, double f_s,
                                    ComponentMask mask) const {
    const StackResult at = evaluate(u, 1.0, lambda);
    ASSERT_TRUE(at.ok);
    const auto force = [this, &u](const Eigen::VectorXd& x, Eigen::VectorXd& f) {
      const StackResult e = evaluate(u, 1.0, Vector6(x));
      f = e.force;
      return e.ok;
    };
    expect_fd_tangent_rule(force, lambda, at.force_tangent, f_s, 1.0, mask);
  }
  // §1.4 at u from the committed state, on the columns of `mask`.
  void expect_fd_tangent(const Vector6& u, double u_s, ComponentMask mask, double dt = 1.0) const {
    const StackResult at = evaluate(u, dt);
    ASSERT_TRUE(at.ok);
    const auto force = [this, dt](const Eigen::VectorXd& x, Eigen::VectorXd& f) {
      const StackResult e = evaluate(Vector6(x), dt);
      f = e.force;
      return e.ok;
    };
    expect_fd_tangent_rule(force, u, at.tangent, u_s, kStiffness, mask);
  }

 private:
  CheckedDeck deck_;
  std::vector<std::unique_ptr<Behavior>> laws_;
  std::vector<std::vector<double>> committed_;
  Vector6 motion_ = Vector6::Zero();
};

const std::string kAxialElastic = "*CONNECTOR ELASTICITY, COMPONENT=1\n1000.\n";
const std::string kForceInitiation =
    "*CONNECTOR DAMAGE INITIATION, COMPONENT=1, CRITERION=FORCE\n, 90.\n";

// E12 (§7.5): u_0 = 0.09, envelope F = 450 (0.29 − U).
const std::string kE12 = kAxialElastic + kForceInitiation +
                         "*CONNECTOR DAMAGE EVOLUTION, TYPE=MOTION, SOFTENING=LINEAR\n0.2\n";

TEST(DamageTangent, E12EveryState) {
  StackDriver d(kE12, kAxial);
  const double u_s = 0.09;
  {
    SCOPED_TRACE("before initiation");
    d.expect_fd_tangent(vec(0.05), u_s, kAxial);
    EXPECT_NEAR(d.evaluate(vec(0.05)).tangent(0, 0), kStiffness, 1e-9);
  }
  d.commit(vec(0.05));
  {
    SCOPED_TRACE("the increment that crosses initiation");
    d.expect_fd_tangent(vec(0.10), u_s, kAxial);
  }
  d.commit(vec(0.10));
  {
    SCOPED_TRACE("softening on the envelope");
    d.expect_fd_tangent(vec(0.15), u_s, kAxial);
    EXPECT_NEAR(d.evaluate(vec(0.15)).tangent(0, 0), -450, 1e-9);
  }
  d.commit(vec(0.15));
  d.commit(vec(0.20));
  EXPECT_NEAR(d.output("CDMG", 0), 0.7975, 1e-12);
  {
    SCOPED_TRACE("unloading after damage: (1 − d) k");
    d.expect_fd_tangent(vec(0.10), u_s, kAxial);
    EXPECT_NEAR(d.evaluate(vec(0.10)).tangent(0, 0), (1 - 0.7975) * kStiffness, 1e-9);
  }
  d.commit(vec(0.10));
  {
    SCOPED_TRACE("reloading below the envelope");
    d.expect_fd_tangent(vec(0.15), u_s, kAxial);
    EXPECT_NEAR(d.evaluate(vec(0.15)).tangent(0, 0), (1 - 0.7975) * kStiffness, 1e-9);
  }
  d.commit(vec(0.20));
  {
    SCOPED_TRACE("reloading past the envelope");
    d.expect_fd_tangent(vec(0.25), u_s, kAxial);
    EXPECT_NEAR(d.evaluate(vec(0.25)).tangent(0, 0), -450, 1e-9);
  }
  d.commit(vec(0.25));
  d.commit(vec(0.30));
  EXPECT_EQ(d.output("CDMG", 1), 1.0);
  EXPECT_EQ(d.output("deleted", 0), 1.0);
  {
    SCOPED_TRACE("fully damaged and deleted: no force, no stiffness");
    d.expect_fd_tangent(vec(0.35), u_s, kAxial);
    const StackResult r = d.evaluate(vec(0.35));
    EXPECT_EQ(r.force[0], 0.0);
    EXPECT_EQ(r.tangent(0, 0), 0.0);
  }
}

TEST(DamageTangent, FullyDamagedBeforeDeletionHasZeroTangent) {
  // d = 1 inside the increment: the degraded force and its tangent vanish on the trial state.
  StackDriver d(kE12, kAxial);
  d.commit(vec(0.05));
  d.commit(vec(0.10));
  const StackResult r = d.evaluate(vec(0.40));
  EXPECT_EQ(r.force[0], 0.0);
  EXPECT_EQ(r.tangent(0, 0), 0.0);
  d.expect_fd_tangent(vec(0.40), 0.09, kAxial);
}

TEST(DamageTangent, E12CompressionDoesNotDriveTensionDamage) {
  // §7.1 one-direction rule: after tension initiation, compression leaves d alone.
  StackDriver d(kE12, kAxial);
  d.commit(vec(0.05));
  d.commit(vec(0.15));
  const double damage = d.output("CDMG", 0);
  const StackResult r = d.commit(vec(-0.2));
  EXPECT_EQ(d.output("CDMG", 0), damage);
  EXPECT_NEAR(r.force[0], -(1 - damage) * 200, 1e-9);
  d.expect_fd_tangent(vec(-0.25), 0.09, kAxial);
}

TEST(DamageTangent, InitiationFromTheOtherSide) {
  // One increment from compression (no lower limit: r = 0 there) into tension past the limit:
  // damage initiates where the force crosses F_U = 90 (u_0 = 0.09), not where r would if it
  // were linear across the sign change (§7.1). At U = 0.15 this is E12's d = 0.58.
  StackDriver d(kE12, kAxial);
  d.commit(vec(-0.1));
  d.expect_fd_tangent(vec(0.15), 0.09, kAxial);
  d.commit(vec(0.15));
  EXPECT_NEAR(d.output("CDMG", 0), 0.58, 1e-12);
}

TEST(DamageTangent, ForceCriterionOnTheTotalForce) {
  // §7.1: a stop's force on the component counts. From f^c = 50 (λ = 0) at U = 0.05 to
  // f^c = 100 + 20 at U = 0.1 with λ = 20, the total force crosses 90 at θ = 40/70, so
  // u_0 = 0.05 + (4/7) 0.05 rather than 0.09; through the crossing increment the degraded force
  // depends on λ (the interpolated initiation point), and that tangent is checked too.
  StackDriver d(kE12, kAxial);
  const Vector6 lambda = vec(20.0);
  EXPECT_TRUE(d.evaluate(vec(0.05)).ok);
  d.commit(vec(0.05));
  d.expect_fd_constraint_tangent(vec(0.10), lambda, 90, kAxial);
  d.expect_fd_tangent(vec(0.10), 0.09, kAxial);
  const StackResult r = d.evaluate(vec(0.10), 1.0, lambda);
  const double u0 = 0.05 + 4.0 / 7.0 * 0.05, kappa = 0.1 - u0;
  EXPECT_NEAR(r.force[0], u0 * (1 - kappa / 0.2) / 0.1 * 100.0, 1e-9);
  EXPECT_NE(r.force_tangent(0, 0), 0.0);
}

TEST(DamageTangent, E12ExponentialAndTabular) {
  StackDriver e(kAxialElastic + kForceInitiation +
                    "*CONNECTOR DAMAGE EVOLUTION, TYPE=MOTION, SOFTENING=EXPONENTIAL\n0.2, 5.\n",
                kAxial);
  e.commit(vec(0.05));
  e.expect_fd_tangent(vec(0.10), 0.09, kAxial);
  e.commit(vec(0.10));
  e.expect_fd_tangent(vec(0.15), 0.09, kAxial);
  // §7.5: the envelope tangent k u_0 g' at U = 0.15.
  EXPECT_NEAR(e.evaluate(vec(0.15)).tangent(0, 0), -505.448546, 5e-7);

  // TABULAR d(δ) through (0, 0), (0.5, 0.05), (1, 0.2): states inside the segments.
  StackDriver t(kAxialElastic + kForceInitiation +
                    "*CONNECTOR DAMAGE EVOLUTION, TYPE=MOTION, SOFTENING=TABULAR\n"
                    "0., 0.\n0.5, 0.05\n1., 0.2\n",
                kAxial);
  t.commit(vec(0.05));
  t.expect_fd_tangent(vec(0.12), 0.09, kAxial);
  t.commit(vec(0.12));
  t.expect_fd_tangent(vec(0.17), 0.09, kAxial);
}

TEST(DamageTangent, E13Energy) {
  StackDriver d(
      kAxialElastic + kForceInitiation + "*CONNECTOR DAMAGE EVOLUTION, TYPE=ENERGY\n10.\n", kAxial);
  d.commit(vec(0.05));
  d.expect_fd_tangent(vec(0.10), 0.09, kAxial);
  d.commit(vec(0.10));
  d.expect_fd_tangent(vec(0.15), 0.09, kAxial);
  EXPECT_NEAR(d.evaluate(vec(0.15)).tangent(0, 0), -608.440320, 5e-7);
  d.commit(vec(0.15));
  EXPECT_NEAR(d.evaluate(vec(0.20)).tangent(0, 0), -608.725586, 5e-7);
  // Unload, then reload past the envelope inside one increment: W starts where δ regains κ_n.
  d.commit(vec(0.12));
  d.expect_fd_tangent(vec(0.18), 0.09, kAxial);
}

const std::string kE14 = kAxialElastic +
                         "*CONNECTOR PLASTICITY, COMPONENT=1\n"
                         "*CONNECTOR HARDENING, TYPE=ISOTROPIC\n80., 0.\n"
                         "*CONNECTOR DAMAGE INITIATION, COMPONENT=1, CRITERION=PLASTIC MOTION\n"
                         "0.05\n";

TEST(DamageTangent, E14PlasticMotion) {
  StackDriver d(kE14 + "*CONNECTOR DAMAGE EVOLUTION, TYPE=MOTION\n0.1\n", kAxial);
  d.commit(vec(0.05));
  d.commit(vec(0.10));
  EXPECT_NEAR(d.output("CDIP", 0), 0.4, 1e-12);
  d.expect_fd_tangent(vec(0.15), 0.08, kAxial);
  EXPECT_NEAR(d.evaluate(vec(0.15)).tangent(0, 0), -800, 1e-9);
  d.commit(vec(0.15));
  d.commit(vec(0.20));
  // Unloading: f^eff = 30, CTF1 = 9, tangent (1 − d) k.
  const StackResult r = d.evaluate(vec(0.15));
  EXPECT_NEAR(r.force[0], 9, 1e-9);
  EXPECT_NEAR(r.tangent(0, 0), 300, 1e-9);
  d.expect_fd_tangent(vec(0.15), 0.08, kAxial);

  // ENERGY with PLASTIC MOTION initiation: W = ∫ F_y dū.
  StackDriver e(kE14 + "*CONNECTOR DAMAGE EVOLUTION, TYPE=ENERGY\n5.\n", kAxial);
  e.commit(vec(0.10));
  e.expect_fd_tangent(vec(0.15), 0.08, kAxial);  // crosses ū_0 = 0.05 inside the increment
  e.commit(vec(0.15));
  e.expect_fd_tangent(vec(0.19), 0.08, kAxial);
}

// E15 (§7.5): coupled FORCE initiation P = |(f1/100, f2/50)| = 1, evolution potential
// |(u1, u2)|, path U = t (0.1, 0.05).
const std::string kCartesianElastic =
    "*CONNECTOR ELASTICITY, COMPONENT=1\n1000.\n"
    "*CONNECTOR ELASTICITY, COMPONENT=2\n1000.\n"
    "*CONNECTOR ELASTICITY, COMPONENT=3\n1000.\n";
const std::string kE15Initiation =
    "*CONNECTOR DAMAGE INITIATION, CRITERION=FORCE\n, 1.\n"
    "*CONNECTOR POTENTIAL\n1, 100.\n2, 50.\n";

// Coupled PLASTIC MOTION (§7.1): a circular coupled plasticity P = |(f1, f2)|/R, F_y = 80,
// damage at ū^pl_0 = 0.02 with linear softening over 0.1. ū is the coupled return's Δλ.
const std::string kCoupledPlastic =
    kCartesianElastic +
    "*CONNECTOR PLASTICITY\n*CONNECTOR HARDENING, TYPE=ISOTROPIC\n80., 0.\n"
    "*CONNECTOR POTENTIAL\n1, 1.\n2, 1.\n"
    "*CONNECTOR DAMAGE INITIATION, CRITERION=PLASTIC MOTION\n0.02\n";

TEST(DamageTangent, CoupledPlasticMotion) {
  StackDriver d(kCoupledPlastic + "*CONNECTOR DAMAGE EVOLUTION, TYPE=MOTION\n0.1\n", kCartesian);
  // Radial path along (0.8, 0.6): yield at |u| = 0.08; ū = |u| − 0.08 on it.
  d.commit(vec(0.08, 0.06));  // |u| = 0.1: ū = 0.02 − just initiated
  EXPECT_NEAR(d.output("CDIP", 0), 1.0, 1e-9);
  EXPECT_NEAR(d.output("CDIPC", 0), 1.0, 1e-9);
  d.expect_fd_tangent(vec(0.12, 0.09, 0.01), 0.08, kCartesian);  // |u| = 0.15, off the radial line
  d.commit(vec(0.12, 0.09));                                     // ū = 0.07, δ = 0.05: d = 0.5
  EXPECT_NEAR(d.output("CDMG", 1), 0.5, 1e-9);
  EXPECT_NEAR(d.output("CDMG", 2), 0.5, 1e-9);
  const StackResult r = d.evaluate(vec(0.12, 0.09));
  EXPECT_NEAR(r.force.head<2>().norm(), 0.5 * 80, 1e-9);
  d.expect_fd_tangent(vec(0.14, 0.1, 0.0), 0.08, kCartesian);
  // ENERGY: W = ∫ P(f^eff) dū. One increment from |u| = 0.05 (elastic, P = 50) to 0.15
  // (ū = 0.07, P = 80) crosses ū_0 = 0.02 at θ = 2/7; §7.2 starts the trapezoid there with the
  // integrand interpolated between the increment's ends: W = (50 + 30·2/7 + 80)/2 · 0.05.
  StackDriver e(kCoupledPlastic + "*CONNECTOR DAMAGE EVOLUTION, TYPE=ENERGY\n4.\n", kCartesian);
  e.commit(vec(0.04, 0.03));
  e.expect_fd_tangent(vec(0.12, 0.09), 0.08, kCartesian);  // crosses ū_0 inside the increment
  e.commit(vec(0.12, 0.09));
  const double work = 0.5 * (50 + 30 * 2.0 / 7 + 80) * 0.05;
  EXPECT_NEAR(e.output("CDMG", 1), 1 - std::exp(-work / 4), 1e-9);
  // Then along the surface: W grows by F_y Δū exactly.
  e.commit(vec(0.16, 0.12));  // ū = 0.12
  EXPECT_NEAR(e.output("CDMG", 1), 1 - std::exp(-(work + 80 * 0.05) / 4), 1e-9);
}

TEST(DamageTangent, E15CoupledUnsymmetric) {
  StackDriver d(kCartesianElastic + kE15Initiation +
                    "*CONNECTOR DAMAGE EVOLUTION, TYPE=MOTION\n0.1\n"
                    "*CONNECTOR POTENTIAL\n1, 1.\n2, 1.\n",
                kCartesian);
  d.commit(vec(0.05, 0.025));
  {
    SCOPED_TRACE("t = 1, the increment that crosses initiation at t_0 = 1/√2");
    d.expect_fd_tangent(vec(0.1, 0.05), 0.05, kCartesian);
    const StackResult r = d.evaluate(vec(0.1, 0.05));
    EXPECT_GT(std::abs(r.tangent(0, 1) - r.tangent(1, 0)), 1.0);  // unsymmetric
  }
  d.commit(vec(0.1, 0.05));
  EXPECT_NEAR(d.output("CDMG", 0), 0.524445639, 5e-10);
  {
    SCOPED_TRACE("t = 1.5 on the envelope, off the path direction");
    d.expect_fd_tangent(vec(0.15, 0.07, 0.01), 0.05, kCartesian);
  }
  {
    // §7.5 E15 at t = 1.5 (four increments of 0.5 as in the spec).
    const StackResult r = d.commit(vec(0.15, 0.075));
    EXPECT_NEAR(d.output("CDMG", 0), 0.946486898, 5e-10);
    EXPECT_NEAR(r.force[0], 8.026965, 5e-7);
    EXPECT_NEAR(r.force[1], 4.013483, 5e-7);
    EXPECT_NEAR(d.output("CDIF", 0), 2.121320, 5e-7);
  }
  {
    SCOPED_TRACE("unloading: (1 − d) K on components 1–2, K on the unaffected component 3");
    const StackResult r = d.evaluate(vec(0.1, 0.05, 0.02));
    const double damage = d.output("CDMG", 1);
    EXPECT_NEAR(r.tangent(0, 0), (1 - damage) * kStiffness, 1e-9);
    EXPECT_NEAR(r.tangent(2, 2), kStiffness, 1e-12);
    d.expect_fd_tangent(vec(0.1, 0.05, 0.02), 0.05, kCartesian);
  }
  // t = 2: fully damaged on 1–2, deleted.
  d.commit(vec(0.2, 0.1));
  EXPECT_EQ(d.output("CDMG", 0), 1.0);
  EXPECT_EQ(d.output("deleted", 0), 1.0);
}

TEST(DamageTangent, CoupledMotionDefaultNormAndEnergy) {
  // Coupled MOTION initiation, no evolution potential: δ is the norm of the affected motions.
  const std::string body = kCartesianElastic +
                           "*CONNECTOR DAMAGE INITIATION, CRITERION=MOTION\n, 0.05\n"
                           "*CONNECTOR POTENTIAL\n1, 1.\n2, 2.\n";
  StackDriver m(body + "*CONNECTOR DAMAGE EVOLUTION, TYPE=MOTION, SOFTENING=EXPONENTIAL\n0.1, 3.\n",
                kCartesian);
  m.commit(vec(0.02, 0.03));
  m.expect_fd_tangent(vec(0.06, 0.05), 0.05, kCartesian);
  m.commit(vec(0.06, 0.05));
  m.expect_fd_tangent(vec(0.08, 0.06, 0.01), 0.05, kCartesian);

  StackDriver e(body + "*CONNECTOR DAMAGE EVOLUTION, TYPE=ENERGY\n2.\n", kCartesian);
  e.commit(vec(0.02, 0.03));
  e.expect_fd_tangent(vec(0.06, 0.05), 0.05, kCartesian);
  e.commit(vec(0.06, 0.05));
  e.expect_fd_tangent(vec(0.08, 0.06, 0.01), 0.05, kCartesian);
}

TEST(DamageTangent, SeveralMechanismsMaximumMultiplicativeAffected) {
  // A FORCE mechanism on 1 that also degrades 2 (MAXIMUM), a MOTION mechanism on 2
  // (MULTIPLICATIVE): component 2 combines both (§7.3), through unsymmetric cross terms.
  StackDriver d(kCartesianElastic + kForceInitiation +
                    "*CONNECTOR DAMAGE EVOLUTION, TYPE=MOTION, AFFECTED COMPONENTS\n1, 2\n0.2\n"
                    "*CONNECTOR DAMAGE INITIATION, COMPONENT=2, CRITERION=MOTION\n-0.04, 0.04\n"
                    "*CONNECTOR DAMAGE EVOLUTION, TYPE=MOTION, DEGRADATION=MULTIPLICATIVE\n0.3\n",
                kCartesian);
  d.commit(vec(0.05, 0.02));
  d.expect_fd_tangent(vec(0.12, 0.06), 0.05, kCartesian);
  d.commit(vec(0.12, 0.06));
  d.expect_fd_tangent(vec(0.15, 0.09, 0.01), 0.05, kCartesian);
  const StackResult r = d.evaluate(vec(0.15, 0.09));
  EXPECT_NE(r.tangent(1, 0), 0.0);  // d_2 depends on u_1 through the FORCE mechanism
  EXPECT_EQ(r.tangent(0, 1), 0.0);  // d_1 does not depend on u_2
  // §7.3: d_2 = 1 − (1 − d_force)(1 − d_motion).
  d.commit(vec(0.15, 0.09));
  EXPECT_GT(d.output("CDMG", 2), d.output("CDMG", 1));
}

TEST(DamageControls, MaxDegradationAndElementDeletion) {
  // MAX DEGRADATION 0.8: d stops at 0.8; with deletion the element goes, without it keeps
  // (1 − 0.8) k (keywords.md §5, docs/decisions.md "Damage").
  for (const bool deletion : {true, false}) {
    StackDriver d(kE12, kAxial, DamageControls{deletion, 0.8, 0.0});
    d.commit(vec(0.05));
    d.commit(vec(0.15));
    d.commit(vec(0.25));  // inviscid d = 0.928 > 0.8
    EXPECT_EQ(d.output("CDMG", 1), 0.8);
    EXPECT_EQ(d.output("deleted", 0), deletion ? 1.0 : 0.0);
    if (!deletion) {
      const StackResult r = d.evaluate(vec(0.3));
      EXPECT_NEAR(r.force[0], 0.2 * kStiffness * 0.3, 1e-9);
      EXPECT_NEAR(r.tangent(0, 0), 0.2 * kStiffness, 1e-9);
      d.expect_fd_tangent(vec(0.3), 0.09, kAxial);
    }
  }
}

TEST(DamageControls, ViscousRegularisationTangent) {
  // d_v = (η d_v,n + Δt d)/(η + Δt): the tangent scales ∂d/∂u by Δt/(η + Δt).
  const double eta = 0.05, dt = 0.1;
  StackDriver d(kE12, kAxial, DamageControls{true, 1.0, eta});
  d.commit(vec(0.05), dt);
  d.expect_fd_tangent(vec(0.10), 0.09, kAxial, dt);
  d.commit(vec(0.10), dt);
  EXPECT_NEAR(d.output("CDMG", 1), dt / (eta + dt) * 0.145, 1e-12);
  d.expect_fd_tangent(vec(0.15), 0.09, kAxial, dt);
  // Held: the regularised damage keeps catching up with the inviscid 0.145.
  d.commit(vec(0.10), dt);
  EXPECT_NEAR(d.output("CDMG", 1), 0.145 * (1 - std::pow(eta / (eta + dt), 2)), 1e-12);
}

// §7.4 increment control: a MOTION evolution is a function of κ, so the damage at the end of an
// increment is the same whatever its size, and a jump is kept (the next increment does not grow);
// an ENERGY evolution integrates its work over the increment (trapezoidal) and VISCOSITY its ODE
// (backward Euler), so there a jump misses the softening branch and is retried smaller.
TEST(DamageIncrementControl, AJumpIsRetriedOnlyWhereTheIncrementSizeChangesTheDamage) {
  StackDriver d(kE12, kAxial);
  d.commit(vec(0.05));
  // 0 → 0.9675 in one increment: kept, and the next increment does not grow.
  EXPECT_EQ(d.evaluate(vec(0.28)).dt_ratio, 1.0);
  // 0 → 0.145: no request.
  EXPECT_TRUE(std::isinf(d.evaluate(vec(0.10)).dt_ratio));
  // The kept jump of decks/verification/cae_damage_direct_jump: EXPONENTIAL (0.2, 5) from
  // U = 0.08 (not initiated) to 0.2 in one increment, d = 0.974; its tangent, the crossing of
  // initiation included, against central differences.
  StackDriver x(kAxialElastic + kForceInitiation +
                    "*CONNECTOR DAMAGE EVOLUTION, TYPE=MOTION, SOFTENING=EXPONENTIAL\n0.2, 5.\n",
                kAxial);
  x.commit(vec(0.08));
  EXPECT_EQ(x.evaluate(vec(0.2)).dt_ratio, 1.0);
  x.expect_fd_tangent(vec(0.2), 0.09, kAxial);
  // ENERGY, G = 10: W = 0.155 (90 + 400 e^(−W/10)) ≈ 21.2 from 0.09 to 0.4, d ≈ 0.88: retried.
  StackDriver e(
      kAxialElastic + kForceInitiation + "*CONNECTOR DAMAGE EVOLUTION, TYPE=ENERGY\n10.\n", kAxial);
  e.commit(vec(0.05));
  EXPECT_LT(e.evaluate(vec(0.4)).dt_ratio, 1.0);
  // E12 with VISCOSITY η = 1e-3 (Δt = 1): d_v ≈ 0.9665 in one increment: retried.
  StackDriver v(kE12, kAxial, DamageControls{true, 1.0, 1e-3});
  v.commit(vec(0.05));
  EXPECT_LT(v.evaluate(vec(0.28)).dt_ratio, 1.0);
}

}  // namespace
}  // namespace clinch
