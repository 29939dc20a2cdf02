#include "src/model/elasticity_queries.hpp"

#include <algorithm>
#include <array>

namespace clinch {

ComponentMask potential_components(const ConnectorBehavior& behavior, PotentialOwner::Kind kind,
                                   std::size_t index) {
  for (const PotentialOwner& o : behavior.potential_owners) {
    if (o.kind != kind || o.index != static_cast<std::int32_t>(index)) continue;
    if (o.potential < 0 || static_cast<std::size_t>(o.potential) >= behavior.potentials.size()) {
      return 0;
    }
    ComponentMask mask = 0;
    for (const PotentialContribution& c :
         behavior.potentials[static_cast<std::size_t>(o.potential)].contributions) {
      if (!c.derived) {
        if (c.component >= 1 && c.component <= 6) mask |= component_bit(c.component);
        continue;
      }
      for (const DerivedComponentTerm& t : behavior.derived_terms) {
        if (t.name.key != c.derived_name.key) continue;
        for (int k : t.components) {
          if (k >= 1 && k <= 6) mask |= component_bit(k);
        }
      }
    }
    return mask;
  }
  return 0;
}

ComponentMask plastic_components(const ConnectorBehavior& behavior, ComponentMask available) {
  ComponentMask mask = 0;
  for (std::size_t k = 0; k < behavior.plasticities.size(); ++k) {
    const ConnectorPlasticity& p = behavior.plasticities[k];
    if (!p.coupled()) {
      if (p.component >= 1 && p.component <= 6) mask |= component_bit(p.component);
    } else {
      mask |= potential_components(behavior, PotentialOwner::Kind::Plasticity, k);
    }
  }
  return static_cast<ComponentMask>(mask & available);
}

ComponentMask rigid_elasticity_components(const ConnectorBehavior& behavior,
                                          ComponentMask available) {
  ComponentMask rigid = 0;
  for (const ConnectorElasticity& e : behavior.elasticities) {
    if (e.kind != ConnectorElasticity::Kind::Rigid) continue;
    rigid |= e.rigid_all ? available : e.rigid_components;
  }
  return static_cast<ComponentMask>(rigid & available);
}

ComponentMask rigid_plastic_components(const ConnectorBehavior& behavior,
                                       ComponentMask available) {
  return static_cast<ComponentMask>(rigid_elasticity_components(behavior, available) &
                                    plastic_components(behavior, available));
}

double rigid_plastic_stiffness(const ConnectorBehavior& behavior, ComponentMask available,
                               int component) {
  std::array<double, 6> diagonal{};
  for (const ConnectorElasticity& e : behavior.elasticities) {
    if (e.kind == ConnectorElasticity::Kind::Linear && has_component(available, e.component)) {
      diagonal[static_cast<std::size_t>(e.component - 1)] += e.stiffness;
    } else if (e.kind == ConnectorElasticity::Kind::Coupled) {
      for (std::size_t i = 0; i < 6; ++i) diagonal[i] += e.coupled[i][i];
    }
  }
  const int first = component <= 3 ? 1 : 4;
  double largest = 0;
  for (int i = first; i < first + 3; ++i) {
    if (has_component(available, i)) {
      largest = std::max(largest, diagonal[static_cast<std::size_t>(i - 1)]);
    }
  }
  return largest > 0 ? 1000.0 * largest : 1.0e8;
}

}  // namespace clinch
