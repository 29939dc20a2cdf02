// Plain data for *RIGID BODY, *KINEMATIC COUPLING and *COUPLING (with *KINEMATIC or
// *DISTRIBUTING) as the deck writes them (docs/constraints.md). The resolve stage turns them into
// the followers and linear constraints of constraint_model.hpp.
#pragma once

namespace clinch {

struct RigidBodyDefinition {};
struct CouplingDefinition {};

}  // namespace clinch
