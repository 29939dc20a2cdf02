// Why an attempt failed, in the terms of the deck (ARCHITECTURE.md principle 8): the DOF or the
// multiplier behind the equation of a zero pivot or of a value that is not finite, and whether
// restraining it would help.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "src/assembly/analysis_plan.hpp"
#include "src/model/model.hpp"
#include "src/solver/newton.hpp"

namespace clinch {

// Why an attempt failed at an equation: a zero pivot, or a value that is not finite. A DOF with
// no stiffness gets the hint to restrain it only when nothing does (connection-types.md §1.1):
// no *BOUNDARY names it and no element gives it stiffness in its initial pose. Otherwise the
// stiffness was lost on the way (a yielded, damaged or flat law past the load it can carry), or
// the DOF moves in a mechanism, and a restraint of that DOF is not the fix.
// Under a distributed model a rank's plan holds only its share of the connectors:
// `every_rank` joins the lines each rank found about its own, in rank order
// (ConnectorSystem::lines_of_every_rank), so that every rank gives the same description.
using LinesOfEveryRank = std::function<std::vector<std::string>(std::vector<std::string>)>;
std::string describe_failure(const Model& model, const AnalysisPlan& plan,
                             const NewtonReport& report, const LinesOfEveryRank& every_rank = {});

}  // namespace clinch
