#include "src/cli/compare_command.hpp"

#include <charconv>
#include <cmath>
#include <iostream>

#include <fmt/format.h>

#include "src/output/csv_table.hpp"
#include "src/output/table_comparison.hpp"

namespace clinch {

std::string check_tolerance(const std::string& text) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value) ||
      value < 0.0) {
    return fmt::format("'{}' is not a tolerance: a finite number >= 0 is needed", text);
  }
  return {};
}

int run_compare(const CompareArguments& arguments) {
  CompareOptions options;
  options.rtol = arguments.rtol;
  options.atol = arguments.atol;
  std::string error;
  if (arguments.columns) {
    options.columns = compile_column_pattern(*arguments.columns, &error);
    if (!options.columns) {
      std::cerr << fmt::format(
          "clinch: error: --columns '{}' is not a valid regular expression: {}\n",
          *arguments.columns, error);
      return 3;
    }
  }
  const std::optional<CsvTable> result = read_csv_table(arguments.result_path, &error);
  if (!result) {
    std::cerr << fmt::format("clinch: error: {}\n", error);
    return 3;
  }
  const std::optional<CsvTable> golden = read_csv_table(arguments.golden_path, &error);
  if (!golden) {
    std::cerr << fmt::format("clinch: error: {}\n", error);
    return 3;
  }
  const std::optional<TableComparison> comparison =
      compare_tables(*result, *golden, options, &error);
  if (!comparison) {
    std::cerr << fmt::format("clinch: error: {}\n", error);
    return 3;
  }
  std::cout << fmt::format("{} against {}\n", arguments.result_path, arguments.golden_path)
            << render_comparison(*comparison, options);
  return comparison->passed() ? 0 : 1;
}

}  // namespace clinch
