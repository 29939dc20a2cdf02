// Plain data for *RIGID BODY, *KINEMATIC COUPLING and *COUPLING (with *KINEMATIC or
// *DISTRIBUTING) as the deck writes them (docs/constraints.md). The resolve stage
// (src/resolve/resolve_rigid_bodies.cpp) turns them into the followers and linear constraints of
// constraint_model.hpp and fills the fields marked "resolved".
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/source_location.hpp"
#include "src/model/name.hpp"
#include "src/model/references.hpp"

namespace clinch {

// *RIGID BODY: Abaqus form (REF NODE with ELSET, PIN NSET, TIE NSET) or CalculiX form (NSET,
// REF NODE, ROT NODE). Nodes of the ELSET's elements and of TIE NSET/NSET are tie nodes, PIN
// NSET nodes pin nodes (a pin node stays a pin node when its element is in the ELSET).
struct RigidBodyDefinition {
  SourceLoc keyword_loc;
  std::int32_t part = 0;  // scope where it was written
  std::optional<TargetRef> ref_node;  // REF NODE= (a node, or a set of exactly one node)
  std::optional<TargetRef> rot_node;  // ROT NODE= (CalculiX)
  std::optional<TargetRef> elset;
  std::optional<TargetRef> pin_nset;
  std::optional<TargetRef> tie_nset;
  std::optional<TargetRef> nset;  // NSET= (CalculiX): tie nodes
  // Resolved: global indices. A body written inside a part is resolved once per instance:
  // `elements` holds every instance's, the nodes those of the last instance.
  std::int32_t reference = -1;
  std::int32_t rotation_node = -1;
  std::vector<std::int32_t> elements;
  std::vector<std::int32_t> tie_nodes, pin_nodes;  // sorted, disjoint, without the reference
};

// The mass of one of a rigid body's elements from its density and volume
// (src/model/element_mass.hpp): a point mass at a node that the resolve stage adds at the
// element's centre of mass and pins to the body's reference node, and the element's rotary
// inertia about that centre on the reference node. Both are exact and positive, so the body's
// mass, centre and inertia tensor are those of its elements in every procedure.
struct ElementMassPoint {
  std::int32_t element = 0;
  std::int32_t node = 0;       // the added node at the centre of mass (global index)
  std::int32_t reference = 0;  // the body's reference node (global index)
  double mass = 0.0;
  std::array<double, 6> rotary{};  // about the centre, global axes: I11, I22, I33, I12, I13, I23
};

// One DOF range of a coupling: first…last (1…6).
struct DofRange {
  int first = 0, last = 0;
  SourceLoc loc;
};

// *KINEMATIC COUPLING, or *COUPLING followed by *KINEMATIC or *DISTRIBUTING.
struct CouplingDefinition {
  enum class Kind : std::uint8_t { KinematicCoupling, Kinematic, Distributing };
  enum class Weighting : std::uint8_t { Uniform, Linear, Quadratic, Cubic };
  Kind kind = Kind::KinematicCoupling;
  SourceLoc keyword_loc;       // *KINEMATIC COUPLING or *COUPLING line
  SourceLoc method_loc;        // *KINEMATIC or *DISTRIBUTING line (a *COUPLING only)
  bool method_given = false;   // *COUPLING: *KINEMATIC or *DISTRIBUTING followed
  std::int32_t part = 0;
  std::string constraint_name;  // CONSTRAINT NAME= (messages)
  std::optional<TargetRef> ref_node;
  // *KINEMATIC COUPLING: one data line per node or node set with its DOF range.
  struct NodeLine {
    TargetRef target;
    DofRange dofs;
  };
  std::vector<NodeLine> node_lines;
  // *COUPLING: the surface of the coupling nodes, and its options.
  std::optional<Name> surface;
  std::optional<double> influence_radius;
  // ORIENTATION=: accepted when the constrained DOFs do not depend on it (checked in resolve).
  std::optional<Name> orientation;
  SourceLoc orientation_loc;  // the parameter's name
  // *KINEMATIC / *DISTRIBUTING data lines; none: every DOF.
  std::vector<DofRange> dof_ranges;
  Weighting weighting = Weighting::Uniform;
  bool refused = false;  // a data line was refused (reported): resolve leaves it out
  // Resolved (for a coupling written inside a part: its last instance's).
  std::int32_t reference = -1;
  std::vector<std::int32_t> nodes;    // coupling nodes (global), without the reference node
  std::vector<double> weights;        // *DISTRIBUTING: the weight factor of each node
  // "*COUPLING 'name'" or "*KINEMATIC COUPLING" for messages.
  std::string display() const {
    if (kind == Kind::KinematicCoupling) return "*KINEMATIC COUPLING";
    return constraint_name.empty() ? "*COUPLING" : "*COUPLING '" + constraint_name + "'";
  }
};

}  // namespace clinch
