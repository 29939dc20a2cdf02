// One connector friction definition as a law of the connector's stack (friction.md §4): a stick
// spring K_s between the motion of the friction components J and the slip u_s, a backward-Euler
// return onto P(f) ≤ F_lim with F_N from the connector's other forces at the iterate, and the
// consistent tangent including ∂f/∂F_N (unsymmetric when the contact force varies, §4.2).
// Returns: radial in closed form for P = |f_i| and the predefined circle (§4.1 step 4), the
// closest-point and multi-surface returns of plasticity for a *CONNECTOR POTENTIAL, with the
// capacity F_lim(γ) in place of the yield size.
#pragma once

#include <cstddef>
#include <memory>

#include "src/behavior/behavior.hpp"
#include "src/model/behavior_model.hpp"

namespace clinch {

// The law of friction definition `index` of `behavior` on a section with these available and
// constrained components. The model must have passed validation.
std::unique_ptr<Behavior> make_friction_behavior(const ConnectorBehavior& behavior,
                                                 std::size_t index, ComponentMask available,
                                                 ComponentMask constrained);

}  // namespace clinch
