// A connector potential (derived-components-and-potentials.md §2) evaluated on arguments that
// carry their gradient against the trial motion (trial_sensitive.hpp): P(x) and
// ∂P/∂u = Σ_j ∂P/∂x_j ∂x_j/∂u, for the coupled damage criteria and evolution measures.
#pragma once

#include <array>

#include "src/behavior/damage/trial_sensitive.hpp"
#include "src/behavior/potential/connector_potential.hpp"

namespace clinch {

using SensitiveVector = std::array<TrialSensitive, 6>;

TrialSensitive evaluate_potential(const ConnectorPotential& potential, const SensitiveVector& x);

// The constants x (no gradient), and x_j = u_j (the trial motion itself).
SensitiveVector constant_vector(const Vector6& x);
SensitiveVector motion_vector(const Vector6& u);

}  // namespace clinch
