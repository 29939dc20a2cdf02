// The constraints whose map is linearised (a distributing coupling, CalculiX's ROT NODE:
// LinearConstraint::exact_under_nlgeom false, src/model/constraint_model.hpp) hold in small
// displacements only: a deck with a step under NLGEOM refuses them, once per definition, at its
// keyword line (docs/constraints.md).
#include <fmt/format.h>

#include <vector>

#include "base/diagnostic.hpp"
#include "src/check/check.hpp"
#include "src/model/model.hpp"

namespace clinch {

void check_linearised_constraints(const Model& model, DiagnosticSink& sink) {
  const Step* nlgeom_step = nullptr;
  for (const Step& step : model.history.steps) {
    if (step.nlgeom) {
      nlgeom_step = &step;
      break;
    }
  }
  if (!nlgeom_step) return;
  const ConstraintModel& constraints = model.constraints;
  std::vector<bool> reported(constraints.sources.size(), false);
  for (const LinearConstraint& equation : constraints.equations) {
    if (equation.exact_under_nlgeom || equation.source < 0) continue;
    const auto source = static_cast<std::size_t>(equation.source);
    if (source >= reported.size() || reported[source]) continue;
    reported[source] = true;
    const ConstraintSource& where = constraints.sources[source];
    sink.report(DiagCode::unsupported_option, where.loc,
                fmt::format("{} is a linear map that holds in small displacements only, and "
                            "step '{}' has NLGEOM; clinch does not run it with finite rotations",
                            where.keyword, nlgeom_step->name.display))
        .notes.push_back({nlgeom_step->loc, "NLGEOM is set here"});
  }
}

}  // namespace clinch
