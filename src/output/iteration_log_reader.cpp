#include "src/output/iteration_log_reader.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <fstream>

namespace clinch {

std::optional<std::vector<IterationRecord>> read_iteration_log(const std::string& path,
                                                               std::string* error) {
  std::ifstream in(path);
  if (!in) {
    *error = fmt::format("{}: cannot open the log", path);
    return std::nullopt;
  }
  std::vector<IterationRecord> records;
  std::string line;
  while (std::getline(in, line)) {
    IterationRecord r;
    int consumed = 0;
    if (std::sscanf(line.c_str(), "step %d increment %d attempt %d iteration %d: residual %lg%n",
                    &r.step, &r.increment, &r.attempt, &r.iteration, &r.residual_norm,
                    &consumed) != 5) {
      continue;
    }
    // The correction and the constraint violation follow the residual's "(largest ... at
    // LOCATION)" part; they are found from the end of the line, which clinch writes, so that a
    // location with parentheses (an instance-qualified label) cannot be mistaken for them.
    const std::size_t violation = line.rfind("), constraint violation ");
    if (violation == std::string::npos || violation < static_cast<std::size_t>(consumed)) continue;
    const std::size_t correction = line.rfind("), correction ", violation);
    if (correction == std::string::npos || correction < static_cast<std::size_t>(consumed))
      continue;
    std::sscanf(line.c_str() + correction + 14, "%lg", &r.correction_norm);
    std::sscanf(line.c_str() + violation + 24, "%lg", &r.constraint_violation);
    records.push_back(r);
  }
  return records;
}

}  // namespace clinch
