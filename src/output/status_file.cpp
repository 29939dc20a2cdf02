#include "src/output/status_file.hpp"

#include <cerrno>
#include <cstring>

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
  out_.open(path, std::ios::out | std::ios::trunc | std::ios::binary);
  if (out_) {
    write_line(fmt::format(kHeaderFormat, "step", "inc", "att", "cut", "equil", "total",
                           "total time", "step time", "time inc"));
  }
  if (!out_) {
    *error = fmt::format("cannot write '{}': {}", path.string(), std::strerror(errno));
    return false;
  }
  return true;
}

void StatusFile::write_attempt(const IncrementAttempt& a) {
  write_line(fmt::format(kLineFormat, a.step, a.increment, a.attempt, a.cut_back ? "U" : "",
                         a.equilibrium_iterations, a.total_iterations, a.total_time, a.step_time,
                         a.time_increment));
}

void StatusFile::write_completed() { write_line("COMPLETED"); }

void StatusFile::write_failed(std::string_view reason, int step, int increment, double total_time) {
  write_line(fmt::format("FAILED: {} (step {}, increment {}, time {})", reason, step, increment,
                         total_time));
}

void StatusFile::write_line(std::string_view line) { out_ << line << '\n' << std::flush; }

}  // namespace clinch
