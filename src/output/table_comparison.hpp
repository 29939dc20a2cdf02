// Column-by-column comparison of a history table against a golden one, the check behind
// `clinch compare` and the verification decks (cli-contract.md `clinch compare`): rows matched by
// total_time, the result interpolated linearly at golden times, a mixed absolute/relative test.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "src/output/csv_table.hpp"

namespace re2 {
class RE2;
}

namespace clinch {

// Defaults: rtol near the accuracy of a converged Newton solution with tight tolerances, atol
// only there to let columns that are zero throughout pass with round-off.
inline constexpr double kDefaultRtol = 1e-6;
inline constexpr double kDefaultAtol = 1e-12;

struct CompareOptions {
  double rtol = kDefaultRtol;
  double atol = kDefaultAtol;
  // Golden columns to compare: those whose whole name `columns` matches; all when null.
  std::shared_ptr<const re2::RE2> columns;
};

// Compiles a --columns pattern. RE2 rather than std::regex: the pattern and the column names come
// from the user, and RE2 matches in time linear in the name with bounded memory, where a
// backtracking engine can take exponential time or overflow the stack on a long name. Returns
// null and sets `error` when RE2 rejects the pattern.
std::shared_ptr<const re2::RE2> compile_column_pattern(std::string_view pattern,
                                                       std::string* error);

enum class ColumnVerdict { Pass, Fail, Missing };

struct ColumnComparison {
  std::string name;
  std::string result_name;  // the result's column when it is named the other way (CTF4@7)
  ColumnVerdict verdict = ColumnVerdict::Pass;
  std::size_t failed_rows = 0;
  std::size_t compared_rows = 0;  // golden rows inside the result's time range
  // The worst golden row (the largest |diff| / allowed) among the compared rows.
  bool has_worst = false;
  double result = 0.0;
  double golden = 0.0;
  double difference = 0.0;
  double allowed = 0.0;
  double total_time = 0.0;
  // Golden rows whose time lies outside the result's time range; each fails the column.
  std::size_t out_of_range_rows = 0;
  double first_out_of_range_time = 0.0;
};

struct TableComparison {
  std::vector<ColumnComparison> columns;
  std::vector<std::string> problems;  // failures of the whole table (a golden step not run)
  std::size_t golden_rows = 0;

  bool passed() const;
};

// Compares `result` with `golden`. Returns nullopt and sets `error` when the tables cannot be
// compared at all: a key column missing, total_time decreasing, a golden table without rows, or
// no golden column left to compare (after the --columns filter). These are usage/input errors.
std::optional<TableComparison> compare_tables(const CsvTable& result, const CsvTable& golden,
                                              const CompareOptions& options, std::string* error);

// The report `clinch compare` prints: tolerances, one line per compared column with its worst
// deviation and PASS/FAIL, the table-level problems and a summary line.
std::string render_comparison(const TableComparison& comparison, const CompareOptions& options);

}  // namespace clinch
