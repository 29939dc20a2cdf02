// Reading the Newton iteration lines of a run log `<job>.log` back (RunLog::iteration writes
// them), for the convergence plots of `clinch report`. Other log lines are skipped.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "src/output/run_log.hpp"

namespace clinch {

// Returns nullopt and sets `error` when the file cannot be read.
std::optional<std::vector<IterationRecord>> read_iteration_log(const std::string& path,
                                                               std::string* error);

}  // namespace clinch
