// What an analysis does with the elements clinch holds as nodes only (src/model/element_library.hpp,
// docs/decisions.md "Elements held as nodes"): one decision per *ELEMENT block.
#include <fmt/format.h>

#include <algorithm>

#include "base/diagnostic.hpp"
#include "src/check/check.hpp"
#include "src/model/element_library.hpp"
#include "src/model/model.hpp"

namespace clinch {
namespace {

// Whether `part` is in the analysis: the root part always, another part when an instance
// places it (an element of a part that is never placed takes no part in the analysis).
bool part_is_placed(const Model& model, std::int32_t part) {
  for (const Instance& instance : model.instances) {
    if (instance.part == part) return true;
  }
  return false;
}

// The global elements that a *RIGID BODY's ELSET carries (resolve_rigid_bodies).
std::vector<bool> rigid_elements(const Model& model) {
  std::vector<bool> rigid(model.elements.size(), false);
  for (const RigidBodyDefinition& body : model.constraints.rigid_bodies) {
    for (std::int32_t e : body.elements) rigid[static_cast<std::size_t>(e)] = true;
  }
  return rigid;
}

// The elements of `block` (of part `part`) that stay deformable, and how many copies its
// instances make of it: a part placed twice is one block of the deck, two sets of elements.
struct BlockCount {
  std::int64_t deformable = 0, total = 0;
};
BlockCount count_deformable(const Model& model, std::int32_t part, const ElementBlock& block,
                            const std::vector<bool>& rigid) {
  BlockCount count;
  for (std::size_t i = 0; i < model.instances.size(); ++i) {
    const Instance& instance = model.instances[i];
    if (instance.part != part || (part != 0 && i == 0)) continue;
    for (std::int32_t k = 0; k < block.count; ++k) {
      const auto e = static_cast<std::size_t>(block.first_element + k + instance.element_offset);
      ++count.total;
      if (e >= rigid.size() || !rigid[e]) ++count.deformable;
    }
  }
  return count;
}

// A block with no formulation cannot be run: clinch has no solid, shell, beam, ... element.
// *RIGID BODY lifts this for the elements its ELSET carries: then only their nodes count. A block
// that is only partly inside rigid bodies is refused once, for its deformable elements. MASS and
// ROTARYI carry inertia only, which plays no role in *STATIC (Abaqus Analysis User's Guide,
// "Static stress analysis"): in a deck without a *DYNAMIC step or gravity they are kept and
// noted, not refused; a dynamic step uses them (nodal_inertia.hpp), gravity loads their masses.
void judge_block(const Model& model, std::int32_t part, const ElementBlock& block,
                 const std::vector<bool>& rigid, bool dynamic, DiagnosticSink& sink) {
  if (block.count == 0) return;
  const auto family = static_cast<ElementFamily>(block.family);
  if (is_inertia_only(family)) {
    if (dynamic) return;
    sink.report(DiagCode::inertia_ignored, block.type_loc,
                fmt::format("{} elements carry inertia only, which a *STATIC step does not use; "
                            "they are kept and have no effect on the results",
                            block.type));
    return;
  }
  if (block.formulation == ElementBlock::Formulation::RigidOnly) return;
  const BlockCount count = count_deformable(model, part, block, rigid);
  if (count.deformable == 0) return;
  const std::string of_total =
      count.deformable == count.total ? std::string()
                                      : fmt::format(" (of {}, the others in a rigid body)",
                                                    count.total);
  sink.report(DiagCode::deformable_element, block.type_loc,
              fmt::format("{} {} element{}{} of type {} would be deformable, and clinch has no "
                          "{} formulation: make its part a rigid body (*RIGID BODY) or remove it",
                          count.deformable, element_family_name(family),
                          count.deformable == 1 ? "" : "s", of_total, block.type,
                          element_family_name(family)));
}

}  // namespace

void check_held_elements(const Model& model, DiagnosticSink& sink) {
  const std::vector<bool> rigid = rigid_elements(model);
  // Gravity (*DLOAD, GRAV) loads the masses in any step.
  const bool dynamic =
      has_dynamic_step(model) ||
      std::any_of(model.history.steps.begin(), model.history.steps.end(),
                  [](const Step& s) { return !s.gravity.empty(); });
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    if (!part_is_placed(model, static_cast<std::int32_t>(p))) continue;
    for (const ElementBlock& block : model.parts[p].element_blocks) {
      judge_block(model, static_cast<std::int32_t>(p), block, rigid, dynamic, sink);
    }
  }
}

}  // namespace clinch
