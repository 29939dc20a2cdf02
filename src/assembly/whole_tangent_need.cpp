#include "src/assembly/whole_tangent_need.hpp"

#include <algorithm>

namespace clinch {

std::string whole_tangent_need(const Model& model) {
  for (const Step& step : model.history.steps) {
    if (step.procedure && step.procedure->riks) return "a Riks step solves its bordered matrix";
    if (step.is_perturbation()) {
      return "a *FREQUENCY or perturbation step reads the whole tangent";
    }
  }
  const auto& behaviors = model.behaviors.behaviors;
  if (std::any_of(behaviors.begin(), behaviors.end(),
                  [](const ConnectorBehavior& b) { return !b.damage_initiations.empty(); })) {
    return "a damage law: the path followed inside an increment may solve its bordered matrix "
           "whole";
  }
  return {};
}

}  // namespace clinch
