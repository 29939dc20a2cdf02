// `clinch study DECK.inp [--work DIR] [--levels N] [--ratio R] [--budget S] [--rtol R] [--jobs J]
// [--columns REGEX] [--no-plot] [--quiet]`: runs the deck over a ladder of increment sizes (the
// deck's own *STATIC settings, then each divided by R), and prints per setting the wall time,
// increments, Newton iterations, cutbacks and the error of the history columns (against the
// finest setting, and estimated by Richardson extrapolation where an order shows). Writes
// DIR/<job>.study.csv, DIR/<job>.study-columns.csv and the work-precision plot
// DIR/<job>.study.svg. Exit 0 = the study compared at least two settings, 1 = the deck has errors
// (nothing was run), 2 = fewer than two settings completed or the study was stopped by SIGINT or
// SIGTERM (docs/study-and-report.md "Stopping a study"), 3 = usage or I/O error.
#pragma once

#include <optional>
#include <string>

namespace clinch {

struct StudyOptions {
  std::string deck;
  std::optional<std::string> work_dir;  // default: <job>.study in the current directory
  int levels = 6;
  double ratio = 2.0;
  std::optional<double> budget_seconds;
  std::optional<double> rtol;
  int jobs = 0;  // 0: one per core
  std::optional<std::string> columns;
  bool plot = true;
  bool quiet = false;
};

// Check a --ratio value (a finite number from 1.01 to 1000) and a --budget or --rtol value (a
// finite number > 0). Each returns an empty string when the value is one, else the message (the
// CLI11 validator convention): NaN compares false with every bound, so a range test alone lets it
// through.
std::string check_ratio(const std::string& text);
std::string check_positive(const std::string& text);

int run_study(const StudyOptions& options);

}  // namespace clinch
