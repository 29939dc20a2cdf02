// The stop and lock active sets (behaviors.md §5), updated between Newton solves from what the
// last evaluation computed (the state's results): stops are activated when violated and released
// when their force has the wrong sign; locks engage on a converged state.
#pragma once

#include "src/assembly/analysis_state.hpp"
#include "src/assembly/increment_conditions.hpp"

namespace clinch {

// §5.1. Returns true when some stop changed (the increment then iterates on).
bool update_stops(const AnalysisPlan& plan, const IncrementConditions& conditions,
                  AnalysisState& state);

// §5.2. Call after commit: a lock engages at the converged state.
void engage_locks(const AnalysisPlan& plan, AnalysisState& state);

}  // namespace clinch
