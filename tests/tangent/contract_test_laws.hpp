// Laws that exist only to exercise the behaviour contract (src/behavior/behavior.hpp) through the
// connector element and the step driver: one whose force depends on a constraint force of its
// connector (as friction's contact force does), one that asks for smaller time increments, one
// whose force overflows.
#pragma once

#include <cmath>
#include <limits>
#include <string>

#include "src/behavior/behavior.hpp"

namespace clinch {

// A linear spring k on component 1, without history: what the laws below share.
class ComponentOneSpring : public Behavior {
 public:
  explicit ComponentOneSpring(double k) : k_(k) {}
  ComponentMask components() const override { return component_bit(1); }
  std::span<const HistoryVariable> history_layout() const override { return {}; }
  bool tangent_is_symmetric() const override { return true; }

 protected:
  // f₁ = k u₁, ∂f₁/∂u₁ = k; returns u₁.
  double spring(const BehaviorInput& in, BehaviorOutput& out) const {
    const double u = in.motion_old[0] + in.increment[0];
    out.force[0] = k_ * u;
    out.tangent(0, 0) = k_;
    return u;
  }

 private:
  double k_;
};

// On component 1: f₁ = k u₁ + c λ₂ u₁³, λ₂ the constraint force of component 2 (SLOT: a
// constrained component). ∂f₁/∂u₁ = k + 3 c λ₂ u₁², ∂f₁/∂λ₂ = c u₁³: an unsymmetric element
// tangent with a block against the multiplier. Smooth, so Newton converges quadratically.
class ContactStiffenedSpring final : public ComponentOneSpring {
 public:
  ContactStiffenedSpring(double k, double c) : ComponentOneSpring(k), c_(c) {}
  bool tangent_is_symmetric() const override { return false; }
  bool needs_connector_forces() const override { return true; }
  IntegrationStatus integrate(const BehaviorInput& in, BehaviorOutput& out) const override {
    const double u = spring(in, out);
    const double lambda = (*in.connector_forces)[1];
    out.force[0] += c_ * lambda * u * u * u;
    out.tangent(0, 0) += 3 * c_ * lambda * u * u;
    out.force_tangent(0, 1) = c_ * u * u * u;
    return IntegrationStatus::Success;
  }

 private:
  double c_;
};

// A linear spring k on component 1 that accepts a motion increment of at most `limit` per
// increment: beyond it, it asks for the increment scaled to fit (suggested_dt_ratio < 1).
class IncrementLimitedSpring final : public ComponentOneSpring {
 public:
  IncrementLimitedSpring(double k, double limit) : ComponentOneSpring(k), limit_(limit) {}
  IntegrationStatus integrate(const BehaviorInput& in, BehaviorOutput& out) const override {
    spring(in, out);
    const double step = std::abs(in.increment[0]);
    if (step > limit_) {
      out.suggested_dt_ratio = 0.9 * limit_ / step;
      out.message = "motion increment " + std::to_string(step) + " above the limit";
    }
    return IntegrationStatus::Success;
  }

 private:
  double limit_;
};

// A linear spring k on component 1 that keeps the next increment from growing, by suggesting a
// ratio of 1 or, with `unreliable`, by reporting every result as Unreliable.
class GrowthHoldingSpring final : public ComponentOneSpring {
 public:
  GrowthHoldingSpring(double k, bool unreliable) : ComponentOneSpring(k), unreliable_(unreliable) {}
  IntegrationStatus integrate(const BehaviorInput& in, BehaviorOutput& out) const override {
    spring(in, out);
    if (unreliable_) {
      out.message = "unsure of this result";
      return IntegrationStatus::Unreliable;
    }
    out.suggested_dt_ratio = 1.0;
    return IntegrationStatus::Success;
  }

 private:
  bool unreliable_;
};

// A linear spring k on component 1 whose force is infinite beyond |u₁| = `limit`, as a law
// that overflows would return it (reported as a Success, which the assembly must not trust).
class OverflowingSpring final : public ComponentOneSpring {
 public:
  OverflowingSpring(double k, double limit) : ComponentOneSpring(k), limit_(limit) {}
  IntegrationStatus integrate(const BehaviorInput& in, BehaviorOutput& out) const override {
    if (std::abs(spring(in, out)) > limit_) {
      out.force[0] = std::numeric_limits<double>::infinity();
    }
    return IntegrationStatus::Success;
  }

 private:
  double limit_;
};

}  // namespace clinch
