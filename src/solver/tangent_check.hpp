// `clinch run --check-tangent` (ARCHITECTURE.md testing habit 2): at the first iterate of an
// increment, compares the assembled tangent with central finite differences of the residual and
// reports the worst entries, so an analyst can see whether slow convergence comes from the
// tangent.
#pragma once

#include <string>

#include "src/assembly/connector_system.hpp"

namespace clinch {

// The report (several lines); the state of `system` is unchanged afterwards.
std::string check_tangent(ConnectorSystem& system, int step, int increment);

}  // namespace clinch
