#include "src/output/run_outputs.hpp"

#include <fmt/format.h>

#include <numbers>

namespace clinch {

void RunOutputs::begin_step(std::size_t step) {
  history_.begin_step(step);
  if (step >= step_names_.size()) return;
  const int number = static_cast<int>(step) + 1;
  status_.write_step(number, step_names_[step]);
  progress_.clear();
  log_.info(fmt::format("step {}: {}", number, step_names_[step]));
}

void RunOutputs::increment_converged(const IncrementAttempt& attempt, bool last_of_step) {
  history_.converged(attempt.step, attempt.increment, attempt.step_time, attempt.total_time,
                     last_of_step);
  if (failed_file() != nullptr) return;
  status_.write_attempt(attempt);
  if (failed_file() != nullptr) return;
  const auto step = static_cast<std::size_t>(attempt.step - 1);
  progress_.update(attempt.step, attempt.increment, attempt.total_time,
                   step < step_names_.size() ? std::string_view(step_names_[step]) : "");
}

bool RunOutputs::completed() {
  history_.sync();
  if (failed_file() != nullptr) return false;
  status_.write_completed();
  status_.sync();
  return failed_file() == nullptr;
}

void RunOutputs::stopped(const std::string& reason, int step, int increment, double time,
                         bool at_start) {
  status_.write_failed(reason, step, increment, time);
  log_.error(at_start ? fmt::format("analysis stopped: {}", reason)
                      : fmt::format("analysis stopped: {} (step {}, increment {}, time {})", reason,
                                    step, increment, time));
}

const OutputFile* RunOutputs::failed_file() const {
  for (const OutputFile* file : {&history_.file(), &status_.file(), &log_.file()}) {
    if (file->failed()) return file;
  }
  return nullptr;
}

void RunOutputs::note(int step, int increment, std::string_view text) {
  log_.info(increment > 0 ? fmt::format("step {} increment {}: {}", step, increment, text)
                          : fmt::format("step {}: {}", step, text));
}

// The eigenvalue table as Abaqus prints it in the .dat file (docs/dynamics.md "Natural
// frequencies").
std::string RunOutputs::modes_extracted(int step, const std::vector<ModeRecord>& modes,
                                        const std::vector<std::string>& dof_names) {
  note(step, 0, "eigenvalue output");
  log_.info(" MODE NO      EIGENVALUE       FREQUENCY (RAD/TIME)  FREQUENCY (CYCLES/TIME)  "
            "GENERALIZED MASS");
  for (const ModeRecord& m : modes) {
    const double omega = circular_frequency(m.eigenvalue);
    log_.info(fmt::format("{:8d}  {:16.6E}  {:20.6E}  {:23.6E}  {:16.6E}", m.mode, m.eigenvalue,
                          omega, omega / (2.0 * std::numbers::pi), m.generalized_mass));
  }
  if (modes_ == nullptr || modes_->write_step(step, modes, dof_names)) return {};
  return modes_->error();
}

void RunOutputs::step_ended(int step, std::string_view why) {
  status_.write_step_end(step, why);
  log_.info(fmt::format("step {} ended: {}", step, why));
}

void RunOutputs::cut_back(int step, int increment, std::string_view reason, double dt) {
  log_.warning(
      fmt::format("step {} increment {}: {}; cutting back to {}", step, increment, reason, dt));
}

}  // namespace clinch
