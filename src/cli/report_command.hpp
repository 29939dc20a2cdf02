// `clinch report RUN_DIR [--job NAME] [--golden GOLDEN.csv [--rtol R] [--atol A]]
// [--study STUDY.csv] [--fit CURVES.csv] [--connectors N] [--elements E,...] [--components C,...]
// [--variables V,...] [-o PAGE.html] [--quiet]`: gathers what a run wrote (history table, status
// file, the Newton iterations of its log), the comparison with a golden table, a study's settings
// and a fit's curves, and has report_page.py draw them into one self-contained HTML page. Exit 0 =
// the page was written, 3 = usage or I/O error (a missing or malformed input, python3 or
// matplotlib missing).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "src/output/table_comparison.hpp"

namespace clinch {

struct ReportOptions {
  std::string run_dir;
  std::optional<std::string> job;
  std::optional<std::string> golden;
  double rtol = kDefaultRtol;
  double atol = kDefaultAtol;
  std::optional<std::string> study;
  std::optional<std::string> fit;  // a <job>.fit-curves.csv of `clinch fit`
  // A model with thousands of connectors would make a page nobody can read, and take minutes
  // to draw: the most loaded ones are drawn, and the page says how many were left out.
  int max_connectors = 20;
  // --elements, --components, --variables (comma-separated): the connectors and nodes (labels as
  // the history names them), components (1-6) and variables (CTF or CTM, ...) to draw.
  std::vector<std::string> elements, variables;
  std::vector<int> components;
  std::optional<std::string> output;  // default: RUN_DIR/<job>.report.html
  bool quiet = false;
};

int run_report(const ReportOptions& options);

}  // namespace clinch
