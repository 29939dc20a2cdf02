// Plain data for *MPC and *EQUATION as the deck writes them (docs/constraints.md). The resolve
// stage turns them into the followers, linear constraints and links of constraint_model.hpp.
#pragma once

namespace clinch {

struct MpcDefinition {};
struct EquationDefinition {};

}  // namespace clinch
