// What a *DYNAMIC step cannot run yet (docs/dynamics.md "Not yet supported"), refused at the
// *DYNAMIC line or at the keyword that asks for it, so that `clinch check` never passes a deck
// that `clinch run` would integrate wrongly: the mass of a rigid body's elements of the types
// whose mass clinch does not compute from their density and volume (element_mass.hpp; in
// *FREQUENCY steps too), and the options of *MASS and *ROTARY INERTIA that clinch does not read
// (mass-proportional damping ALPHA, ORIENTATION, COMPOSITE).
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>

#include "base/diagnostic.hpp"
#include "src/check/check.hpp"
#include "src/model/active_dofs.hpp"
#include "src/model/element_library.hpp"
#include "src/model/element_mass.hpp"
#include "src/model/inertia_elements.hpp"
#include "src/model/model.hpp"

namespace clinch {
namespace {

void refuse(DiagnosticSink& sink, SourceLoc loc, std::string message) {
  sink.report(DiagCode::unsupported_option, loc, std::move(message));
}

}  // namespace

namespace {

// Abaqus computes a rigid body's mass from the density and volume of the solid, shell, membrane,
// beam, truss and planar elements it carries (Abaqus Analysis User's Guide, "Rigid body
// definition": "the mass and inertia of a rigid body can be calculated based on contributions
// from its elements"). clinch computes it for the shapes of element_mass.hpp; a body that carries
// other elements, or sections clinch cannot weigh, is refused once per *ELEMENT block, since its
// inertia would be silently short, and elements whose material has no *DENSITY are noted to carry
// no mass, as in Abaqus. Rigid elements (R3D4, ...) carry no mass in
// Abaqus/Standard; MASS and ROTARYI are read.
void check_rigid_body_element_mass(const Model& model, DiagnosticSink& sink) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, const ElementBlock*> block_at;
  for (const Part& part : model.parts) {
    for (const ElementBlock& block : part.element_blocks) {
      block_at[{block.keyword_loc.file, block.keyword_loc.line}] = &block;
    }
  }
  std::set<const ElementBlock*> reported;
  const std::vector<std::optional<ElementMassData>> mass_data = element_mass_data(model);
  for (const RigidBodyDefinition& body : model.constraints.rigid_bodies) {
    for (const std::int32_t e : body.elements) {
      const Element& element = model.elements[static_cast<std::size_t>(e)];
      const auto found = block_at.find({element.file, element.keyword_line});
      if (found == block_at.end()) continue;
      const ElementBlock& block = *found->second;
      const auto family = static_cast<ElementFamily>(block.family);
      if (is_inertia_only(family) || family == ElementFamily::Rigid ||
          family == ElementFamily::Analysed) {
        continue;
      }
      // The body's mass would be short without a word: refused once per block.
      const auto refuse = [&](const std::string& what) {
        Diagnostic& d = sink.report(
            DiagCode::unsupported_option, block.type_loc,
            fmt::format("the mass of the {} elements of type {} in a rigid body {} is not "
                        "supported by clinch in a *DYNAMIC or *FREQUENCY step or under gravity: "
                        "{}; give the body's mass as MASS and ROTARYI elements on its nodes, and "
                        "remove these elements",
                        element_family_name(family), block.type,
                        what.empty() ? "(from their density and volume)" : "with " + what,
                        what.empty() ? "it computes it for solids, shells, membranes, plane "
                                       "stress and plane strain elements, trusses and beams, not "
                                       "for pyramids or axisymmetric elements"
                                     : "beams take the profiles RECT, CIRC, PIPE and THICK PIPE, "
                                       "shells a single material and thickness"));
        if (body.keyword_loc.valid()) d.notes.push_back({body.keyword_loc, "*RIGID BODY is here"});
      };
      if (element_mass_computed(block)) {
        const auto& data = mass_data[static_cast<std::size_t>(e)];
        if ((data && data->unsupported.empty()) || !reported.insert(&block).second) continue;
        if (data) {
          refuse(data->unsupported + " on their section");
          continue;
        }
        sink.report(DiagCode::parameter_ignored, block.type_loc,
                    fmt::format("the {} elements of type {} in a rigid body carry no mass: they "
                                "have no section with a material that gives *DENSITY",
                                element_family_name(family), block.type));
        continue;
      }
      if (reported.insert(&block).second) refuse("");
    }
  }
}

// Whether a kinematic constraint eliminates a rotation of `node` (a rigid body's tie node, a
// kinematic coupling node, MPC BEAM, an *EQUATION whose first term is a rotation).
bool rotation_is_dependent(const Model& model, std::int32_t node) {
  const ConstraintModel& c = model.constraints;
  for (const NodeFollower& f : c.followers) {
    if (f.node == node && (f.dofs & 0b111000) != 0) return true;
  }
  for (const LinearConstraint& e : c.equations) {
    if (!e.terms.empty() && e.terms.front().node == node && e.terms.front().dof >= 4) return true;
  }
  return false;
}

// Under NLGEOM a ROTARYI turns by finite rotations with the node's own update
// (rotary_inertia_finite.hpp); a node whose rotation a constraint gives has no such update.
void check_step(const Model& model, const Step& step, DiagnosticSink& sink) {
  if (!step.nlgeom) return;
  const std::vector<std::int32_t> node_of = inertia_element_nodes(model);
  for (const ElementSection& section : model.structure.sections) {
    if (section.kind != ElementSection::Kind::RotaryInertia) continue;
    for (const std::int32_t e : section.elements) {
      const std::int32_t node = node_of[static_cast<std::size_t>(e)];
      if (node < 0 || !rotation_is_dependent(model, node)) continue;
      Diagnostic& d = sink.report(
          DiagCode::unsupported_option, section.keyword_loc,
          "*ROTARY INERTIA on a node whose rotation a kinematic constraint gives (a rigid body's "
          "tie node, a coupling node, MPC BEAM, *EQUATION) is not supported by clinch with "
          "NLGEOM: put the rotary inertia on the reference node, which turns with the same "
          "rotation");
      d.notes.push_back({step.dynamic->loc, "the NLGEOM *DYNAMIC step is here"});
      break;
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
  // Gravity loads a rigid body's element mass in any step (docs/dynamics.md "Gravity").
  const bool gravity = std::any_of(model.history.steps.begin(), model.history.steps.end(),
                                   [](const Step& s) { return !s.gravity.empty(); });
  if (!has_dynamic_step(model)) {
    if (gravity) check_rigid_body_element_mass(model, sink);
    return;
  }
  for (const Step& step : model.history.steps) {
    if (step.dynamic) check_step(model, step, sink);
  }
  check_inertia_sections(model, sink);
  check_inertia_dofs(model, sink);
  check_rigid_body_element_mass(model, sink);
}

}  // namespace clinch
