// What `clinch run` cannot run yet although `clinch check` validates it (README, docs/decisions.md
// "Behaviours not yet run": FORCE damage beside friction or RIGID): reported by both commands, so
// that `check` never passes a deck that `run` then refuses, and the refusal names file, line and
// column.
#include <fmt/format.h>

#include "base/diagnostic.hpp"
#include "src/check/check.hpp"
#include "src/model/model.hpp"

namespace clinch {
namespace {

bool has_rigid_elasticity(const ConnectorBehavior& behavior) {
  for (const ConnectorElasticity& e : behavior.elasticities) {
    if (e.kind == ConnectorElasticity::Kind::Rigid) return true;
  }
  return false;
}

}  // namespace

void report_run_refusals(const Model& model, DiagnosticSink& sink) {
  const auto& behaviors = model.behaviors.behaviors;
  std::vector<bool> in_use(behaviors.size(), false);
  for (const ConnectorSection& section : model.sections.connector_sections) {
    if (section.behavior_index >= 0 && !section.elements.empty()) {
      in_use[static_cast<std::size_t>(section.behavior_index)] = true;
    }
  }
  for (std::size_t b = 0; b < behaviors.size(); ++b) {
    if (!in_use[b]) continue;
    const ConnectorBehavior& behavior = behaviors[b];
    auto refuse = [&](SourceLoc loc, std::string_view keyword) {
      sink.report(DiagCode::unsupported_option, loc,
                  fmt::format("{} is not supported by clinch run yet (clinch check validates "
                              "it, but the deck cannot be run)",
                              keyword))
          .notes.push_back(
              {behavior.loc, fmt::format("in connector behavior '{}'", behavior.name.display)});
    };
    for (const DamageInitiation& d : behavior.damage_initiations) {
      if (!d.valid) continue;
      // The FORCE criterion reads the total force (behaviors.md §7.1): the damage law sees the
      // elastic-plastic force below it and the constraint forces, but friction comes after it
      // in the stack, and a RIGID component's force is a multiplier it cannot degrade.
      if (d.criterion == DamageInitiation::Criterion::Force &&
          (!behavior.frictions.empty() || has_rigid_elasticity(behavior))) {
        refuse(d.criterion_loc,
               "CRITERION=FORCE in a behavior that also has friction or RIGID elasticity");
      }
    }
  }
}

}  // namespace clinch
