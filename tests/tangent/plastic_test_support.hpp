// Test support for connector plasticity: a behaviour built from deck text through the whole
// reader, and a driver that integrates it increment by increment (commit = copy the trial history
// to the committed one), with the finite-difference tangent check of behaviors.md §1.4.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "parser/deck_reader.hpp"
#include "src/behavior/plastic/elastic_plastic_behavior.hpp"
#include "tests/tangent/behavior_tangent_check.hpp"
#include "tests/unit/checked_deck.hpp"

namespace clinch {

inline Vector6 vec(double a, double b = 0, double c = 0, double d = 0, double e = 0, double f = 0) {
  Vector6 v;
  v << a, b, c, d, e, f;
  return v;
}

struct PlasticLaw {
  CheckedDeck deck;
  std::unique_ptr<Behavior> law;
};

// `body` follows "*CONNECTOR BEHAVIOR, NAME=B"; the law acts on the components in `available`.
inline std::unique_ptr<PlasticLaw> make_law(const std::string& body, ComponentMask available) {
  auto p = std::make_unique<PlasticLaw>();
  read_deck_text("b.inp", "*CONNECTOR BEHAVIOR, NAME=B\n" + body, p->deck.sources, p->deck.model,
                 p->deck.sink);
  // A behaviour block alone: the only error expected is that the deck has no *STEP.
  for (const Diagnostic& d : p->deck.sink.diagnostics()) {
    if (d.code != DiagCode::no_step) {
      EXPECT_NE(d.severity, Severity::Error) << p->deck.dump();
    }
  }
  p->law = make_connector_behavior(p->deck.model.behaviors.behaviors.at(0), available);
  return p;
}

struct Evaluation {
  IntegrationStatus status = IntegrationStatus::Failure;
  BehaviorOutput out;
  std::vector<double> history;
};

// A plastic law's history read through its named layout (behavior.hpp): what the output of
// CUP, CUPEQ, CUPEQC and CALPHAF shows.
struct BehaviorState {
  Vector6 plastic_motion = Vector6::Zero();      // CUP
  Vector6 equivalent_plastic = Vector6::Zero();  // CUPEQ of each uncoupled plasticity
  ComponentMask uncoupled_plastic = 0;           // components whose CUPEQ slot is named
  double coupled_equivalent_plastic = 0;         // CUPEQC
  bool has_coupled_plasticity = false;
  Vector6 back_force = Vector6::Zero();          // CALPHAF
};

inline BehaviorState read_state(const Behavior& law, std::span<const double> history) {
  BehaviorState s;
  const std::span<const HistoryVariable> layout = law.history_layout();
  for (int i = 1; i <= 6; ++i) {
    if (const int k = history_slot(layout, "CUP", i); k >= 0) s.plastic_motion[i - 1] = history[k];
    if (const int k = history_slot(layout, "CUPEQ", i); k >= 0) {
      s.equivalent_plastic[i - 1] = history[k];
      s.uncoupled_plastic |= component_bit(i);
    }
    if (const int k = history_slot(layout, "CALPHAF", i); k >= 0) s.back_force[i - 1] = history[k];
  }
  if (const int k = history_slot(layout, "CUPEQC", 0); k >= 0) {
    s.has_coupled_plasticity = true;
    s.coupled_equivalent_plastic = history[k];
  }
  return s;
}

// Integrates one element's law; `commit` makes the last trial state the converged one.
class Driver {
 public:
  explicit Driver(const Behavior& law)
      : law_(law), committed_(static_cast<std::size_t>(law.history_size()), 0.0) {}

  Evaluation evaluate(const Vector6& u, TangentRequest t = TangentRequest::Consistent) const {
    Evaluation e;
    // The caller does not pre-fill history_new: NaN catches a slot the law forgets to write.
    e.history.assign(committed_.size(), std::nan(""));
    e.out.history_new = e.history;
    const Vector6 increment = u - motion_;
    const BehaviorInput in{motion_, increment, 0.0, 0.0, committed_, t};
    e.status = law_.integrate(in, e.out);
    return e;
  }
  // Integrates to `u` and commits; returns the converged evaluation.
  Evaluation step(const Vector6& u) {
    Evaluation e = evaluate(u);
    EXPECT_EQ(e.status, IntegrationStatus::Success) << e.out.message;
    for (double h : e.history) EXPECT_FALSE(std::isnan(h));
    committed_ = e.history;
    motion_ = u;
    return e;
  }
  BehaviorState state() const { return read_state(law_, committed_); }
  const Vector6& motion() const { return motion_; }

  // §1.4 at `u`, every evaluation from the committed history; only the columns of `mask` are
  // compared.
  void expect_fd_tangent(const Vector6& u, double u_s, double k_s, ComponentMask mask) const {
    const Evaluation at = evaluate(u);
    ASSERT_EQ(at.status, IntegrationStatus::Success) << at.out.message;
    const auto force = [this](const Eigen::VectorXd& x, Eigen::VectorXd& f) {
      const Evaluation e = evaluate(Vector6(x));
      f = e.out.force;
      return e.status == IntegrationStatus::Success;
    };
    expect_fd_tangent_rule(force, u, at.out.tangent, u_s, k_s, mask);
  }

 private:
  const Behavior& law_;
  std::vector<double> committed_;
  Vector6 motion_ = Vector6::Zero();
};

}  // namespace clinch
