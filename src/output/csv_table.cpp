#include "src/output/csv_table.hpp"

#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

namespace clinch {
namespace {

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

// Accepts what the history writer produces (shortest round-trip, "nan", "inf") and, for
// hand-written golden tables, a leading '+'.
bool parse_number(std::string_view field, double* value) {
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);
  if (field.empty()) return false;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), *value);
  return ec == std::errc() && end == field.data() + field.size();
}

}  // namespace

std::optional<std::size_t> CsvTable::column_index(std::string_view name) const {
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (columns[i] == name) return i;
  }
  return std::nullopt;
}

std::optional<CsvTable> parse_csv_table(const std::string& path, std::string_view text,
                                        std::string* error) {
  CsvTable table;
  table.path = path;
  bool have_header = false;
  std::size_t line_number = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos) eol = text.size();
    const std::string_view line = trim(text.substr(pos, eol - pos));
    pos = eol + 1;
    ++line_number;
    if (line.empty()) continue;
    if (!have_header) {
      if (line.front() == '#') continue;
      for (std::string_view name : split_fields(line)) {
        if (name.empty()) {
          *error = fmt::format("{}:{}: empty column name in the header", path, line_number);
          return std::nullopt;
        }
        if (table.column_index(name)) {
          *error = fmt::format("{}:{}: column '{}' appears twice in the header", path, line_number,
                               name);
          return std::nullopt;
        }
        table.columns.emplace_back(name);
      }
      have_header = true;
      continue;
    }
    const std::vector<std::string_view> fields = split_fields(line);
    if (fields.size() != table.columns.size()) {
      *error = fmt::format("{}:{}: row has {} fields, the header has {}", path, line_number,
                           fields.size(), table.columns.size());
      return std::nullopt;
    }
    std::vector<double> row(fields.size());
    for (std::size_t i = 0; i < fields.size(); ++i) {
      if (!parse_number(fields[i], &row[i])) {
        *error = fmt::format("{}:{}: '{}' in column '{}' is not a number", path, line_number,
                             fields[i], table.columns[i]);
        return std::nullopt;
      }
    }
    table.rows.push_back(std::move(row));
    table.row_lines.push_back(line_number);
  }
  if (!have_header) {
    *error = fmt::format("{}:{}: empty table: no header row", path, line_number + 1);
    return std::nullopt;
  }
  return table;
}

std::optional<CsvTable> read_csv_table(const std::string& path, std::string* error) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    *error = fmt::format("{}: cannot read: is a directory", path);
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    *error = fmt::format("{}: cannot read: {}", path, std::strerror(errno));
    return std::nullopt;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) {
    *error = fmt::format("{}: cannot read: {}", path, std::strerror(errno));
    return std::nullopt;
  }
  return parse_csv_table(path, buffer.str(), error);
}

}  // namespace clinch
