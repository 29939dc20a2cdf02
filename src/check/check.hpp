// The check stage: the rules that need the whole resolved model (behaviors.md: attachment,
// duplicates, components available in every section that uses a behaviour), reading the model
// and reporting, never writing it. It runs after resolve (src/resolve/resolve.hpp).
#pragma once

namespace clinch {

class DiagnosticSink;
struct Model;

// Behaviour rules of behaviors.md (attachment, duplicates, components available).
void check_behaviors(const Model& model, DiagnosticSink& sink);

// motion-suspends-stop at each *CONNECTOR MOTION line that drives a component with a stop.
void check_motion_stops(const Model& model, DiagnosticSink& sink);

// One decision per block of held elements (solids, shells, beams, masses, ...): refused while
// deformable, noted when inertia only and no step is dynamic (held_elements.cpp).
void check_held_elements(const Model& model, DiagnosticSink& sink);

// Overconstraints across rigid bodies, couplings, MPCs and equations: a DOF tied twice or also
// prescribed, cycles, chains and linearised maps under NLGEOM, connectors inside a rigid group
// (constraint_checks.cpp).
void check_constraints(const Model& model, DiagnosticSink& sink);

// What a *DYNAMIC step cannot run yet (dynamic_step_checks.cpp), and the values of *MASS and
// *ROTARY INERTIA that the inertia of a dynamic or frequency step reads.
void check_dynamic_steps(const Model& model, DiagnosticSink& sink);
// A step reads the inertia: *DYNAMIC or *FREQUENCY.
bool has_dynamic_step(const Model& model);

// What a *FREQUENCY step cannot run yet (frequency_step_checks.cpp).
void check_frequency_steps(const Model& model, DiagnosticSink& sink);
// What a *STEP, PERTURBATION cannot have (perturbation_step_checks.cpp).
void check_perturbation_steps(const Model& model, DiagnosticSink& sink);
// TIME INTERVAL and NUMBER INTERVAL in force in a Riks step (output_interval_checks.cpp).
void check_output_intervals(const Model& model, DiagnosticSink& sink);

void check_model(const Model& model, DiagnosticSink& sink);

// Errors for what `clinch run` cannot run yet although check_model accepts it (FORCE damage
// beside friction or RIGID elasticity). `clinch check` and `clinch run` both call it after reading,
// so that check never passes a deck that run refuses; tests of the checks alone do not.
void report_run_refusals(const Model& model, DiagnosticSink& sink);

}  // namespace clinch
