// The lumped mass of a *FREQUENCY step over the solved equations (docs/dynamics.md "Natural
// frequencies"): the nodal inertia (nodal_inertia.hpp) of the DOFs that are free under the
// current conditions, as upper-triangle entries and as a factor F with M = F Fᵀ
// (frequency_eigensolver.hpp). Each node's 3 × 3 block (its masses, its rotary inertia tensor)
// gives one column of F per direction that carries inertia, √d q for each eigenpair (d, q) of the
// block, so that a tensor with a zero principal inertia gives no column in that direction.
#pragma once

#include "src/assembly/connector_system.hpp"
#include "src/solver/step_problem.hpp"

namespace clinch {

FrequencyModel frequency_model(const Model& model, const ConnectorSystem& system);

}  // namespace clinch
