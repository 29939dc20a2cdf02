// History output by step time in a step that has no time of its own (docs/cli-contract.md, "The
// history table"): a Riks step advances by arc length, so the TIME INTERVAL and NUMBER INTERVAL
// of the requests in force there cannot place rows; they write one at every increment, with a
// warning at the request, once per Riks step.
#include <fmt/format.h>

#include "base/diagnostic.hpp"
#include "src/check/check.hpp"
#include "src/model/model.hpp"

namespace clinch {

void check_output_intervals(const Model& model, DiagnosticSink& sink) {
  const std::vector<std::vector<const OutputRequest*>> in_force =
      history_requests_in_force(model.history);
  for (std::size_t s = 0; s < model.history.steps.size(); ++s) {
    const Step& step = model.history.steps[s];
    if (!step.procedure || !step.procedure->riks) continue;
    for (const OutputRequest* r : in_force[s]) {
      if (!r->time_interval && !r->number_interval) continue;
      sink.report(DiagCode::parameter_ignored, r->loc,
                  fmt::format("{} has no effect in the Riks step '{}': it advances by arc length, "
                              "not time, so this request writes a row at every increment there",
                              r->time_interval ? "TIME INTERVAL" : "NUMBER INTERVAL",
                              step.name.display));
    }
  }
}

}  // namespace clinch
