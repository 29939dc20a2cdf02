// libFuzzer target: the history-table reader on any byte string. A crash, a sanitizer report or a
// hang is a bug; a table that cannot be read is the expected outcome (cli-contract.md, exit 3).
// A table that is read must come back the same when written as clinch writes it (names through
// csv_field, numbers in shortest round-trip form) and read again: the quoting of names and the
// reading of quoted fields (docs/history-table.md) are each other's inverse.
#include <fmt/format.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

#include "src/output/csv_table.hpp"

namespace {

bool same_value(double a, double b) {
  return std::isnan(a) ? std::isnan(b) : a == b && std::signbit(a) == std::signbit(b);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::string error;
  const std::optional<clinch::CsvTable> table = clinch::parse_csv_table("fuzz.csv", text, &error);
  if (!table) {
    if (error.rfind("fuzz.csv:", 0) != 0) std::abort();  // every message names file and line
    return 0;
  }
  std::string written;
  for (std::size_t c = 0; c < table->columns.size(); ++c) {
    written += (c == 0 ? "" : ",") + clinch::csv_field(table->columns[c]);
  }
  written += '\n';
  for (const std::vector<double>& row : table->rows) {
    for (std::size_t c = 0; c < row.size(); ++c) written += fmt::format("{}{}", c == 0 ? "" : ",", row[c]);
    written += '\n';
  }
  const std::optional<clinch::CsvTable> again =
      clinch::parse_csv_table("again.csv", written, &error);
  if (!again || again->columns != table->columns || again->rows.size() != table->rows.size()) {
    std::abort();
  }
  for (std::size_t r = 0; r < table->rows.size(); ++r) {
    for (std::size_t c = 0; c < table->columns.size(); ++c) {
      if (!same_value(again->rows[r][c], table->rows[r][c])) std::abort();
    }
  }
  return 0;
}
