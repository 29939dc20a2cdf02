#include "src/output/status_file.hpp"

#include <fmt/format.h>

namespace clinch {
namespace {

// Column layout shared by the header and the attempt lines. Times use 7 significant digits: the
// status file is for reading progress; the history table carries the exact values.
constexpr std::string_view kHeaderFormat =
    "{:>5} {:>5} {:>4} {:>4} {:>6} {:>6} {:>15} {:>15} {:>15}";
constexpr std::string_view kLineFormat =
    "{:>5} {:>5} {:>4} {:>4} {:>6} {:>6} {:>15.7g} {:>15.7g} {:>15.7g}";

}  // namespace

bool StatusFile::open(const std::filesystem::path& path, std::string* error) {
  if (!file_.open(path, error)) return false;
  if (!write_line(fmt::format(kHeaderFormat, "step", "inc", "att", "cut", "equil", "total",
                              "total time", "step time", "time inc"))) {
    *error = file_.error();
    return false;
  }
  return true;
}

bool StatusFile::write_attempt(const IncrementAttempt& a) {
  return write_line(fmt::format(kLineFormat, a.step, a.increment, a.attempt, a.cut_back ? "U" : "",
                         a.equilibrium_iterations, a.total_iterations, a.total_time, a.step_time,
                         a.time_increment));
}

bool StatusFile::write_step(int step, std::string_view name) {
  return write_line(fmt::format("STEP {}: {}", step, name));
}

bool StatusFile::write_step_end(int step, std::string_view why) {
  return write_line(fmt::format("STEP {} ENDED: {}", step, why));
}

bool StatusFile::write_completed() { return write_line("COMPLETED"); }

bool StatusFile::write_failed(std::string_view reason, int step, int increment, double total_time) {
  return write_line(fmt::format("FAILED: {} (step {}, increment {}, time {})", reason, step,
                                increment, total_time));
}

bool StatusFile::write_line(std::string_view line) {
  line_.assign(line);
  line_ += '\n';
  return file_.write(line_);
}

}  // namespace clinch
