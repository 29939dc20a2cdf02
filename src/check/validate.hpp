// Whole-model validation: everything that needs the complete model (references, sections,
// behaviour rules, steps), run by `clinch check` and before every run. Each family has its own
// function; validate_model runs them in dependency order.
#pragma once

namespace clinch {

class DiagnosticSink;
struct Model;

// Sections, orientations, springs: types, element kinds, section_of_element, behaviour refs.
void validate_sections(Model& model, DiagnosticSink& sink);
// Behaviour rules of behaviors.md (attachment, duplicates, components available).
void validate_behaviors(Model& model, DiagnosticSink& sink);
// Derived components, potentials and friction (derived-components-and-potentials.md, friction.md).
void validate_potentials_and_friction(Model& model, DiagnosticSink& sink);
// Amplitudes, steps, conditions, loads and output requests (keywords.md §8–§18).
void validate_history(Model& model, DiagnosticSink& sink);

void validate_model(Model& model, DiagnosticSink& sink);

// Errors for what `clinch run` cannot run yet although validate_model accepts it (FORCE damage
// beside friction or RIGID elasticity). `clinch check` and `clinch run` both call it after reading,
// so that check never passes a deck that run refuses; tests of the validation alone do not.
void report_run_refusals(const Model& model, DiagnosticSink& sink);

}  // namespace clinch
