// The mass of the solid and shell elements that a rigid body carries, from their density and
// volume (docs/dynamics.md "Inertia on constrained nodes"). Abaqus computes a rigid body's mass
// and inertia from its elements; clinch integrates each element's mass, centre of mass and
// inertia about that centre exactly (Gauss rules of sufficient degree). The resolve stage puts
// the mass at a node of its own at the centre and the inertia on the body's reference node
// (ElementMassPoint): lumping the mass on the element's corner nodes instead would keep the
// mass and centre but overstate the inertia, with a rest that is not positive. A shell's mass
// is ρ t per unit area, its inertia with the thickness term ρ t³/12 n nᵀ.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "base/small_types.hpp"

namespace clinch {

struct Model;
struct ElementBlock;

// One element's mass, its centre of mass and its inertia tensor about that centre (global
// axes), and the reference node of the rigid body that carries it.
struct ElementMass {
  std::int32_t element = 0, reference = 0;  // global indices
  std::int32_t body = 0;                     // into ConstraintModel::rigid_bodies
  double mass = 0.0;
  Vector3 centre = Vector3::Zero();
  Matrix3 rotary = Matrix3::Zero();  // positive semi-definite
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

// The mass of every rigid body's solid and shell elements of the computed types that have a
// density (the others are refused or warned about: src/check/dynamic_step_checks.cpp).
std::vector<ElementMass> rigid_body_element_masses(const Model& model);

}  // namespace clinch
