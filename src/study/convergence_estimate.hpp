// Error estimates of an increment-size study: the history tables of a ladder of runs (coarsest
// first, each scale the previous one divided by a fixed ratio) compared column by column with the
// finest run, and Richardson extrapolation where the three finest runs show a convergence order.
//
// All tables are compared at the times of the coarsest run (rows matched by total_time, the others
// interpolated linearly, as `clinch compare` does), so that the whole path counts, not only its
// end. A column's error is the largest difference over those times divided by the scale of its
// kind in the model (src/output/abaqus_labels.hpp): forces and moments by the largest |value| of
// any force or moment column in any run, motions by the largest motion, damage and criteria by 1
// (or their largest value when above). A column that is zero next to that scale (the total force
// of a component a motion drives, the residual of a constraint) would otherwise read its
// round-off as a large relative error; it is left out and listed.
//
// With d1 = |v(F-2) - v(F-1)| and d2 = |v(F-1) - v(F)| (largest over the times), the observed
// order is p = log(d1/d2) / log(ratio). Where p is plausible (kMinOrder..kMaxOrder), the limit is
// v(F) + (v(F) - v(F-1)) / (ratio^p - 1) and each run's estimated error is its largest distance
// from that limit. Elsewhere the estimate is the difference from the finest run, a lower bound that
// the study flags.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "src/output/csv_table.hpp"

namespace clinch {

inline constexpr double kMinOrder = 0.3;
inline constexpr double kMaxOrder = 10.0;
// Differences below this fraction of a column's scale are round-off: the runs agree.
inline constexpr double kRoundOff = 1e-10;
// A column whose largest |value| is at most this fraction of the scale of its kind is zero to
// round-off: below the default rtol of `clinch compare` (1e-6), which could not tell it from zero
// either.
inline constexpr double kNegligibleColumn = 1e-6;

enum class OrderStatus {
  Observed,     // p plausible: Richardson estimate
  Agree,        // the finest runs agree to round-off: the finest run's error is taken as zero
  NotObserved,  // differences do not shrink at a plausible rate: the estimate is a lower bound
  TooFewRuns,   // fewer than three consecutive completed runs at the fine end
  ZeroColumn,   // the column is zero in every run: no relative error
  Negligible,   // zero to round-off next to the scale of its kind: left out (kNegligibleColumn)
};

struct ColumnEstimate {
  std::string name;
  double scale = 0.0;  // the scale of its kind: largest |value| of such columns over runs and times
  double peak = 0.0;   // its own largest |value| over runs and times
  OrderStatus status = OrderStatus::TooFewRuns;
  double order = 0.0;              // p when Observed
  std::vector<double> difference;  // per run: largest |v - v(finest)| / scale
  std::vector<double> estimated;   // per run: estimated error / scale
};

struct StudyEstimate {
  std::vector<double> times;  // the comparison times (the coarsest run's rows)
  std::vector<ColumnEstimate> columns;
  // Per run, the worst column: its relative difference from the finest run, the estimated
  // error, and whether every column's estimate rests on an observed order (or on agreement).
  std::vector<double> worst_difference, worst_estimated;
  std::vector<std::string> worst_column;
  std::vector<bool> estimate_is_bound;
};

// `tables` are completed runs, coarsest first; `scales` their increment scales. The order needs
// the three finest runs to be consecutive settings (scales a factor `ratio` apart, no failed
// setting between them). `columns` selects the columns by name (all history
// columns when empty). With `keep_negligible` false, columns zero to round-off are left out
// (status Negligible, no estimate). Returns nullopt and sets `error` when a table lacks total_time or a
// selected column.
std::optional<StudyEstimate> estimate_errors(const std::vector<const CsvTable*>& tables,
                                             const std::vector<double>& scales, double ratio,
                                             const std::vector<std::string>& columns,
                                             bool keep_negligible, std::string* error);

// The value of `column` in `table` at `time`, interpolated linearly between the rows around it
// (the first row after a run that ended early: the run's last value).
double value_at(const CsvTable& table, std::size_t time_column, std::size_t column, double time);

}  // namespace clinch
