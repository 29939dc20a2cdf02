// Plain data for the kinematic constraints of the scene around the connectors: *RIGID BODY,
// *KINEMATIC COUPLING, *COUPLING with *KINEMATIC or *DISTRIBUTING, *MPC and *EQUATION
// (docs/constraints.md). The reader keeps each definition as written (`definitions`); the resolve
// stage turns them into the flat lists the analysis eliminates: nodes whose DOFs follow a
// reference node, and linear equations. A dependent DOF keeps its place in the DOF map; its
// value is computed from the DOFs it depends on (src/assembly/dependent_dofs.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/source_location.hpp"
#include "src/model/active_dofs.hpp"
#include "src/model/mpc_equation_model.hpp"
#include "src/model/rigid_body_model.hpp"

namespace clinch {

// Where a constraint came from, for messages: "*RIGID BODY" at its keyword line, "*EQUATION" at
// the line of its first term, "*MPC BEAM" at its data line.
struct ConstraintSource {
  std::string keyword;
  SourceLoc loc;
};

// DOFs of `node` that follow `reference` (rigid body TIE and PIN nodes, kinematic coupling
// nodes, MPC BEAM, TIE and PIN). With `rigid_arm`, the translations follow the rigid motion of the
// reference node: u = u_ref + (R_ref − I)(X − X_ref) (small displacements: θ_ref × (X − X_ref));
// without, they equal u_ref (MPC TIE and PIN). Rotations equal the reference node's rotation.
// A rigid body prescribed in a translation at one of its other nodes is anchored there
// (docs/constraints.md "Conditions on a body's nodes"): that node keeps the translation as its
// own, and the body's nodes, the reference node among them, follow it in that translation,
// u = u_anchor + (R_ref − I)(X − X_anchor), the reference node still giving the rotation.
struct NodeFollower {
  std::int32_t node = -1;       // the dependent node (global index)
  std::int32_t reference = -1;  // the independent node (global index)
  DofMask dofs = 0;             // bit k − 1 for DOF k (a 2-D model uses 1, 2 and 6)
  bool rigid_arm = true;
  std::int32_t source = -1;     // into ConstraintModel::sources
  std::int32_t anchor = -1;     // whose translations `dofs` follow, when not the reference's
  // The node whose translations the follower's translations read.
  std::int32_t translation_source() const { return anchor >= 0 ? anchor : reference; }
};

// One term a·u of a linear constraint: DOF `dof` (1…6) of global node `node`.
struct LinearTerm {
  std::int32_t node = -1;
  int dof = 0;
  double coefficient = 0;
};

// Σ a_i u_i = 0 (*EQUATION; a distributing coupling's map in small displacements). The first
// term's DOF is the one eliminated (Abaqus: "the first nodal variable is eliminated").
struct LinearConstraint {
  std::vector<LinearTerm> terms;
  // False for a linearised map that only holds in small displacements (a distributing
  // coupling): a step with NLGEOM=YES refuses it.
  bool exact_under_nlgeom = true;
  std::int32_t source = -1;
};

// MPC LINK: the distance between `node` and `other` stays at its initial value; one translation
// of `node` (the one along which the link lies most) is eliminated.
struct DistanceLink {
  std::int32_t node = -1, other = -1;
  std::int32_t source = -1;
};

struct ConstraintModel {
  // As written.
  std::vector<RigidBodyDefinition> rigid_bodies;
  std::vector<CouplingDefinition> couplings;
  std::vector<MpcDefinition> mpcs;
  std::vector<EquationDefinition> equation_definitions;

  // Resolved: what the analysis eliminates.
  std::vector<ConstraintSource> sources;
  std::vector<NodeFollower> followers;
  std::vector<LinearConstraint> equations;
  std::vector<DistanceLink> links;
  // The mass of rigid bodies' elements, one point per element (added nodes among `followers`).
  std::vector<ElementMassPoint> element_masses;
};

}  // namespace clinch
