// The mass of the solid and shell elements that a rigid body carries, from their density and
// volume (docs/dynamics.md "Inertia on constrained nodes"). Abaqus computes a rigid body's mass
// and inertia from its elements; clinch lumps each element's mass on its nodes as ∫ρNᵢ dV, which
// keeps the mass and its first moment exact, and gives the rest of the second moment (what the
// lumps miss of ∫ρ x xᵀ dV) to the body's reference node as a rotary inertia, so that the body's
// mass, centre and inertia tensor are those of its elements. A shell's mass is ρ t per unit area,
// its second moment with the thickness term ρ t³/12 n nᵀ.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "base/small_types.hpp"

namespace clinch {

struct Model;
struct ElementBlock;

struct ElementMassLump {
  std::int32_t element = 0, node = 0;  // global indices
  double mass = 0.0;
};

struct ReferenceRotaryInertia {
  std::int32_t node = 0;             // the rigid body's reference node
  Matrix3 inertia = Matrix3::Zero();  // global axes; a correction, not positive by itself
};

struct RigidBodyElementMass {
  std::vector<ElementMassLump> lumps;
  std::vector<ReferenceRotaryInertia> rotary;
};

// Whether clinch computes the mass of the elements of `block`: the linear tetrahedra and
// hexahedra (C3D4, C3D8 and their variants) and the linear shells (S3, S4 and theirs).
bool element_mass_computed(const ElementBlock& block);

// The density of the material of each element's section, and a shell's thickness (its first
// data line), by global element index: none when the element has no solid or shell section or
// its material no *DENSITY.
struct ElementMassData {
  double density = 0.0;
  double thickness = 0.0;  // shells
};
std::vector<std::optional<ElementMassData>> element_mass_data(const Model& model);

// The element masses of every rigid body's solid and shell elements of the computed types that
// have a density (the others are refused or warned about: src/check/dynamic_step_checks.cpp).
RigidBodyElementMass rigid_body_element_mass(const Model& model);

}  // namespace clinch
