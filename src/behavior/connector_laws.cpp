#include "src/behavior/connector_laws.hpp"

#include "src/behavior/damage/damage_behavior.hpp"
#include "src/behavior/damping/damping_behavior.hpp"
#include "src/behavior/friction/friction_behavior.hpp"
#include "src/behavior/plastic/elastic_plastic_behavior.hpp"

namespace clinch {

std::vector<std::unique_ptr<Behavior>> make_connector_laws(const ConnectorBehavior& behavior,
                                                           ComponentMask available,
                                                           ComponentMask constrained,
                                                           const DamageControls& controls) {
  std::vector<std::unique_ptr<Behavior>> laws;
  if (auto law = make_connector_behavior(behavior, available)) laws.push_back(std::move(law));
  // Damage reads the elastic-plastic force right below it and degrades only that (§7.3).
  if (auto law = make_damage_behavior(behavior, available, controls)) {
    laws.push_back(std::move(law));
  }
  // Damping acts in parallel (§8); before friction, whose contact force reads CTF (which holds
  // CVF) without its own friction force (friction.md §2.2).
  if (auto law = make_damping_behavior(behavior, available)) laws.push_back(std::move(law));
  for (std::size_t f = 0; f < behavior.frictions.size(); ++f) {
    if (auto law = make_friction_behavior(behavior, f, available, constrained)) {
      laws.push_back(std::move(law));
    }
  }
  return laws;
}

}  // namespace clinch
