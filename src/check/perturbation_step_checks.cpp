// What a linear perturbation step cannot have (docs/perturbation.md): it is linear about its base
// state, so it has no geometric nonlinearity of its own, no time and no procedure with
// increments of its own. Each misuse is reported at the parameter or keyword that asks for it.
#include <fmt/format.h>

#include "base/diagnostic.hpp"
#include "src/check/check.hpp"
#include "src/model/model.hpp"

namespace clinch {

void check_perturbation_steps(const Model& model, DiagnosticSink& sink) {
  for (const Step& step : model.history.steps) {
    if (!step.perturbation || step.placeholder) continue;
    if (step.nlgeom_loc.valid()) {
      sink.report(DiagCode::conflicting_parameters, step.nlgeom_loc,
                  "NLGEOM cannot be given on a perturbation step: its response is linear about "
                  "the base state, whose geometric nonlinearity the general steps before it set")
          .notes.push_back({step.perturbation_loc, "PERTURBATION given here"});
    }
    if (step.dynamic) {
      sink.report(DiagCode::unsupported_option, step.dynamic->loc,
                  "*DYNAMIC cannot be a perturbation step (expected *STATIC or *FREQUENCY after "
                  "*STEP, PERTURBATION; a transient response is a general step)")
          .notes.push_back({step.perturbation_loc, "PERTURBATION given here"});
    } else if (step.procedure && step.procedure->riks) {
      sink.report(DiagCode::unsupported_option, step.procedure->loc,
                  "*STATIC, RIKS cannot be a perturbation step (expected *STATIC without RIKS)")
          .notes.push_back({step.perturbation_loc, "PERTURBATION given here"});
    } else if (step.procedure && step.procedure->stabilize) {
      sink.report(DiagCode::unsupported_option, step.procedure->stabilize->loc,
                  "STABILIZE cannot be used in a perturbation step: its response is one linear "
                  "solve about the base state, with no increments for viscous forces to act over")
          .notes.push_back({step.perturbation_loc, "PERTURBATION given here"});
    }
    if (step.amplitude_given) {
      sink.report(DiagCode::parameter_ignored, step.loc,
                  "AMPLITUDE on a perturbation step has no effect: its loads and prescribed "
                  "values are applied at their full magnitude");
    }
    for (const ConditionBlock& block : step.blocks) {
      if (block.amplitude.empty()) continue;
      sink.report(DiagCode::parameter_ignored, block.amplitude.loc,
                  fmt::format("AMPLITUDE on {} in a perturbation step has no effect: the "
                              "perturbation is applied at its full magnitude",
                              condition_keyword(block.kind)));
    }
  }
}

}  // namespace clinch
