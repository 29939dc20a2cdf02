// Where MASS and ROTARYI elements sit (keywords.md: elements that carry inertia only): clinch
// holds them as nodes in their element blocks, so their node is found block by block and
// instance by instance.
#pragma once

#include <cstdint>
#include <vector>

namespace clinch {

struct Model;

// The global node of every MASS and ROTARYI element, by global element index (−1 for other
// elements and for an inertia element without a node).
std::vector<std::int32_t> inertia_element_nodes(const Model& model);

}  // namespace clinch
