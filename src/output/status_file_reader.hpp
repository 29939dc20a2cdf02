// Reading a status file `<job>.sta` back (cli-contract.md): the increment attempts and the line
// that says how the run ended, for `clinch study` (increments, iterations, cutbacks of each run)
// and `clinch report` (cutbacks marked on the plots).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "src/output/status_file.hpp"

namespace clinch {

struct StatusRecord {
  std::vector<IncrementAttempt> attempts;
  std::map<int, std::string> step_names;  // from the `STEP <n>: <name>` lines
  std::string ending;  // "COMPLETED", "FAILED: ..." or "" when the run ended without one

  int converged_increments() const;
  int cutbacks() const;
  int total_iterations() const;  // over every attempt, cut back or not
};

// Returns nullopt and sets `error` ("PATH:LINE: message") when the file cannot be read or a line
// is not an attempt line of the contract's layout.
std::optional<StatusRecord> read_status_file(const std::string& path, std::string* error);

}  // namespace clinch
