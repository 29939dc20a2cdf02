// Reading a history table back (cli-contract.md "History table"): a header row and numeric rows,
// as `clinch compare` and the regression tests need it. `#` lines before the header (provenance
// notes in golden tables) are skipped. Fields follow RFC 4180: a name with a comma, a quote or a
// line break is written in double quotes, its quotes doubled (docs/history-table.md).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace clinch {

struct CsvTable {
  std::string path;  // as given, for messages
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;  // each row has columns.size() values
  std::vector<std::size_t> row_lines;     // 1-based file line of each row
  // The header's 1-based file line, and the 1-based column of each name on it, for messages.
  std::size_t header_line = 0;
  std::vector<std::size_t> header_columns;

  // Index of the column named `name`, or nullopt.
  std::optional<std::size_t> column_index(std::string_view name) const;
};

// `text` as one CSV field: as it is, or in double quotes with its quotes doubled when it holds a
// comma, a quote or a line break, or starts or ends with a blank (the reader trims those), or
// starts with '#' (a note before the header).
std::string csv_field(std::string_view text);

// Parses `text` read from `path`. On failure returns nullopt and sets `error` to
// "PATH:LINE: message" (empty file, empty or repeated column name, ragged row, bad number, a
// quote not closed). LINE is the line where the record starts.
std::optional<CsvTable> parse_csv_table(const std::string& path, std::string_view text,
                                        std::string* error);

// Reads and parses the file at `path`; an unreadable file is reported like a parse error.
std::optional<CsvTable> read_csv_table(const std::string& path, std::string* error);

}  // namespace clinch
