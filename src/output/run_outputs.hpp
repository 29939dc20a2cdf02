// The outputs of a run as observers of its increments: the history rows, the status file, the
// log and the progress line. The step driver tells them what happened; they know in which order to
// write it: a converged increment's row reaches the disk before its status line, so that a killed
// run's status file is never ahead of its history, and completion is claimed only once every
// output is whole and on the disk (cli-contract.md).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "src/output/history_recorder.hpp"
#include "src/output/modes_file.hpp"
#include "src/output/progress.hpp"
#include "src/output/run_log.hpp"
#include "src/output/status_file.hpp"

namespace clinch {

class RunOutputs {
 public:
  RunOutputs(HistoryRecorder& history, StatusFile& status, RunLog& log, Progress& progress)
      : history_(history), status_(status), log_(log), progress_(progress) {}

  // The steps' names (NAME= or Step-<n>), in deck order: the .sta, the log and the progress line
  // name each step with them.
  void set_step_names(std::vector<std::string> names) { step_names_ = std::move(names); }

  // Step `step` (0-based) begins: its requests become current, its name goes to the .sta and log.
  void begin_step(std::size_t step);
  // Row 0: the initial state, before any condition applies (output-variables.md §1.4).
  void initial_state() { history_.converged(1, 0, 0.0, 0.0, false); }
  // An attempt that failed, that a law abandoned, or that is solved again: its status line.
  void attempt_ended(const IncrementAttempt& attempt) { status_.write_attempt(attempt); }
  // A converged increment: its row (if due), then its status line, then the progress line.
  void increment_converged(const IncrementAttempt& attempt, bool last_of_step);
  // The history and the status file, COMPLETED line included, on the disk; false when some output
  // could not be written.
  bool completed();
  // The FAILED line, and the log's line with where the run was (`at_start`: before any increment,
  // where the reason says it all).
  void stopped(const std::string& reason, int step, int increment, double time, bool at_start);
  // Log lines (run_log.hpp): Newton's iterations, a note on step `step` (or on its increment
  // `increment` when > 0), a note that stands alone, a warning, and a cutback with its reason.
  void iteration(const IterationRecord& record) { log_.iteration(record); }
  void note(int step, int increment, std::string_view text);
  // Why a step ended, when its procedure decided it (a Riks step): the .sta and the log.
  void step_ended(int step, std::string_view why);
  void note(std::string_view text) { log_.info(text); }
  void warning(std::string_view text) { log_.warning(text); }
  void cut_back(int step, int increment, std::string_view reason, double dt);
  // A linear perturbation step's row (docs/perturbation.md), from the states `at(+h)` and
  // `at(−h)` along its response, at the total time of its base state; false when `at` failed.
  bool perturbation_response(int step, double total_time, double h,
                             const std::function<bool(double)>& at) {
    return history_.perturbation(step, total_time, h, at);
  }
  // The modes file of the frequency steps (none: their modes go to the log only).
  void set_modes_file(ModesFile* modes) { modes_ = modes; }
  // A frequency step's modes: the eigenvalue table in the log, then the rows of the modes file.
  // The modes file's error when it could not be written; empty otherwise.
  std::string modes_extracted(int step, const std::vector<ModeRecord>& modes,
                              const std::vector<std::string>& dof_names);
  // The first output that could not be written, or null.
  const OutputFile* failed_file() const;

 private:
  HistoryRecorder& history_;
  StatusFile& status_;
  RunLog& log_;
  Progress& progress_;
  std::vector<std::string> step_names_;
  ModesFile* modes_ = nullptr;
};

}  // namespace clinch
