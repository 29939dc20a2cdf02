// Connector damage as a law of the stack (behaviors.md §7), right after the elastic-plastic law
// whose force f^eff it degrades: each mechanism's damage from its initiation criterion and
// evolution, the overall damage of each affected component (§7.3), the force −d f^eff that makes
// the elastic force (1 − d) f^eff, and the consistent tangent −(d D^eff + f^eff ⊗ ∂d/∂u) of §7.4,
// which is unsymmetric. Friction, damping, stop and constraint forces are not degraded.
#pragma once

#include <memory>

#include "src/behavior/behavior.hpp"
#include "src/model/behavior_model.hpp"

namespace clinch {

// How damage ends, from the *SECTION CONTROLS of the section (keywords.md §5): deletion once
// every affected component reaches the largest damage, that largest damage, and the viscosity η
// of the regularisation d_v' = (d − d_v)/η (0: none).
struct DamageControls {
  bool element_deletion = true;
  double max_degradation = 1.0;
  double viscosity = 0.0;
};

// The damage law of `behavior` on the `available` components; nullptr when the behaviour has no
// damage initiation. The model must have passed validation.
std::unique_ptr<Behavior> make_damage_behavior(const ConnectorBehavior& behavior,
                                               ComponentMask available,
                                               const DamageControls& controls = {});

}  // namespace clinch
