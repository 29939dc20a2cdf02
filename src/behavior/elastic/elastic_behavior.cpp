#include "src/behavior/elastic/elastic_behavior.hpp"

#include <array>
#include <utility>
#include <vector>

#include "src/behavior/piecewise_linear_table.hpp"
#include "src/model/elasticity_queries.hpp"

namespace clinch {
namespace {

using Kind = ConnectorElasticity::Kind;

struct NonlinearComponent {
  int slot;  // component − 1
  PiecewiseLinearTable table;
};

// Linear (§4.1, §4.3) and nonlinear (§4.2) elasticity, every definition on a component added
// (§2): f = K u + Σ table(u_i). A diagonal K is kept as compact (slot, k) arrays: this loop runs
// for every connector in every iteration.
class ElasticBehavior final : public Behavior {
 public:
  ElasticBehavior(const LinearStiffness& linear, std::vector<NonlinearComponent> nonlinear)
      : diagonal_(linear.diagonal), k_(linear.k), nonlinear_(std::move(nonlinear)) {
    mask_ = linear.components;
    for (int i = 0; i < 6; ++i) {
      if (!has_component(linear.components, i + 1)) continue;
      linear_slot_[static_cast<std::size_t>(linear_count_)] = i;
      linear_stiffness_[static_cast<std::size_t>(linear_count_)] = linear.k(i, i);
      ++linear_count_;
    }
    for (const NonlinearComponent& c : nonlinear_) mask_ |= component_bit(c.slot + 1);
  }
  bool empty() const { return mask_ == 0; }

  ComponentMask components() const override { return mask_; }
  // §4.6: path-independent, no history.
  std::span<const HistoryVariable> history_layout() const override { return {}; }
  bool tangent_is_symmetric() const override { return true; }

  IntegrationStatus integrate(const BehaviorInput& in, BehaviorOutput& out) const override {
    const bool tangent = in.tangent != TangentRequest::None;
    if (diagonal_) {
      out.force.setZero();
      if (tangent) out.tangent.setZero();
      for (int n = 0; n < linear_count_; ++n) {
        const int i = linear_slot_[static_cast<std::size_t>(n)];
        const double k = linear_stiffness_[static_cast<std::size_t>(n)];
        out.force[i] = k * (in.motion_old[i] + in.increment[i]);
        if (tangent) out.tangent(i, i) = k;
      }
    } else {
      out.force.noalias() = k_ * (in.motion_old + in.increment);
      if (tangent) out.tangent = k_;
    }
    for (const NonlinearComponent& c : nonlinear_) {
      const TableSample s = c.table.evaluate(in.motion_old[c.slot] + in.increment[c.slot]);
      out.force[c.slot] += s.value;
      if (tangent) out.tangent(c.slot, c.slot) += s.slope;
    }
    return IntegrationStatus::Success;
  }

 private:
  bool diagonal_ = true;
  Matrix6 k_ = Matrix6::Zero();  // the non-diagonal K
  ComponentMask mask_ = 0;
  int linear_count_ = 0;
  std::array<int, 6> linear_slot_{};
  std::array<double, 6> linear_stiffness_{};
  std::vector<NonlinearComponent> nonlinear_;
};

std::vector<NonlinearComponent> nonlinear_components(const ConnectorBehavior& behavior,
                                                     ComponentMask available) {
  std::vector<NonlinearComponent> out;
  for (const ConnectorElasticity& e : behavior.elasticities) {
    if (e.kind == Kind::Nonlinear && has_component(available, e.component)) {
      out.push_back({e.component - 1, PiecewiseLinearTable::from_points(e.table, e.extrapolation)});
    }
  }
  return out;
}

std::unique_ptr<Behavior> make_law(const LinearStiffness& linear,
                                   std::vector<NonlinearComponent> nonlinear) {
  auto law = std::make_unique<ElasticBehavior>(linear, std::move(nonlinear));
  if (law->empty()) return nullptr;
  return law;
}

}  // namespace

std::unique_ptr<Behavior> make_elastic_behavior(const ConnectorBehavior& behavior,
                                                ComponentMask available) {
  return make_law(linear_stiffness(behavior, available),
                  nonlinear_components(behavior, available));
}

std::unique_ptr<Behavior> make_nonlinear_elastic_behavior(const ConnectorBehavior& behavior,
                                                          ComponentMask available) {
  return make_law(LinearStiffness{}, nonlinear_components(behavior, available));
}

LinearStiffness linear_stiffness(const ConnectorBehavior& behavior, ComponentMask available) {
  // §2: every linear definition on a component adds; §4.4: a rigid-plastic component has the
  // stiff spring k_rigid.
  LinearStiffness out;
  for (const ConnectorElasticity& e : behavior.elasticities) {
    if (e.kind == Kind::Linear && has_component(available, e.component)) {
      out.k(e.component - 1, e.component - 1) += e.stiffness;
      out.components |= component_bit(e.component);
    } else if (e.kind == Kind::Coupled) {
      // Rows and columns of unavailable components are dropped: the restriction of §4.3.
      out.coupled = true;
      out.components |= available;
      for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 6; ++j) {
          const bool kept = has_component(available, i + 1) && has_component(available, j + 1);
          if (kept) out.k(i, j) += e.coupled[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
        }
      }
    }
  }
  const ComponentMask rigid_plastic = rigid_plastic_components(behavior, available);
  for (int i = 1; i <= 6; ++i) {
    if (!has_component(rigid_plastic, i)) continue;
    out.k(i - 1, i - 1) += rigid_plastic_stiffness(behavior, available, i);
    out.components |= component_bit(i);
  }
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      if (i != j && out.k(i, j) != 0.0) out.diagonal = false;
    }
  }
  return out;
}

ComponentMask rigid_components(const ConnectorBehavior& behavior, ComponentMask available) {
  // §4.4: a rigid-plastic component is a stiff spring of the elastic-plastic law instead.
  return static_cast<ComponentMask>(rigid_elasticity_components(behavior, available) &
                                    ~rigid_plastic_components(behavior, available));
}

}  // namespace clinch
