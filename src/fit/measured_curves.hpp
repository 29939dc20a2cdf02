// The measured curves of a fit (`clinch fit --data`, docs/fit.md "Data files"): a table whose
// header names history columns as a run writes them (cli-contract.md "History table"; Abaqus
// labels such as CTM1@7 accepted), one of them the abscissa (total_time unless --x names another,
// e.g. CU1@1), every other one a measured curve. The key columns step, increment and step_time
// are ignored. The residual of a run is, per measured value, (model − measured) / scale, the
// model's curve interpolated linearly at the measured abscissa.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "src/output/csv_table.hpp"

namespace clinch {

struct MeasuredColumn {
  std::size_t index = 0;  // in the data table
  double scale = 1.0;     // the residual's unit: --scale, else the largest |measured value|
};

struct MeasuredCurves {
  CsvTable table;
  std::size_t abscissa = 0;  // its column in the data table
  std::vector<MeasuredColumn> columns;

  std::size_t point_count() const { return table.rows.size() * columns.size(); }
  // "PATH:LINE:COL" of a header name, for messages.
  std::string header_position(std::size_t column) const;
};

// Reads a data file. `scales` maps column names (either labelling) to their scale. Returns
// nullopt and sets `error` ("PATH:LINE:COL: error: ...") for an unreadable file, a missing
// abscissa column, no measured column, no rows, a value that is not finite, a --scale name that
// is not a column or a scale that is not > 0, or a measured column that is zero throughout and
// has no --scale.
std::optional<MeasuredCurves> read_measured_curves(const std::string& path,
                                                   const std::string& abscissa,
                                                   const std::map<std::string, double>& scales,
                                                   std::string* error);

// Checks that a run's history table (`run`, of the deck named `deck`) has the abscissa and every
// measured column; the message points at the header name that is missing.
bool check_columns_written(const MeasuredCurves& curves, const CsvTable& run,
                           const std::string& deck, std::string* error);

// The model's values at the measured points (row by row, column by column): the run's column
// interpolated linearly at each measured abscissa. Nullopt, with `error`, when the run's abscissa
// does not reach a measured one or, other than total_time, is not monotonic (the model then has
// no single value there).
std::optional<std::vector<double>> model_values(const MeasuredCurves& curves, const CsvTable& run,
                                                std::string* error);

// (model − measured) / scale for the values model_values gives, appended to `residuals`.
void append_residuals(const MeasuredCurves& curves, const std::vector<double>& model,
                      std::vector<double>& residuals);

}  // namespace clinch
