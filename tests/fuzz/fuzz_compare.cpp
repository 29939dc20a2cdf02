// libFuzzer target: `clinch compare` on any byte string, split as
//   <--columns pattern>\n<result table>\n%%\n<golden table>
// (an empty first line compares every column). A crash, a sanitizer report or a hang is a bug;
// a table that cannot be read or compared is the expected outcome (cli-contract.md, exit 3).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "src/output/csv_table.hpp"
#include "src/output/table_comparison.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::size_t pattern_end = text.find('\n');
  if (pattern_end == std::string_view::npos) return 0;
  const std::size_t split = text.find("\n%%\n", pattern_end);
  if (split == std::string_view::npos) return 0;
  const std::string pattern(text.substr(0, pattern_end));
  // Each table keeps its last newline, as a file has it; the result table may be empty.
  const std::string_view result_text = text.substr(pattern_end + 1, split - pattern_end);
  const std::string_view golden_text = text.substr(split + 4);

  clinch::CompareOptions options;
  std::string error;
  if (!pattern.empty()) {
    // As compare_command.cpp builds it; a pattern RE2 rejects is a usage error there.
    options.columns = clinch::compile_column_pattern(pattern, &error);
    if (!options.columns) return 0;
  }
  const std::optional<clinch::CsvTable> result =
      clinch::parse_csv_table("result.csv", result_text, &error);
  const std::optional<clinch::CsvTable> golden =
      clinch::parse_csv_table("golden.csv", golden_text, &error);
  if (!result || !golden) return 0;
  const std::optional<clinch::TableComparison> comparison =
      clinch::compare_tables(*result, *golden, options, &error);
  if (comparison) (void)clinch::render_comparison(*comparison, options);
  return 0;
}
