// The status file `<job>.sta` (cli-contract.md): one fixed-width line per increment attempt as the
// step driver makes it, flushed at once, and a last line that says how the run ended.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "src/output/output_file.hpp"

namespace clinch {

// One increment attempt, as the step driver reports it.
struct IncrementAttempt {
  int step = 0;
  int increment = 0;
  int attempt = 0;        // 1 for the first try of an increment, 2.. after cutbacks
  bool cut_back = false;  // this attempt failed and the increment was cut back
  int equilibrium_iterations = 0;
  int total_iterations = 0;  // equilibrium iterations plus those spent on status changes
  double total_time = 0.0;
  double step_time = 0.0;
  double time_increment = 0.0;
};

class StatusFile {
 public:
  // Creates (truncates) `path` and writes the header. On failure returns false and sets `error`.
  bool open(const std::filesystem::path& path, std::string* error);

  // Each returns false when the line could not be written whole; file().error() says why.
  bool write_attempt(const IncrementAttempt& attempt);
  // `STEP <n>: <name>` before the first attempt of step n (docs/study-and-report.md, "Step
  // names"): not an attempt line, so readers that take lines of numbers pass over it.
  bool write_step(int step, std::string_view name);
  // `STEP <n> ENDED: <why>` after the last attempt of a step whose procedure ended it (a Riks
  // step's stopping criterion); not an attempt line either.
  bool write_step_end(int step, std::string_view why);
  bool write_completed();
  // `FAILED: <reason> (step S, increment I, time T)`.
  bool write_failed(std::string_view reason, int step, int increment, double total_time);

  bool is_open() const { return file_.is_open(); }
  // The file underneath, which keeps the first write failure.
  const OutputFile& file() const { return file_; }
  bool sync() { return file_.sync(); }

 private:
  bool write_line(std::string_view line);

  OutputFile file_;
  std::string line_;  // reused line buffer
};

}  // namespace clinch
