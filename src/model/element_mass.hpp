// The mass of the continuum, structural and truss elements that a rigid body carries, from their
// density and volume (docs/dynamics.md "Element mass of a rigid body"). Abaqus computes a rigid
// body's mass and inertia from its elements; clinch integrates each element's mass, centre of
// mass and inertia about that centre exactly over its isoparametric geometry (Gauss rules of
// sufficient degree). The resolve stage puts the mass at a node of its own at the centre and the
// inertia on the body's reference node (ElementMassPoint): lumping the mass on the element's
// corner nodes instead would keep the mass and centre but overstate the inertia, with a rest
// that is not positive. A surface (shell, membrane, planar element) has ρ t per unit area and
// the thickness term ρ t³/12 n nᵀ in its second moment; a truss ρ A per unit length, its
// cross-section adding no inertia (a thin rod); a beam ρ A per unit length and the
// cross-section's second moments ρ ∫x₁² dA, ρ ∫x₂² dA along its local axes n1, n2.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "base/small_types.hpp"

namespace clinch {

struct Model;
struct ElementBlock;

// The isoparametric geometries whose mass clinch integrates, in Abaqus node order.
enum class ElementShape : std::uint8_t {
  Line2,
  Line3,  // trusses and beams (Line3: the middle node second)
  Tri3,
  Tri6,
  Quad4,
  Quad8,
  Quad9,  // shells, membranes, planar continua
  Tet4,
  Tet10,
  Wedge6,
  Wedge15,
  Hex8,
  Hex20  // solids
};

// The shape of the elements of `block` whose mass clinch computes from their density: solids
// (C3D4, C3D6, C3D8, C3D10, C3D15, C3D20 and their variants, SC6R, SC8R), shells and membranes
// of 3, 4, 6, 8 or 9 nodes, plane stress and plane strain elements (CPS, CPE), trusses and
// beams. None for pyramids and axisymmetric elements (refused: src/check/dynamic_step_checks.cpp).
std::optional<ElementShape> mass_shape(const ElementBlock& block);
inline bool element_mass_computed(const ElementBlock& block) {
  return mass_shape(block).has_value();
}

// One element's mass, its centre of mass and its inertia tensor about that centre (global axes).
struct ElementMassProperties {
  double mass = 0.0;
  Vector3 centre = Vector3::Zero();
  Matrix3 rotary = Matrix3::Zero();  // positive semi-definite
};

// A beam's cross-section (*BEAM SECTION, SECTION=RECT, CIRC, PIPE or THICK PIPE): its area, its
// second moments ∫x₁² dA and ∫x₂² dA about its centroid along the local axes, and the
// approximate n1 axis of the section's second data line ((0, 0, −1) when not given), which
// the beam's tangent t makes exact (n1 ⟂ t, n2 = t × n1).
struct BeamProfile {
  double area = 0.0;
  double along_n1 = 0.0, along_n2 = 0.0;
  Vector3 n1 = Vector3(0, 0, -1);
};
// The profile of a *BEAM SECTION: SECTION= and its first data line; none for the other
// profiles (their mass is refused).
std::optional<BeamProfile> beam_profile(std::string_view section, std::span<const double> sizes);

// What an element's section gives its mass: the density ρ of its material (per unit volume,
// 0 without *DENSITY), the section factor (the first field of the section's first data line: a
// shell's, membrane's or planar element's thickness, a truss's area; 1 when blank) or a beam's
// profile, and for shells and membranes the OFFSET of the midsurface from the nodes (a fraction
// of the thickness along the normal: SPOS 0.5, SNEG −0.5; the midsurface lies at −offset·t·n
// from the reference surface) and the DENSITY= mass per unit area added to the material's. A
// section clinch cannot take names the parameter in `unsupported` (COMPOSITE, NODAL THICKNESS,
// SECTION=I, ...).
struct ElementMassData {
  double density = 0.0;
  double section = 1.0;
  std::optional<BeamProfile> beam;
  double offset = 0.0;
  double added_per_area = 0.0;
  std::string unsupported;
};

// The mass properties of an element of `shape` with nodes at `x` and section `data`.
ElementMassProperties element_mass_properties(ElementShape shape, std::span<const Vector3> x,
                                              const ElementMassData& data);

// The ElementMassData of each element, by global element index: none when the element has no
// solid, shell, membrane, truss or beam section, or neither its material's *DENSITY nor a
// section DENSITY= gives it mass and its section is one clinch takes.
std::vector<std::optional<ElementMassData>> element_mass_data(const Model& model);

// One element of a rigid body with its mass, and the body's reference node that carries it.
struct ElementMass : ElementMassProperties {
  std::int32_t element = 0, reference = 0;  // global indices
  std::int32_t body = 0;                    // into ConstraintModel::rigid_bodies
};

// The mass of every rigid body's elements of the computed shapes that have a density (the
// others are refused or warned about: src/check/dynamic_step_checks.cpp).
std::vector<ElementMass> rigid_body_element_masses(const Model& model);

}  // namespace clinch
