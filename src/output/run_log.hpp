// The run log `<job>.log` (cli-contract.md): every message that was printed, with warnings, and
// one line per Newton iteration with the residual and correction norms. Messages are echoed to
// the chosen streams so that the log holds exactly what the user saw.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <string_view>

#include "src/output/output_file.hpp"

namespace clinch {

// One Newton iteration, as the log records it.
struct IterationRecord {
  int step = 0;
  int increment = 0;
  int attempt = 0;
  int iteration = 0;
  double residual_norm = 0.0;
  double largest_residual = 0.0;
  std::string largest_residual_at;  // e.g. "node 5 dof 2"; may be empty
  double correction_norm = 0.0;
  double largest_correction = 0.0;
  std::string largest_correction_at;
  double constraint_violation = 0.0;
};

class RunLog {
 public:
  // Messages are echoed to `info_echo` (info) and `warning_echo` (warnings, errors); a null
  // stream means that kind is not printed, only logged.
  explicit RunLog(std::ostream* info_echo = nullptr, std::ostream* warning_echo = nullptr)
      : info_echo_(info_echo), warning_echo_(warning_echo) {}

  // Creates (truncates) `path`. On failure returns false and sets `error`.
  bool open(const std::filesystem::path& path, std::string* error);

  // `text` is printed and logged verbatim (it may span lines, e.g. a rendered diagnostic with its
  // source excerpt); a final newline is added when missing. A message that cannot be logged is
  // still printed; file() tells the step driver.
  void info(std::string_view text);
  void warning(std::string_view text);
  void error(std::string_view text);

  // Logged only: iteration lines would drown the terminal.
  void iteration(const IterationRecord& record);

  // The file underneath, which keeps the first write failure.
  const OutputFile& file() const { return file_; }

 private:
  void emit(std::string_view text, std::ostream* echo);

  OutputFile file_;
  std::string line_;  // reused line buffer
  std::ostream* info_echo_;
  std::ostream* warning_echo_;
};

}  // namespace clinch
