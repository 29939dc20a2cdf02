#include "src/output/table_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <set>
#include <unordered_map>

#include <fmt/format.h>
#include <re2/re2.h>

#include "src/output/abaqus_labels.hpp"
#include "src/output/history_table.hpp"

namespace clinch {
namespace {

// Times closer than this fraction of the largest |total_time| of either table are the same time:
// the result and the golden may reach a time by different sums of increments (0.1 + 0.2 vs 0.3).
constexpr double kTimeTolerance = 1e-12;

// Where a golden time falls in the result: an existing row, between two rows, or outside.
struct TimeMatch {
  enum class Kind { Row, Between, Outside } kind = Kind::Outside;
  std::size_t row = 0;  // Row: the row; Between: the row before
  double weight = 0.0;  // Between: weight of the row after
};

std::vector<double> column_values(const CsvTable& table, std::size_t column) {
  std::vector<double> values;
  values.reserve(table.rows.size());
  for (const std::vector<double>& row : table.rows) values.push_back(row[column]);
  return values;
}

bool check_time_order(const CsvTable& table, const std::vector<double>& times, std::string* error) {
  for (std::size_t i = 1; i < times.size(); ++i) {
    if (!(times[i] >= times[i - 1])) {
      *error = fmt::format("{}:{}: total_time {} comes after {}: rows must be in time order",
                           table.path, table.row_lines[i], times[i], times[i - 1]);
      return false;
    }
  }
  return true;
}

// A golden time equal (within `tol`) to result times maps to the LAST result row at that time: a
// repeated row is a later state at the same time (a re-solved increment). Rows of several steps at
// one time (a linear perturbation step takes no time, docs/perturbation.md) are told apart by
// the golden row's step: the last of them in that step, if it has one. Between two times the
// bracketing rows are the adjacent pair around it.
TimeMatch match_time(const std::vector<double>& times, const std::vector<double>& steps, double t,
                     double step, double tol) {
  TimeMatch match;
  if (times.empty() || !std::isfinite(t) || t < times.front() - tol || t > times.back() + tol) {
    return match;
  }
  const auto after = std::upper_bound(times.begin(), times.end(), t + tol);
  const std::size_t last = static_cast<std::size_t>(std::distance(times.begin(), after)) - 1;
  if (times[last] >= t - tol) {
    match.kind = TimeMatch::Kind::Row;
    match.row = last;
    for (std::size_t i = last + 1; i-- > 0 && times[i] >= t - tol;) {
      if (steps[i] == step) {
        match.row = i;
        break;
      }
    }
    return match;
  }
  match.kind = TimeMatch::Kind::Between;
  match.row = last;
  match.weight = (t - times[last]) / (times[last + 1] - times[last]);
  return match;
}

double value_at(const std::vector<double>& values, const TimeMatch& match) {
  if (match.kind == TimeMatch::Kind::Row) return values[match.row];
  const double before = values[match.row];
  const double after = values[match.row + 1];
  return before + match.weight * (after - before);
}

bool require_keys(const CsvTable& table, std::string* error) {
  for (const char* key : HistoryTable::kKeyColumns) {
    if (!table.column_index(key)) {
      *error = fmt::format("{}: no '{}' column: not a history table", table.path, key);
      return false;
    }
  }
  return true;
}

bool is_key(const std::string& name) {
  return std::find(std::begin(HistoryTable::kKeyColumns), std::end(HistoryTable::kKeyColumns),
                   name) != std::end(HistoryTable::kKeyColumns);
}

// |diff| / allowed, to pick the worst row of a column; a NaN or a non-zero |diff| with nothing
// allowed is infinitely bad.
double badness(double r, double g, double difference, double allowed) {
  if (r == g) return 0.0;
  if (std::isnan(difference) || allowed <= 0.0) return std::numeric_limits<double>::infinity();
  return difference / allowed;
}

ColumnComparison compare_column(const std::string& name, const std::vector<double>& result,
                                const std::vector<double>& golden,
                                const std::vector<TimeMatch>& matches,
                                const std::vector<double>& golden_times,
                                const CompareOptions& options) {
  ColumnComparison c;
  c.name = name;
  // cli-contract.md: scale_of_column is the largest |g| of the column.
  double scale = 0.0;
  for (double g : golden) {
    if (std::isfinite(g)) scale = std::max(scale, std::abs(g));
  }
  bool worst_failed = false;
  double worst_badness = -1.0;
  for (std::size_t i = 0; i < golden.size(); ++i) {
    if (matches[i].kind == TimeMatch::Kind::Outside) {
      if (c.out_of_range_rows++ == 0) c.first_out_of_range_time = golden_times[i];
      continue;
    }
    ++c.compared_rows;
    const double g = golden[i];
    const double r = value_at(result, matches[i]);
    const double difference = std::abs(r - g);
    const double allowed = options.atol + options.rtol * std::max(std::abs(g), scale);
    // Equal values pass even when infinite; a NaN on either side never passes.
    const bool pass = r == g || difference <= allowed;
    if (!pass) ++c.failed_rows;
    // The worst row is a failing one if any fails, then the one with the largest badness.
    const double b = badness(r, g, difference, allowed);
    if (!c.has_worst || (!pass && !worst_failed) || (pass != worst_failed && b > worst_badness)) {
      c.has_worst = true;
      worst_failed = !pass;
      worst_badness = b;
      c.result = r;
      c.golden = g;
      c.difference = difference;
      c.allowed = allowed;
      c.total_time = golden_times[i];
    }
  }
  c.verdict =
      c.failed_rows > 0 || c.out_of_range_rows > 0 ? ColumnVerdict::Fail : ColumnVerdict::Pass;
  return c;
}

}  // namespace

bool TableComparison::passed() const {
  return problems.empty() &&
         std::all_of(columns.begin(), columns.end(),
                     [](const ColumnComparison& c) { return c.verdict == ColumnVerdict::Pass; });
}

std::shared_ptr<const re2::RE2> compile_column_pattern(std::string_view pattern,
                                                       std::string* error) {
  re2::RE2::Options re2_options;
  re2_options.set_log_errors(false);  // the caller reports the error its own way
  auto compiled = std::make_shared<const re2::RE2>(pattern, re2_options);
  if (!compiled->ok()) {
    *error = compiled->error();
    return nullptr;
  }
  return compiled;
}

std::optional<TableComparison> compare_tables(const CsvTable& result, const CsvTable& golden,
                                              const CompareOptions& options, std::string* error) {
  if (!require_keys(result, error) || !require_keys(golden, error)) return std::nullopt;
  if (golden.rows.empty()) {
    *error = fmt::format("{}: the golden table has no rows", golden.path);
    return std::nullopt;
  }
  const std::vector<double> result_times =
      column_values(result, *result.column_index("total_time"));
  const std::vector<double> golden_times =
      column_values(golden, *golden.column_index("total_time"));
  if (!check_time_order(result, result_times, error) ||
      !check_time_order(golden, golden_times, error)) {
    return std::nullopt;
  }

  std::vector<std::string> names;
  for (const std::string& name : golden.columns) {
    if (is_key(name)) continue;
    if (options.columns && !re2::RE2::FullMatch(name, *options.columns)) continue;
    names.push_back(name);
  }
  if (names.empty()) {
    *error = options.columns
                 ? fmt::format("{}: --columns selects none of its columns", golden.path)
                 : fmt::format("{}: the golden table has no column besides the keys", golden.path);
    return std::nullopt;
  }

  TableComparison comparison;
  comparison.golden_rows = golden.rows.size();

  // "step must exist": every step of the golden table has rows in the result, so that a run that
  // stopped early cannot pass on the steps it did finish.
  const std::vector<double> result_steps = column_values(result, *result.column_index("step"));
  const std::set<double> ran(result_steps.begin(), result_steps.end());
  std::set<double> reported;
  for (double step : column_values(golden, *golden.column_index("step"))) {
    if (!ran.contains(step) && reported.insert(step).second) {
      comparison.problems.push_back(
          fmt::format("step {} of the golden table has no row in the result", step));
    }
  }

  double time_scale = 0.0;
  for (const std::vector<double>* times : {&result_times, &golden_times}) {
    for (double t : *times) {
      if (std::isfinite(t)) time_scale = std::max(time_scale, std::abs(t));
    }
  }
  const double time_tol = kTimeTolerance * time_scale;
  const std::vector<double> golden_steps = column_values(golden, *golden.column_index("step"));
  std::vector<TimeMatch> matches;
  matches.reserve(golden_times.size());
  for (std::size_t i = 0; i < golden_times.size(); ++i) {
    matches.push_back(
        match_time(result_times, result_steps, golden_times[i], golden_steps[i], time_tol));
  }

  // A golden column is found in the result by its name, else by the same column in the other
  // naming (CTM1@7 in one table, CTF4@7 in the other: output-variables.md §1.1).
  std::unordered_map<std::string, std::size_t> result_by_canonical;
  for (std::size_t i = 0; i < result.columns.size(); ++i) {
    result_by_canonical.emplace(canonical_column_name(result.columns[i]), i);
  }
  for (const std::string& name : names) {
    std::optional<std::size_t> in_result = result.column_index(name);
    if (!in_result) {
      const auto it = result_by_canonical.find(canonical_column_name(name));
      if (it != result_by_canonical.end()) in_result = it->second;
    }
    if (!in_result) {
      ColumnComparison missing;
      missing.name = name;
      missing.verdict = ColumnVerdict::Missing;
      comparison.columns.push_back(std::move(missing));
      continue;
    }
    comparison.columns.push_back(compare_column(name, column_values(result, *in_result),
                                                column_values(golden, *golden.column_index(name)),
                                                matches, golden_times, options));
    if (result.columns[*in_result] != name) {
      comparison.columns.back().result_name = result.columns[*in_result];
    }
  }
  return comparison;
}

std::string render_comparison(const TableComparison& comparison, const CompareOptions& options) {
  std::size_t name_width = 6;
  for (const ColumnComparison& c : comparison.columns) {
    name_width = std::max(name_width, c.name.size());
  }
  std::string out = fmt::format("rtol {}, atol {}; {} golden rows\n", options.rtol, options.atol,
                                comparison.golden_rows);
  auto line = std::back_inserter(out);
  // Result and golden in shortest round-trip form: the exact values, for updating a golden file.
  fmt::format_to(line, "{:<{}}  {:<7} {:>24} {:>24} {:>10} {:>10}  {}\n", "column", name_width,
                 "verdict", "result", "golden", "|diff|", "allowed", "total_time");
  std::size_t failed = 0;
  for (const ColumnComparison& c : comparison.columns) {
    const bool pass = c.verdict == ColumnVerdict::Pass;
    if (!pass) ++failed;
    fmt::format_to(line, "{:<{}}  {:<7}", c.name, name_width, pass ? "PASS" : "FAIL");
    if (c.verdict == ColumnVerdict::Missing) {
      out += " missing in the result\n";
      continue;
    }
    if (c.has_worst) {
      fmt::format_to(line, " {:>24} {:>24} {:>10.3e} {:>10.3e}  {}", c.result, c.golden,
                     c.difference, c.allowed, c.total_time);
    }
    if (c.failed_rows > 0) {
      fmt::format_to(line, "  ({} of {} rows fail)", c.failed_rows, c.compared_rows);
    }
    if (c.out_of_range_rows > 0) {
      fmt::format_to(line, "  (golden rows outside the result's times: {}, the first at {})",
                     c.out_of_range_rows, c.first_out_of_range_time);
    }
    if (!c.result_name.empty()) fmt::format_to(line, "  (the result's {})", c.result_name);
    out += '\n';
  }
  for (const std::string& problem : comparison.problems) {
    fmt::format_to(line, "FAIL: {}\n", problem);
  }
  fmt::format_to(line, "{}: {} of {} columns fail{}\n", comparison.passed() ? "PASS" : "FAIL",
                 failed, comparison.columns.size(),
                 comparison.problems.empty()
                     ? ""
                     : fmt::format("; table problems: {}", comparison.problems.size()));
  return out;
}

}  // namespace clinch
