// The law stack of a connector behaviour on one section, in the order of behaviors.md §1.3:
// the elastic-plastic law, the damage that degrades it (§7), the damping (in parallel, behaviors.md §8), then one friction law per
// *CONNECTOR FRICTION in deck order.
#pragma once

#include <memory>
#include <vector>

#include "src/behavior/behavior.hpp"
#include "src/behavior/damage/damage_behavior.hpp"
#include "src/model/behavior_model.hpp"

namespace clinch {

// The laws of `behavior` that act on some of the `available` components of a section whose
// constrained components are `constrained`, with the section's damage controls. The model must
// have passed validation.
std::vector<std::unique_ptr<Behavior>> make_connector_laws(const ConnectorBehavior& behavior,
                                                           ComponentMask available,
                                                           ComponentMask constrained,
                                                           const DamageControls& controls = {});

}  // namespace clinch
