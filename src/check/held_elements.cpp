// What an analysis does with the elements clinch holds as nodes only (src/model/element_library.hpp,
// docs/decisions.md "Elements held as nodes"): one decision per *ELEMENT block.
#include <fmt/format.h>

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

// A block with no formulation cannot be run: clinch has no solid, shell, beam, ... element.
// *RIGID BODY will lift this by marking the blocks it carries Formulation::RigidOnly; then only
// their nodes count. MASS and ROTARYI carry inertia only, which plays no role in *STATIC
// (Abaqus Analysis User's Guide, "Static stress analysis"), the only procedure clinch runs: they
// are kept and noted, not refused.
void judge_block(const ElementBlock& block, DiagnosticSink& sink) {
  if (block.count == 0) return;
  const auto family = static_cast<ElementFamily>(block.family);
  if (is_inertia_only(family)) {
    sink.report(DiagCode::inertia_ignored, block.type_loc,
                fmt::format("{} elements carry inertia only, which a *STATIC step does not use; "
                            "they are kept and have no effect on the results",
                            block.type));
    return;
  }
  if (block.formulation == ElementBlock::Formulation::RigidOnly) return;
  sink.report(DiagCode::deformable_element, block.type_loc,
              fmt::format("{} {} element{} of type {} would be deformable, and clinch has no "
                          "{} formulation: make its part a rigid body (*RIGID BODY) or remove it",
                          block.count, element_family_name(family), block.count == 1 ? "" : "s",
                          block.type, element_family_name(family)));
}

}  // namespace

void check_held_elements(const Model& model, DiagnosticSink& sink) {
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    if (!part_is_placed(model, static_cast<std::int32_t>(p))) continue;
    for (const ElementBlock& block : model.parts[p].element_blocks) judge_block(block, sink);
  }
}

}  // namespace clinch
