// Connector damping in a static step (behaviors.md §8): the viscous force f^v = C·v (linear
// uncoupled and coupled) plus f^v_i = table_i(v_i) (NONLINEAR), with the velocity v = Δu/Δt of
// the increment; every definition on a component adds (§2). Its tangent is C/Δt plus the table
// slopes over Δt. The force is reported as CVF and enters CTF.
#pragma once

#include <memory>

#include "src/behavior/behavior.hpp"
#include "src/model/behavior_model.hpp"

namespace clinch {

// The damping of `behavior` on the `available` components; nullptr when none acts there. The
// model must have passed validation.
std::unique_ptr<Behavior> make_damping_behavior(const ConnectorBehavior& behavior,
                                                ComponentMask available);

}  // namespace clinch
