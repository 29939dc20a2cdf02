#include "src/output/status_file_reader.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

namespace clinch {

int StatusRecord::converged_increments() const {
  int n = 0;
  for (const IncrementAttempt& a : attempts) n += a.cut_back ? 0 : 1;
  return n;
}

int StatusRecord::cutbacks() const {
  return static_cast<int>(attempts.size()) - converged_increments();
}

int StatusRecord::total_iterations() const {
  int n = 0;
  for (const IncrementAttempt& a : attempts) n += a.total_iterations;
  return n;
}

std::optional<StatusRecord> read_status_file(const std::string& path, std::string* error) {
  std::ifstream in(path);
  if (!in) {
    *error = fmt::format("{}: cannot open the status file", path);
    return std::nullopt;
  }
  StatusRecord record;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (number == 1) continue;  // header
    if (line.rfind("STEP ", 0) == 0) {
      const std::size_t colon = line.find(": ");
      try {
        if (colon == std::string::npos) throw std::invalid_argument("no name");
        record.step_names[std::stoi(line.substr(5, colon - 5))] = line.substr(colon + 2);
      } catch (const std::exception&) {
        *error = fmt::format("{}:{}: not a step line: '{}'", path, number, line);
        return std::nullopt;
      }
      continue;
    }
    if (line.rfind("COMPLETED", 0) == 0 || line.rfind("FAILED", 0) == 0) {
      record.ending = line;
      continue;
    }
    // step inc att [U] equil total total_time step_time time_inc; the cutback flag is blank
    // when the attempt converged.
    std::istringstream fields(line);
    std::vector<std::string> f;
    for (std::string x; fields >> x;) f.push_back(x);
    if (f.empty()) continue;
    const bool cut = f.size() == 9;
    if (f.size() != 8 && !(cut && f[3] == "U")) {
      *error = fmt::format("{}:{}: not a status line: '{}'", path, number, line);
      return std::nullopt;
    }
    try {
      IncrementAttempt a;
      std::size_t i = 0;
      a.step = std::stoi(f[i++]);
      a.increment = std::stoi(f[i++]);
      a.attempt = std::stoi(f[i++]);
      a.cut_back = cut;
      if (cut) ++i;
      a.equilibrium_iterations = std::stoi(f[i++]);
      a.total_iterations = std::stoi(f[i++]);
      a.total_time = std::stod(f[i++]);
      a.step_time = std::stod(f[i++]);
      a.time_increment = std::stod(f[i++]);
      record.attempts.push_back(a);
    } catch (const std::exception&) {
      *error = fmt::format("{}:{}: not a status line: '{}'", path, number, line);
      return std::nullopt;
    }
  }
  return record;
}

}  // namespace clinch
