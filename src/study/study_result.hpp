// What `clinch study` found: each setting of the ladder (its scale, how its run went, what its
// status file says) and the error estimates over the completed ones; and the choice `--rtol`
// asks for.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "src/output/status_file_reader.hpp"
#include "src/study/convergence_estimate.hpp"
#include "src/study/ladder_runner.hpp"

namespace clinch {

struct StudySetting {
  double scale = 1.0;
  std::string deck;  // the scaled deck
  SettingOutcome outcome;
  std::optional<StatusRecord> status;  // when the run wrote a readable status file
  std::string history;                 // its history table
  int run = -1;  // index of this setting among the completed runs of the estimate, -1 if none
};

struct StudyResult {
  std::vector<StudySetting> settings;
  std::optional<StudyEstimate> estimate;  // when at least one setting completed
  std::optional<double> rtol;
  std::optional<std::size_t> chosen;  // the setting --rtol names
};

// The work of a run, the same on any machine: one residual assembly per increment attempt
// (prescribed motions alone need no Newton iteration) plus one per Newton iteration.
int setting_work(const StatusRecord& status);

// The cheapest completed setting whose estimated error (worst column) is below `rtol`: the least
// work, then the shortest wall time. Work comes first because the wall time of runs made side by
// side depends on what else the cores were doing.
std::optional<std::size_t> cheapest_setting(const StudyResult& result, double rtol);

// "1", "1/4", "0.3" for a scale.
std::string scale_text(double scale);

}  // namespace clinch
