#include "src/behavior/elastic/elastic_behavior.hpp"

#include <array>
#include <stdexcept>
#include <utility>
#include <vector>

#include "src/behavior/piecewise_linear_table.hpp"

namespace clinch {
namespace {

using Kind = ConnectorElasticity::Kind;

// Linear (§4.1) and nonlinear (§4.2) uncoupled components. Linear ones are kept as compact
// (slot, k) arrays: this loop runs for every connector in every iteration.
class UncoupledElasticBehavior final : public Behavior {
 public:
  void add_linear(int component, double stiffness) {
    linear_slot_[static_cast<std::size_t>(linear_count_)] = component - 1;
    linear_stiffness_[static_cast<std::size_t>(linear_count_)] = stiffness;
    ++linear_count_;
    mask_ |= component_bit(component);
  }
  void add_nonlinear(int component, PiecewiseLinearTable table) {
    nonlinear_.push_back({component - 1, std::move(table)});
    mask_ |= component_bit(component);
  }
  bool empty() const { return mask_ == 0; }

  ComponentMask components() const override { return mask_; }
  // §4.6: path-independent, no history.
  std::span<const HistoryVariable> history_layout() const override { return {}; }
  bool tangent_is_symmetric() const override { return true; }

  IntegrationStatus integrate(const BehaviorInput& in, BehaviorOutput& out) const override {
    const bool tangent = in.tangent != TangentRequest::None;
    out.force.setZero();
    if (tangent) out.tangent.setZero();
    for (int n = 0; n < linear_count_; ++n) {
      const int i = linear_slot_[static_cast<std::size_t>(n)];
      const double k = linear_stiffness_[static_cast<std::size_t>(n)];
      out.force[i] = k * (in.motion_old[i] + in.increment[i]);
      if (tangent) out.tangent(i, i) = k;
    }
    for (const NonlinearComponent& c : nonlinear_) {
      const TableSample s = c.table.evaluate(in.motion_old[c.slot] + in.increment[c.slot]);
      out.force[c.slot] = s.value;
      if (tangent) out.tangent(c.slot, c.slot) = s.slope;
    }
    return IntegrationStatus::Success;
  }

 private:
  struct NonlinearComponent {
    int slot;  // component − 1
    PiecewiseLinearTable table;
  };
  ComponentMask mask_ = 0;
  int linear_count_ = 0;
  std::array<int, 6> linear_slot_{};
  std::array<double, 6> linear_stiffness_{};
  std::vector<NonlinearComponent> nonlinear_;
};

// Coupled linear elasticity (§4.3): f = D u over the available components (D restricted by
// linear_stiffness).
class CoupledElasticBehavior final : public Behavior {
 public:
  CoupledElasticBehavior(const Matrix6& d, ComponentMask available)
      : d_(d), mask_(available) {}

  ComponentMask components() const override { return mask_; }
  std::span<const HistoryVariable> history_layout() const override { return {}; }
  bool tangent_is_symmetric() const override { return true; }

  IntegrationStatus integrate(const BehaviorInput& in, BehaviorOutput& out) const override {
    out.force.noalias() = d_ * (in.motion_old + in.increment);
    if (in.tangent != TangentRequest::None) out.tangent = d_;
    return IntegrationStatus::Success;
  }

 private:
  Matrix6 d_ = Matrix6::Zero();
  ComponentMask mask_;
};

}  // namespace

std::unique_ptr<Behavior> make_elastic_behavior(const ConnectorBehavior& behavior,
                                                ComponentMask available) {
  const ConnectorElasticity* coupled = nullptr;
  auto uncoupled = std::make_unique<UncoupledElasticBehavior>();
  for (const ConnectorElasticity& e : behavior.elasticities) {
    switch (e.kind) {
      case Kind::Coupled:
        coupled = &e;
        break;
      case Kind::Linear:
        if (has_component(available, e.component)) uncoupled->add_linear(e.component, e.stiffness);
        break;
      case Kind::Nonlinear:
        if (has_component(available, e.component)) {
          uncoupled->add_nonlinear(e.component,
                                   PiecewiseLinearTable::from_points(e.table, e.extrapolation));
        }
        break;
      case Kind::Rigid:
        break;  // a constraint, see rigid_components
    }
  }
  if (coupled != nullptr) {
    // §4.3: a coupled elasticity excludes any uncoupled one; validation rejects the mix.
    if (!uncoupled->empty()) {
      throw std::invalid_argument("coupled and uncoupled connector elasticity in one behaviour");
    }
    if (available == 0) return nullptr;
    return std::make_unique<CoupledElasticBehavior>(linear_stiffness(behavior, available).k,
                                                    available);
  }
  if (uncoupled->empty()) return nullptr;
  return uncoupled;
}

LinearStiffness linear_stiffness(const ConnectorBehavior& behavior, ComponentMask available) {
  LinearStiffness out;
  for (const ConnectorElasticity& e : behavior.elasticities) {
    if (e.kind == Kind::Linear && has_component(available, e.component)) {
      out.k(e.component - 1, e.component - 1) = e.stiffness;
      out.components |= component_bit(e.component);
    } else if (e.kind == Kind::Coupled) {
      // Rows and columns of unavailable components are dropped: the restriction of §4.3.
      out.coupled = true;
      out.components |= available;
      for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 6; ++j) {
          const bool kept = has_component(available, i + 1) && has_component(available, j + 1);
          const double d = e.coupled[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
          out.k(i, j) = kept ? d : 0.0;
          if (kept && i != j && d != 0.0) out.diagonal = false;
        }
      }
    }
  }
  return out;
}

ComponentMask rigid_components(const ConnectorBehavior& behavior, ComponentMask available) {
  ComponentMask rigid = 0;
  for (const ConnectorElasticity& e : behavior.elasticities) {
    if (e.kind != Kind::Rigid) continue;
    rigid |= e.rigid_all ? available : e.rigid_components;
  }
  return static_cast<ComponentMask>(rigid & available);
}

}  // namespace clinch
