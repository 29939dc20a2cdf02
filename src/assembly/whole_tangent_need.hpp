// Whether a distributed run can assemble its tangent by rows (docs/parallel.md "Assembly by
// rows"), each rank holding only its part, or needs the whole tangent on every rank.
#pragma once

#include <string>

#include "src/model/model.hpp"

namespace clinch {

// What in the model needs the whole tangent on every rank, for the run log; empty when nothing
// does: a Riks step (its
// bordered matrix), a *FREQUENCY or perturbation step (the shifted matrix and the one-off solve
// read the whole tangent), a damage law (the path followed inside an increment may solve its
// bordered matrix whole, docs/riks.md).
std::string whole_tangent_need(const Model& model);

}  // namespace clinch
