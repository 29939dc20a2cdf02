#include "src/behavior/damping/damping_behavior.hpp"

#include <optional>
#include <utility>
#include <vector>

#include "src/behavior/piecewise_linear_table.hpp"

namespace clinch {
namespace {

class DampingBehavior final : public Behavior {
 public:
  DampingBehavior(ComponentMask components, const Matrix6& linear,
                  std::vector<std::pair<int, PiecewiseLinearTable>> tables)
      : components_(components), linear_(linear), tables_(std::move(tables)) {}

  ComponentMask components() const override { return components_; }
  std::span<const HistoryVariable> history_layout() const override { return {}; }
  bool tangent_is_symmetric() const override { return true; }
  ForceKind force_kind() const override { return ForceKind::Viscous; }

  IntegrationStatus integrate(const BehaviorInput& in, BehaviorOutput& out) const override {
    // §8: row 0 (no increment yet) has no velocity.
    if (!(in.dt > 0)) return IntegrationStatus::Success;
    const Vector6 velocity = in.increment / in.dt;
    out.force = linear_ * velocity;
    const bool want_tangent = in.tangent == TangentRequest::Consistent;
    if (want_tangent) out.tangent = linear_ / in.dt;
    for (const auto& [slot, table] : tables_) {
      const TableSample s = table.evaluate(velocity[slot]);
      out.force[slot] += s.value;
      if (want_tangent) out.tangent(slot, slot) += s.slope / in.dt;
    }
    return IntegrationStatus::Success;
  }

 private:
  ComponentMask components_;
  Matrix6 linear_;  // C: uncoupled and coupled linear definitions added
  std::vector<std::pair<int, PiecewiseLinearTable>> tables_;  // (component − 1, force(v))
};

}  // namespace

std::unique_ptr<Behavior> make_damping_behavior(const ConnectorBehavior& behavior,
                                                ComponentMask available) {
  ComponentMask components = 0;
  Matrix6 linear = Matrix6::Zero();
  std::vector<std::pair<int, PiecewiseLinearTable>> tables;
  for (const ConnectorDamping& d : behavior.dampings) {
    if (d.structural) continue;
    switch (d.kind) {
      case ConnectorDamping::Kind::Linear:
        if (!has_component(available, d.component)) break;
        linear(d.component - 1, d.component - 1) += d.coefficient;
        components |= component_bit(d.component);
        break;
      case ConnectorDamping::Kind::Nonlinear:
        if (!has_component(available, d.component)) break;
        tables.emplace_back(d.component - 1,
                            PiecewiseLinearTable::from_points(d.table, d.extrapolation));
        components |= component_bit(d.component);
        break;
      case ConnectorDamping::Kind::Coupled: {
        // §4.3 ordering; only the available components take part.
        const Stiffness6 c = expand_coupled_terms(d.coupled_terms);
        for (int i = 0; i < 6; ++i) {
          for (int j = 0; j < 6; ++j) {
            if (has_component(available, i + 1) && has_component(available, j + 1)) {
              linear(i, j) += c[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
            }
          }
        }
        components |= available;
        break;
      }
      case ConnectorDamping::Kind::Rayleigh:  // refused by the reader (unsupported-option)
        break;
    }
  }
  if (components == 0) return nullptr;
  return std::make_unique<DampingBehavior>(components, linear, std::move(tables));
}

}  // namespace clinch
