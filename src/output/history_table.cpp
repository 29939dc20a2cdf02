#include "src/output/history_table.hpp"

#include <iterator>
#include <stdexcept>

#include <fmt/format.h>

#include "src/output/csv_table.hpp"

namespace clinch {

bool HistoryTable::open(const std::filesystem::path& path, std::vector<std::string> columns,
                        std::string* error) {
  if (!file_.open(path, error)) return false;
  columns_ = std::move(columns);
  line_.clear();
  for (const char* key : kKeyColumns) {
    if (!line_.empty()) line_ += ',';
    line_ += key;
  }
  for (const std::string& column : columns_) {
    line_ += ',';
    line_ += csv_field(column);  // a set name may hold a comma (RFC 4180 quoting)
  }
  line_ += '\n';
  if (!file_.write(line_)) {
    *error = file_.error();
    return false;
  }
  return true;
}

bool HistoryTable::write_row(int step, int increment, double step_time, double total_time,
                             std::span<const double> values) {
  if (values.size() != columns_.size()) {
    throw std::logic_error(
        fmt::format("history row with {} values for {} columns", values.size(), columns_.size()));
  }
  // fmt's default double format is the shortest string that reads back to the same value
  // (cli-contract.md: round-trip precision).
  line_.clear();
  auto out = std::back_inserter(line_);
  fmt::format_to(out, "{},{},{},{}", step, increment, step_time, total_time);
  for (double v : values) fmt::format_to(out, ",{}", v);
  line_ += '\n';
  return file_.write(line_);
}

}  // namespace clinch
