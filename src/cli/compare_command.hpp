// `clinch compare RESULT.csv GOLDEN.csv [--rtol R] [--atol A] [--columns REGEX]`
// (cli-contract.md): compares two history tables column by column. Exit 0 when every column
// passes, 1 when one fails or is missing, 3 on a usage or I/O error.
#pragma once

#include <optional>
#include <string>

#include "src/output/table_comparison.hpp"

namespace clinch {

struct CompareArguments {
  std::string result_path;
  std::string golden_path;
  double rtol = kDefaultRtol;
  double atol = kDefaultAtol;
  std::optional<std::string> columns;  // RE2 pattern, matched against the whole column name
};

// Checks a --rtol/--atol value: a finite number >= 0. Returns an empty string when it is one, else
// the message (the CLI11 validator convention).
std::string check_tolerance(const std::string& text);

int run_compare(const CompareArguments& arguments);

}  // namespace clinch
