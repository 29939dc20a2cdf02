// libFuzzer target: `clinch compare` on any byte string, split as
//   <--columns pattern>\n<result table>\n%%\n<golden table>
// (an empty first line compares every column). A crash, a sanitizer report or a hang is a bug;
// a table that cannot be read or compared is the expected outcome (cli-contract.md, exit 3).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <regex>
#include <string>
#include <string_view>

#include "src/output/csv_table.hpp"
#include "src/output/table_comparison.hpp"

namespace {
constexpr std::size_t kMaxRegexText = 256;
}  // namespace

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
  if (!pattern.empty()) {
    // As compare_command.cpp builds it. libstdc++'s std::regex compiles and matches by
    // recursion, so long patterns (and long names, below) are left out: they would exhaust the
    // stack inside the library, not in clinch.
    if (pattern.size() > kMaxRegexText) return 0;
    // libstdc++ 12 reads the number of a back-reference (\555...) or of a repeat count
    // ({555...}) into a long without an overflow check: undefined behaviour inside the library,
    // which UBSan stops at. RE2, meant to replace std::regex here, checks its repeat counts.
    std::size_t digits = 0;
    for (const char c : pattern) {
      digits = c >= '0' && c <= '9' ? digits + 1 : 0;
      if (digits > 18) return 0;
    }
    try {
      options.columns.emplace(pattern, std::regex::ECMAScript);
    } catch (const std::regex_error&) {
      return 0;
    }
  }
  std::string error;
  const std::optional<clinch::CsvTable> result =
      clinch::parse_csv_table("result.csv", result_text, &error);
  const std::optional<clinch::CsvTable> golden =
      clinch::parse_csv_table("golden.csv", golden_text, &error);
  if (!result || !golden) return 0;
  if (options.columns) {
    for (const std::string& name : golden->columns) {
      if (name.size() > kMaxRegexText) return 0;
    }
  }
  const std::optional<clinch::TableComparison> comparison =
      clinch::compare_tables(*result, *golden, options, &error);
  if (comparison) (void)clinch::render_comparison(*comparison, options);
  return 0;
}
