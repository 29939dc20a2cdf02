#include "src/check/validate.hpp"

#include "base/diagnostic.hpp"
#include "src/model/model.hpp"

namespace clinch {

void validate_model(Model& model, DiagnosticSink& sink) {
  finalize_geometry(model, sink);
  validate_sections(model, sink);
  validate_behaviors(model, sink);
  validate_potentials_and_friction(model, sink);
  validate_history(model, sink);
}

}  // namespace clinch
