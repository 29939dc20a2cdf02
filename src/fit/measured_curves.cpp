#include "src/fit/measured_curves.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "src/output/abaqus_labels.hpp"
#include "src/output/history_table.hpp"

namespace clinch {
namespace {

bool is_key(const std::string& name) {
  return std::find(std::begin(HistoryTable::kKeyColumns), std::end(HistoryTable::kKeyColumns),
                   name) != std::end(HistoryTable::kKeyColumns);
}

// A column of `table` by its name or by the same column in the other labelling (CTM1@7, CTF4@7).
std::optional<std::size_t> find_column(const CsvTable& table, const std::string& name) {
  if (std::optional<std::size_t> i = table.column_index(name)) return i;
  const std::string canonical = canonical_column_name(name);
  for (std::size_t i = 0; i < table.columns.size(); ++i) {
    if (canonical_column_name(table.columns[i]) == canonical) return i;
  }
  return std::nullopt;
}

}  // namespace

std::string MeasuredCurves::header_position(std::size_t column) const {
  return fmt::format("{}:{}:{}", table.path, table.header_line, table.header_columns[column]);
}

std::optional<MeasuredCurves> read_measured_curves(const std::string& path,
                                                   const std::string& abscissa,
                                                   const std::map<std::string, double>& scales,
                                                   std::string* error) {
  std::optional<CsvTable> table = read_csv_table(path, error);
  if (!table) return std::nullopt;
  MeasuredCurves curves;
  curves.table = std::move(*table);
  const CsvTable& t = curves.table;
  const std::string header = fmt::format("{}:{}:1", path, t.header_line);
  const std::optional<std::size_t> x = find_column(t, abscissa);
  if (!x) {
    *error = fmt::format(
        "{}: error: no column '{}' to measure the curves against (--x names the "
        "abscissa; total_time unless it is given)",
        header, abscissa);
    return std::nullopt;
  }
  curves.abscissa = *x;
  if (t.rows.empty()) {
    *error = fmt::format("{}: error: the data file has no rows", header);
    return std::nullopt;
  }
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    for (std::size_t c = 0; c < t.columns.size(); ++c) {
      if (!std::isfinite(t.rows[r][c])) {
        *error = fmt::format("{}:{}: error: '{}' is not finite: a measured value is a number", path,
                             t.row_lines[r], t.columns[c]);
        return std::nullopt;
      }
    }
  }
  for (const auto& [name, scale] : scales) {
    if (!find_column(t, name)) continue;  // the scale is for another data file
    if (!(scale > 0.0) || !std::isfinite(scale)) {
      *error = fmt::format("--scale {}={}: a scale is a finite number > 0", name, scale);
      return std::nullopt;
    }
  }
  for (std::size_t c = 0; c < t.columns.size(); ++c) {
    if (c == *x || is_key(t.columns[c])) continue;
    MeasuredColumn column;
    column.index = c;
    const std::string canonical = canonical_column_name(t.columns[c]);
    const auto given = std::find_if(scales.begin(), scales.end(), [&](const auto& s) {
      return canonical_column_name(s.first) == canonical;
    });
    if (given != scales.end()) {
      column.scale = given->second;
    } else {
      double peak = 0.0;
      for (const std::vector<double>& row : t.rows) peak = std::max(peak, std::abs(row[c]));
      if (peak == 0.0) {
        *error = fmt::format(
            "{}: error: '{}' is zero throughout: give its scale with --scale "
            "{}=S",
            curves.header_position(c), t.columns[c], t.columns[c]);
        return std::nullopt;
      }
      column.scale = peak;
    }
    curves.columns.push_back(column);
  }
  if (curves.columns.empty()) {
    *error = fmt::format(
        "{}: error: no measured column: the header names only the abscissa '{}' "
        "and key columns",
        header, t.columns[*x]);
    return std::nullopt;
  }
  return curves;
}

bool check_columns_written(const MeasuredCurves& curves, const CsvTable& run,
                           const std::string& deck, std::string* error) {
  std::vector<std::size_t> needed = {curves.abscissa};
  for (const MeasuredColumn& c : curves.columns) needed.push_back(c.index);
  for (std::size_t c : needed) {
    if (find_column(run, curves.table.columns[c])) continue;
    std::string written;
    for (std::size_t k = 4; k < run.columns.size() && k < 16; ++k) {
      written += (k > 4 ? ", " : "") + run.columns[k];
    }
    if (run.columns.size() > 16) written += ", ...";
    *error = fmt::format(
        "{}: error: the run of {} writes no column '{}' (it writes {}): request "
        "it in the deck's *OUTPUT, HISTORY",
        curves.header_position(c), deck, curves.table.columns[c], written);
    return false;
  }
  return true;
}

std::optional<std::vector<double>> model_values(const MeasuredCurves& curves, const CsvTable& run,
                                                std::string* error) {
  const CsvTable& data = curves.table;
  const std::size_t x_column = *find_column(run, data.columns[curves.abscissa]);
  std::vector<double> xs;
  for (const std::vector<double>& row : run.rows) xs.push_back(row[x_column]);
  if (xs.empty()) {
    *error = fmt::format("{}: the run wrote no row", run.path);
    return std::nullopt;
  }
  // The run's abscissa, made increasing: a decreasing one (a pull in -1) is read backwards.
  const bool increasing = xs.back() >= xs.front();
  std::vector<std::size_t> order(xs.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = increasing ? i : order.size() - 1 - i;
  for (std::size_t k = 1; k < order.size(); ++k) {
    if (xs[order[k]] < xs[order[k - 1]]) {
      *error = fmt::format(
          "{}:{}: error: the run's {} turns back at {} (row {}): the model has no single value "
          "there; "
          "measure against total_time (--x total_time)",
          run.path, run.row_lines[order[k]], run.columns[x_column], xs[order[k]], order[k] + 1);
      return std::nullopt;
    }
  }
  std::vector<double> sorted_x;
  for (std::size_t i : order) sorted_x.push_back(xs[i]);
  const double span = std::max(std::abs(sorted_x.front()), std::abs(sorted_x.back()));
  const double tolerance = 1e-12 * span;  // as `clinch compare` matches times
  std::vector<std::size_t> model_columns;
  for (const MeasuredColumn& c : curves.columns) {
    model_columns.push_back(*find_column(run, data.columns[c.index]));
  }
  std::vector<double> values;
  values.reserve(curves.point_count());
  for (std::size_t r = 0; r < data.rows.size(); ++r) {
    const double x = data.rows[r][curves.abscissa];
    if (x < sorted_x.front() - tolerance || x > sorted_x.back() + tolerance) {
      *error = fmt::format("{}:{}: error: {} = {} lies outside the run's range [{}, {}]", data.path,
                           data.row_lines[r], data.columns[curves.abscissa], x, sorted_x.front(),
                           sorted_x.back());
      return std::nullopt;
    }
    // The last row at or before x (the later state at a repeated abscissa), and the next one.
    const auto after = std::upper_bound(sorted_x.begin(), sorted_x.end(), x + tolerance);
    const std::size_t k = static_cast<std::size_t>(
        std::max<std::ptrdiff_t>(0, std::distance(sorted_x.begin(), after) - 1));
    const bool at_row = sorted_x[k] >= x - tolerance || k + 1 == sorted_x.size();
    const double w = at_row ? 0.0 : (x - sorted_x[k]) / (sorted_x[k + 1] - sorted_x[k]);
    for (std::size_t column : model_columns) {
      const double before = run.rows[order[k]][column];
      values.push_back(at_row ? before : before + w * (run.rows[order[k + 1]][column] - before));
    }
  }
  return values;
}

void append_residuals(const MeasuredCurves& curves, const std::vector<double>& model,
                      std::vector<double>& residuals) {
  std::size_t i = 0;
  for (const std::vector<double>& row : curves.table.rows) {
    for (const MeasuredColumn& c : curves.columns) {
      residuals.push_back((model[i++] - row[c.index]) / c.scale);
    }
  }
}

}  // namespace clinch
