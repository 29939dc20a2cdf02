#include "src/model/history_model.hpp"

#include <algorithm>

namespace clinch {

const char* condition_keyword(ConditionKind kind) {
  switch (kind) {
    case ConditionKind::Boundary:
      return "*BOUNDARY";
    case ConditionKind::Motion:
      return "*CONNECTOR MOTION";
    case ConditionKind::Load:
      return "*CLOAD";
    case ConditionKind::ConnectorLoad:
      return "*CONNECTOR LOAD";
    case ConditionKind::Gravity:
      return "*DLOAD";
  }
  return "";
}

bool Step::replaces(ConditionKind kind) const {
  for (const ConditionBlock& block : blocks) {
    if (block.kind == kind && block.op_new) return true;
  }
  return false;
}

std::vector<std::vector<const OutputRequest*>> history_requests_in_force(
    const HistoryModel& history) {
  std::vector<std::vector<const OutputRequest*>> in_force;
  std::vector<const OutputRequest*> outputs;
  for (const Step& step : history.steps) {
    for (const OutputRequest& r : step.outputs) {
      if (r.field) continue;
      if (r.op == OutputRequest::Op::New) outputs.clear();
      if (r.op == OutputRequest::Op::Replace) {
        std::erase_if(outputs, [&](const OutputRequest* o) { return o->name.key == r.name.key; });
      }
      outputs.push_back(&r);
    }
    in_force.push_back(outputs);
  }
  return in_force;
}

std::optional<double> output_time_interval(const OutputRequest& request, const Step& step) {
  if (!step.procedure || step.procedure->riks || step.frequency) return std::nullopt;
  if (request.time_interval) return request.time_interval;
  if (request.number_interval) return step.procedure->period / *request.number_interval;
  return std::nullopt;
}

std::vector<double> output_time_intervals(const HistoryModel& history, std::size_t s) {
  std::vector<double> intervals;
  const std::vector<std::vector<const OutputRequest*>> in_force = history_requests_in_force(history);
  for (const OutputRequest* r : in_force[s]) {
    if (auto interval = output_time_interval(*r, history.steps[s])) intervals.push_back(*interval);
  }
  std::sort(intervals.begin(), intervals.end());
  intervals.erase(std::unique(intervals.begin(), intervals.end()), intervals.end());
  return intervals;
}

}  // namespace clinch
