#include "src/resolve/resolve.hpp"

namespace clinch {

void resolve_model(Model& model, DiagnosticSink& sink) {
  resolve_geometry(model, sink);
  resolve_sections(model, sink);
  resolve_structure(model, sink);
  resolve_rigid_bodies(model, sink);
  resolve_mpc_equations(model, sink);
  resolve_rigid_body_element_masses(model);
  resolve_potentials_and_friction(model, sink);
  resolve_history(model, sink);
}

}  // namespace clinch
