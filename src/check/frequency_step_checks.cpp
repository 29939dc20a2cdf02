// What a *FREQUENCY step cannot run yet (docs/dynamics.md "Natural frequencies"), refused at the
// keyword that asks for it so that `clinch check` never passes a deck that `clinch run` would
// solve wrongly: loads and connector conditions given inside the step (its *BOUNDARY holds DOFs
// for this step only, docs/perturbation.md; loads do not enter an eigenproblem) and kinematic
// constraints (the mass of a constrained node would have to follow the constraint).
#include <fmt/format.h>

#include "base/diagnostic.hpp"
#include "src/check/check.hpp"
#include "src/model/model.hpp"

namespace clinch {

void check_frequency_steps(const Model& model, DiagnosticSink& sink) {
  bool constraint_reported = false;
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
    const ConstraintSource* constraint = first_kinematic_constraint(model);
    if (constraint == nullptr || constraint_reported) continue;
    constraint_reported = true;
    Diagnostic& d = sink.report(
        DiagCode::unsupported_option, step.frequency->loc,
        "*FREQUENCY with kinematic constraints (*RIGID BODY, *COUPLING, *MPC, *EQUATION) is not "
        "supported by clinch yet: the mass of constrained nodes would have to follow the "
        "constraints");
    if (constraint->loc.valid()) {
      d.notes.push_back({constraint->loc, fmt::format("{} is here", constraint->keyword)});
    }
  }
}

}  // namespace clinch
