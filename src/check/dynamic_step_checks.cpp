// What a *DYNAMIC step cannot run yet (docs/dynamics.md "Not yet supported"), refused at the
// *DYNAMIC line or at the keyword that asks for it, so that `clinch check` never passes a deck
// that `clinch run` would integrate wrongly: kinematic constraints (rigid-body inertia), and the
// options of *MASS and *ROTARY INERTIA that clinch does not read (mass-proportional damping
// ALPHA, ORIENTATION, COMPOSITE).
#include <fmt/format.h>

#include <algorithm>

#include "base/diagnostic.hpp"
#include "src/check/check.hpp"
#include "src/model/active_dofs.hpp"
#include "src/model/inertia_elements.hpp"
#include "src/model/model.hpp"

namespace clinch {
namespace {

void refuse(DiagnosticSink& sink, SourceLoc loc, std::string message) {
  sink.report(DiagCode::unsupported_option, loc, std::move(message));
}

}  // namespace

const ConstraintSource* first_kinematic_constraint(const Model& model) {
  const ConstraintModel& c = model.constraints;
  if (c.rigid_bodies.empty() && c.couplings.empty() && c.mpcs.empty() &&
      c.equation_definitions.empty()) {
    return nullptr;
  }
  static const ConstraintSource kUnnamed{"*RIGID BODY, *COUPLING, *MPC or *EQUATION", {}};
  return c.sources.empty() ? &kUnnamed : &c.sources.front();
}

namespace {

void check_step(const Model& model, const Step& step, DiagnosticSink& sink) {
  const SourceLoc at = step.dynamic->loc;
  if (const ConstraintSource* constraint = first_kinematic_constraint(model)) {
    Diagnostic& d = sink.report(
        DiagCode::unsupported_option, at,
        "*DYNAMIC with kinematic constraints (*RIGID BODY, *COUPLING, *MPC, *EQUATION) is not "
        "supported by clinch yet: the inertia of rigid bodies and of constrained nodes is not "
        "implemented");
    if (constraint->loc.valid()) {
      d.notes.push_back({constraint->loc, fmt::format("{} is here", constraint->keyword)});
    }
  }
}

// *MASS and *ROTARY INERTIA options that would change the inertia clinch assembles.
void check_inertia_sections(const Model& model, DiagnosticSink& sink) {
  for (const ElementSection& section : model.structure.sections) {
    const bool mass = section.kind == ElementSection::Kind::Mass;
    if (!mass && section.kind != ElementSection::Kind::RotaryInertia) continue;
    for (const KeptParameter& p : section.parameters) {
      if (p.name != "ALPHA" && p.name != "ORIENTATION" && p.name != "COMPOSITE") continue;
      refuse(sink, section.keyword_loc,
             fmt::format("{} on *{} is not supported by clinch yet in a *DYNAMIC or *FREQUENCY step{}", p.name,
                         section.keyword,
                         p.name == "ALPHA" ? " (mass-proportional damping)"
                         : p.name == "ORIENTATION"
                             ? " (give the inertia in the global axes)"
                             : ""));
    }
    for (std::size_t i = 0; !section.rows.empty() && i < section.rows[0].values.size(); ++i) {
      // A negative mass or principal inertia makes the equations of motion unstable.
      if ((mass || i < 3) && section.rows[0].values[i] < 0.0) {
        sink.report(DiagCode::value_out_of_range, section.rows[0].loc,
                    fmt::format("*{} value {} is negative ({})", section.keyword, i + 1,
                                section.rows[0].values[i]));
      }
    }
  }
}

// Inertia on a node none of whose translations (rotations) an element uses has no equation of
// motion and is left out (nodal_inertia.hpp); said once per section, at its first such element.
void check_inertia_dofs(const Model& model, DiagnosticSink& sink) {
  const std::vector<std::int32_t> node_of = inertia_element_nodes(model);
  const std::vector<DofMask> active = active_dofs(model);
  for (const ElementSection& section : model.structure.sections) {
    const bool mass = section.kind == ElementSection::Kind::Mass;
    if (!mass && section.kind != ElementSection::Kind::RotaryInertia) continue;
    const DofMask wanted = mass ? 0b000111 : 0b111000;
    std::int32_t first = -1;
    std::size_t count = 0;
    for (std::int32_t e : section.elements) {
      const std::int32_t node = node_of[static_cast<std::size_t>(e)];
      if (node < 0 || (active[static_cast<std::size_t>(node)] & wanted) != 0) continue;
      if (count++ == 0) first = e;
    }
    if (count == 0) continue;
    const Element& element = model.elements[static_cast<std::size_t>(first)];
    sink.report(DiagCode::inactive_dof, element.loc(),
                fmt::format("the {} of element {} acts on no DOF: no connector or spring uses the "
                            "{} of its node, so it has no equation of motion and is left out{}",
                            mass ? "mass" : "rotary inertia",
                            qualified_label(model, element.instance, element.label),
                            mass ? "translations" : "rotations",
                            count > 1 ? fmt::format(" (and {} more element{} of *{})", count - 1,
                                                    count > 2 ? "s" : "", section.keyword)
                                      : ""));
  }
}

}  // namespace

bool has_dynamic_step(const Model& model) {
  return std::any_of(model.history.steps.begin(), model.history.steps.end(),
                     [](const Step& s) { return s.dynamic || s.frequency; });
}

void check_dynamic_steps(const Model& model, DiagnosticSink& sink) {
  if (!has_dynamic_step(model)) return;
  for (const Step& step : model.history.steps) {
    if (step.dynamic) check_step(model, step, sink);
  }
  check_inertia_sections(model, sink);
  check_inertia_dofs(model, sink);
}

}  // namespace clinch
