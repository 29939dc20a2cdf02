// Output requests resolved by resolve_history (keywords.md §17–§18, output-variables.md §1.2):
// sets resolved and stored in the requests, components against the connection type (E0902),
// variables the behaviour cannot produce (W0901), derived-component names (E0506,
// cder-no-context) and duplicate columns (W0903), by expanding every request of a step into its
// history columns.
#pragma once

#include <vector>

#include "src/model/active_dofs.hpp"

namespace clinch {

class DiagnosticSink;
struct Model;

void resolve_output_requests(Model& model, const std::vector<DofMask>& active,
                             DiagnosticSink& sink);

}  // namespace clinch
