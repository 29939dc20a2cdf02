// The resolve stage: fills the model from what the reader recorded, once the deck is complete.
// Instances are placed, sets replayed, references followed to node and element indices, sections
// joined to their elements and behaviours, derived components and potential contributions
// classified, and step targets and output requests expanded. It reports what it cannot fill (a
// name that is not defined, a value that contradicts its keyword) at the field at fault. The check
// stage (src/check/check.hpp) then only reads the resolved model. Each family has its own
// function; resolve_model runs them in dependency order.
#pragma once

namespace clinch {

class DiagnosticSink;
struct Model;

// input-syntax.md §7: set operations, element nodes, instance placement, the global arrays.
void resolve_geometry(Model& model, DiagnosticSink& sink);
// Sections, orientations, springs: types, element kinds, section_of_element, behaviour refs.
void resolve_sections(Model& model, DiagnosticSink& sink);
// The sections, materials, surfaces and display bodies of held elements (structure_model.hpp).
void resolve_structure(Model& model, DiagnosticSink& sink);
// *RIGID BODY and the couplings into the followers and equations of constraint_model.hpp; before
// resolve_history, whose active_dofs() reads them (src/resolve/resolve_rigid_bodies.cpp).
void resolve_rigid_bodies(Model& model, DiagnosticSink& sink);
// *MPC and *EQUATION into the followers, equations and links of constraint_model.hpp; before
// resolve_history for the same reason (src/resolve/resolve_mpc_equations.cpp).
void resolve_mpc_equations(Model& model, DiagnosticSink& sink);
// The mass of rigid bodies' elements from their density: a node at each element's centre of mass,
// pinned to the body's reference node (src/resolve/resolve_element_masses.cpp); after the
// sections and the bodies, before anchor_rigid_bodies, which rewrites the followers.
void resolve_rigid_body_element_masses(Model& model);
// A *BOUNDARY on a rigid body's node other than its reference node acts on the body: the body
// is anchored at the node in that translation, and a tie node's rotation moves to the reference
// node (src/resolve/anchor_rigid_bodies.cpp). Called by resolve_history once the *BOUNDARY
// targets are resolved and before the active DOFs are, which read the followers.
void anchor_rigid_bodies(Model& model);
// Derived components, potentials and friction (derived-components-and-potentials.md, friction.md):
// names inside each behaviour block, classification, and the rules that need it.
void resolve_potentials_and_friction(Model& model, DiagnosticSink& sink);
// Amplitudes, steps, conditions, loads and output requests (keywords.md §8–§18).
void resolve_history(Model& model, DiagnosticSink& sink);

void resolve_model(Model& model, DiagnosticSink& sink);

}  // namespace clinch
