// Connector elasticity as a Behavior (behaviors.md §4): linear uncoupled, nonlinear uncoupled
// (a force–motion table) and coupled linear stiffness, restricted to the components the
// connection type makes available. RIGID elasticity is not a law but a constraint, so the plan
// asks for its components separately and the assembler enforces them (§4.4).
#pragma once

#include <memory>

#include "src/behavior/behavior.hpp"
#include "base/small_types.hpp"
#include "src/model/behavior_model.hpp"

namespace clinch {

// The elastic law of `behavior` on the components in `available` (every definition on a
// component added, §2); nullptr when the behaviour has no non-rigid elasticity on an available
// component. The model must have passed validation.
std::unique_ptr<Behavior> make_elastic_behavior(const ConnectorBehavior& behavior,
                                                ComponentMask available);
// Its NONLINEAR tables alone (the elastic-plastic law holds the linear part, §6.2).
std::unique_ptr<Behavior> make_nonlinear_elastic_behavior(const ConnectorBehavior& behavior,
                                                          ComponentMask available);

// The linear part of the elasticity of `behavior` on `available` (§4.1, §4.3, §4.4): the
// components with a linear uncoupled or a coupled stiffness or a rigid-plastic spring, and K over
// them, every definition added (zero rows and columns elsewhere).
// Plasticity needs it because its elastic law is F = K (u − u^pl) (§6.2).
struct LinearStiffness {
  Matrix6 k = Matrix6::Zero();
  ComponentMask components = 0;
  bool coupled = false;   // from a coupled (21-term) elasticity
  bool diagonal = true;   // no off-diagonal term on the kept components
};
LinearStiffness linear_stiffness(const ConnectorBehavior& behavior, ComponentMask available);

// Components of `available` that a RIGID elasticity of `behavior` holds exactly by a multiplier
// (§4.4: with COMPONENT=, that component; otherwise the listed ones, or every available one when
// none is listed), rigid-plastic components excepted.
ComponentMask rigid_components(const ConnectorBehavior& behavior, ComponentMask available);

}  // namespace clinch
