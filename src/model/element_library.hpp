// The element types clinch reads (Abaqus element library): each with its node count and family.
// Connectors, springs and dashpots are analysed; every other type is held as its nodes only
// (a block of the model's ElementBlocks), which a rigid body may later carry (docs/decisions.md,
// "Elements held as nodes").
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "src/model/geometry.hpp"

namespace clinch {

// The family of a type held as nodes; it names the type in messages and decides what a static
// step does with it.
enum class ElementFamily : std::uint8_t {
  Analysed,  // a connector, spring or dashpot
  Solid, Shell, Membrane, Rigid, Beam, Truss, Planar, Mass, RotaryInertia
};

struct ElementTypeInfo {
  std::string_view name;  // canonical upper-case name, e.g. "C3D8R"
  ElementType type;       // ElementType::Held for every family but Analysed
  int nodes;              // nodes of one element
  ElementFamily family;
};

// The type of canonical (folded) name `name`, or nullptr.
const ElementTypeInfo* find_element_type(std::string_view name);

// Every known type, in table order (the unit tests read them all).
std::span<const ElementTypeInfo> element_types();

// "solid", "shell", "mass", ... for messages.
std::string_view element_family_name(ElementFamily family);

// The positions (1-based, in the element's node order) of the nodes of face `face` ("S1"…"S6",
// "SPOS", "SNEG") of an element of `info`'s type (the manual's face numbering of the solid,
// shell and rigid element libraries): the linear and quadratic tetrahedra, wedges and hexahedra
// (C3D4, C3D10, C3D6, C3D8, C3D20 and their variants), and the two sides SPOS/SNEG of shells,
// membranes and R3D3/R3D4 (every node). Empty when the type has no such face, or when clinch
// does not know the type's faces (C3D5, C3D15, SC6R, ...).
std::span<const int> face_node_positions(const ElementTypeInfo& info, std::string_view face);

// MASS and ROTARYI: inertia only, no stiffness (Abaqus: no role in a *STATIC step).
inline bool is_inertia_only(ElementFamily family) {
  return family == ElementFamily::Mass || family == ElementFamily::RotaryInertia;
}

}  // namespace clinch
