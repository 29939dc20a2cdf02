// `clinch run --check-tangent` (ARCHITECTURE.md testing habit 2): at the first iterate of an
// increment, compares the whole assembled tangent of the connector system with central finite
// differences of its residual and reports the worst entries, so an analyst can see whether slow
// convergence comes from the tangent.
#pragma once

#include <string>

#include "src/assembly/connector_system.hpp"

namespace clinch {

// The report (several lines); the state of `system` is restored exactly afterwards (conditions,
// prescribed predictor and results included), so a checked run gives the same history as an
// unchecked one. The whole matrix is compared, prescribed DOFs included (it is checked without the
// increment's conditions), read through the storage of its pattern (full or symmetric upper).
std::string check_tangent(ConnectorSystem& system, int step, int increment);

}  // namespace clinch
