// Runs the settings of an increment-size study as `clinch run` child processes, several at once
// where cores allow, coarsest first. Separate processes keep each run exactly what the user would
// get from `clinch run` on the scaled deck, and a run that fails or crashes cannot take the study
// down with it. With a time budget, a finer setting is started only when the cost observed so far
// (each setting about `cost_ratio` times the previous one) says it can end within the budget.
// A child never outlives the study: it is sent SIGTERM when the study ends, however it ends.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace clinch {

struct LadderSetting {
  double scale = 1.0;
  std::string deck;     // the scaled deck
  std::string out_dir;  // where its run writes (created)
  std::string job;
};

enum class SettingState { NotRun, Running, Completed, Failed };

struct SettingOutcome {
  SettingState state = SettingState::NotRun;
  int exit_code = -1;
  double wall_seconds = 0.0;  // from the start of the child process to its end
  std::string note;           // why it was not run, or how the process ended abnormally
};

struct LadderOptions {
  std::string clinch;  // the executable to run
  int jobs = 1;
  std::optional<double> budget_seconds;
  double cost_ratio = 2.0;
  // Called a few times a second while runs go on, and once when each ends.
  std::function<void(const std::vector<SettingOutcome>&)> on_progress;
  // Asked as often: the number of a signal that stops the study, 0 while none. Once it is not 0,
  // the signal is sent to every running child, which stops as `clinch run` does on it, no
  // setting is started any more, and run_ladder returns when the children have ended.
  std::function<int()> stop_signal;
};

std::vector<SettingOutcome> run_ladder(const std::vector<LadderSetting>& settings,
                                       const LadderOptions& options);

// The path of the running executable, for starting clinch again.
std::string current_executable();

}  // namespace clinch
