#include "src/check/check.hpp"

namespace clinch {

void check_model(const Model& model, DiagnosticSink& sink) {
  check_behaviors(model, sink);
  check_motion_stops(model, sink);
  check_held_elements(model, sink);
  check_constraints(model, sink);
  check_dynamic_steps(model, sink);
  check_frequency_steps(model, sink);
  check_perturbation_steps(model, sink);
  check_output_intervals(model, sink);
}

}  // namespace clinch
