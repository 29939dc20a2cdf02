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
    // The correction and the constraint violation follow the residual's "(largest ...)" part,
    // whose location text may hold any characters.
    const std::size_t correction = line.find("), correction ", consumed);
    const std::size_t violation = line.find("), constraint violation ", consumed);
    if (correction == std::string::npos || violation == std::string::npos) continue;
    std::sscanf(line.c_str() + correction + 14, "%lg", &r.correction_norm);
    std::sscanf(line.c_str() + violation + 24, "%lg", &r.constraint_violation);
    records.push_back(r);
  }
  return records;
}

}  // namespace clinch
