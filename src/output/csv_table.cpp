#include "src/output/csv_table.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include <fmt/format.h>

namespace clinch {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

// The fields of one record: views into the text, but for quoted fields with doubled quotes,
// which are held undoubled in `unescaped`. A long table is read without an allocation per number.
struct Record {
  std::vector<std::string_view> fields;
  std::deque<std::string> unescaped;  // a deque: its strings stay where the views point
  bool quoted = false;                // some field was quoted

  bool blank() const { return fields.size() == 1 && fields[0].empty() && !quoted; }
};

// Reads the record that starts at `pos` (RFC 4180: fields separated by commas; a field in double
// quotes may hold commas, line breaks and quotes written twice) and moves `pos` past its line
// break and `line` to the line of the next record. An unquoted field is trimmed of blanks, and
// blanks around a quoted field are ignored, as the tables always allowed blanks after a comma.
// False, with the reason in `why`, when a quote is not closed or text follows a closing quote.
bool read_record(std::string_view text, std::size_t& pos, std::size_t& line, Record& record,
                 std::string* why) {
  record.fields.clear();
  record.unescaped.clear();
  record.quoted = false;
  const std::size_t n = text.size();
  while (true) {
    const std::size_t start = pos;
    while (pos < n && is_blank(text[pos])) ++pos;
    if (pos < n && text[pos] == '"') {
      record.quoted = true;
      const std::size_t opening_line = line;
      const std::size_t first = ++pos;
      bool doubled = false;
      while (true) {
        const std::size_t quote = text.find('"', pos);
        if (quote == std::string_view::npos) {
          *why = fmt::format("the quoted field that starts on line {} is not closed",
                             opening_line);
          return false;
        }
        line += static_cast<std::size_t>(
            std::count(text.begin() + static_cast<std::ptrdiff_t>(pos),
                       text.begin() + static_cast<std::ptrdiff_t>(quote), '\n'));
        pos = quote + 1;
        if (pos < n && text[pos] == '"') {
          doubled = true;
          ++pos;
          continue;
        }
        const std::string_view inside = text.substr(first, quote - first);
        if (!doubled) {
          record.fields.push_back(inside);
          break;
        }
        std::string& field = record.unescaped.emplace_back();
        for (std::size_t i = 0; i < inside.size(); ++i) {
          field += inside[i];
          if (inside[i] == '"') ++i;  // the second quote of a pair
        }
        record.fields.push_back(field);
        break;
      }
      while (pos < n && is_blank(text[pos])) ++pos;
      if (pos < n && text[pos] != ',' && text[pos] != '\n') {
        *why = "text after the closing quote of a field (a quote inside a quoted field is "
               "written twice)";
        return false;
      }
    } else {
      pos = std::min(text.find_first_of(",\n", pos), n);
      record.fields.push_back(trim(text.substr(start, pos - start)));
    }
    if (pos >= n || text[pos] == '\n') {
      ++pos;
      ++line;
      return true;
    }
    ++pos;  // the comma
  }
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

std::string csv_field(std::string_view text) {
  // Blanks at either end are quoted too, since the reader trims unquoted fields, and a leading
  // '#', which would make a first header field read as a note.
  const bool plain = text.find_first_of(",\"\n\r") == std::string_view::npos &&
                     (text.empty() || (!is_blank(text.front()) && !is_blank(text.back()) &&
                                       text.front() != '#'));
  if (plain) return std::string(text);
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

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
  std::size_t line = 1;  // of the next record
  std::size_t pos = 0;
  Record record;
  std::string why;
  while (pos < text.size()) {
    const std::size_t record_line = line;
    const std::size_t record_start = pos;
    if (!have_header) {
      // `#` lines before the header are notes, whatever they hold.
      std::size_t eol = text.find('\n', pos);
      if (eol == std::string_view::npos) eol = text.size();
      const std::string_view first_line = trim(text.substr(pos, eol - pos));
      if (!first_line.empty() && first_line.front() == '#') {
        pos = eol + 1;
        ++line;
        continue;
      }
    }
    if (!read_record(text, pos, line, record, &why)) {
      *error = fmt::format("{}:{}: {}", path, record_line, why);
      return std::nullopt;
    }
    if (record.blank()) continue;
    if (!have_header) {
      table.header_line = record_line;
      // A record starts a line: the names on it have a column, those of a quoted field that
      // spans lines or holds doubled quotes (read into a copy) are given column 1.
      const std::string_view header_text =
          text.substr(record_start, text.find('\n', record_start) - record_start);
      const std::less<const char*> before;
      for (const std::string_view name : record.fields) {
        const bool on_line = !before(name.data(), header_text.data()) &&
                             !before(header_text.data() + header_text.size(), name.data());
        table.header_columns.push_back(
            on_line ? static_cast<std::size_t>(name.data() - header_text.data()) + 1 : 1);
        if (name.empty()) {
          *error = fmt::format("{}:{}: empty column name in the header", path, record_line);
          return std::nullopt;
        }
        if (table.column_index(name)) {
          *error = fmt::format("{}:{}: column '{}' appears twice in the header", path,
                               record_line, name);
          return std::nullopt;
        }
        table.columns.emplace_back(name);
      }
      have_header = true;
      continue;
    }
    if (record.fields.size() != table.columns.size()) {
      *error = fmt::format("{}:{}: row has {} fields, the header has {}", path, record_line,
                           record.fields.size(), table.columns.size());
      return std::nullopt;
    }
    std::vector<double> row(record.fields.size());
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (!parse_number(record.fields[i], &row[i])) {
        *error = fmt::format("{}:{}: '{}' in column '{}' is not a number", path, record_line,
                             record.fields[i], table.columns[i]);
        return std::nullopt;
      }
    }
    table.rows.push_back(std::move(row));
    table.row_lines.push_back(record_line);
  }
  if (!have_header) {
    *error = fmt::format("{}:{}: empty table: no header row", path, line);
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
