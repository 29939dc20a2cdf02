// Which DOFs of each node some element uses (keywords.md, "DOF numbering"): the rule behind the
// inactive-DOF checks of *BOUNDARY (W0803) and *CLOAD (E0801), the silent skipping of nodal
// output components, and later the analysis plan's DOF map. Kept in one place so that it can be
// refined (connection-types.md §1.1) without touching its users.
#pragma once

#include <cstdint>
#include <vector>

namespace clinch {

struct Model;

// Bit d − 1 stands for DOF d (1–3 translations, 4–6 rotations).
using DofMask = std::uint8_t;

// DOF mask of every global node; 0 for a node that belongs to no element. Valid after
// resolve_sections (it reads section_of_element and the *SPRING DOFs).
std::vector<DofMask> active_dofs(const Model& model);

// The DOFs of each node that follow another node (rigid bodies, couplings, MPCs: the resolved
// NodeFollower list): a *CLOAD there acts on what the node follows, so it has a DOF even where no
// element uses the node.
std::vector<DofMask> following_dofs(const Model& model);

}  // namespace clinch
