// What a *FREQUENCY step cannot run yet (docs/dynamics.md "Natural frequencies"), refused at the
// keyword that asks for it so that `clinch check` never passes a deck that `clinch run` would
// solve wrongly: loads and connector conditions given inside the step (its *BOUNDARY holds DOFs
// for this step only, docs/perturbation.md; loads do not enter an eigenproblem). The mass of
// constrained nodes follows the constraints (frequency_mass.hpp); what a rigid body's elements
// would weigh is refused with the dynamic checks (dynamic_step_checks.cpp).
#include <fmt/format.h>

#include "base/diagnostic.hpp"
#include "src/check/check.hpp"
#include "src/model/model.hpp"

namespace clinch {

void check_frequency_steps(const Model& model, DiagnosticSink& sink) {
  for (const Step& step : model.history.steps) {
    if (!step.frequency) continue;
    for (const ConditionBlock& block : step.blocks) {
      if (block.kind == ConditionKind::Boundary) continue;
      sink.report(DiagCode::unsupported_option, block.loc,
                  fmt::format("{} in a *FREQUENCY step is not supported by clinch: the step "
                              "takes *BOUNDARY only (give loads and connector conditions in a "
                              "*STATIC or *DYNAMIC step before it)",
                              condition_keyword(block.kind)));
    }
  }
}

}  // namespace clinch
