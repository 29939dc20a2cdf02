#include "src/study/convergence_estimate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "src/output/abaqus_labels.hpp"

namespace clinch {
namespace {

constexpr std::size_t kKeyColumns = 4;  // step, increment, step_time, total_time

// The kinds whose columns share a scale: forces with moments, displacements with rotations.
enum class Kind { Load, Motion, Ratio, Own };
Kind kind_of(const std::string& name) {
  const Quantity q = column_quantity(name);
  if (is_force_like(q)) return Kind::Load;
  if (is_motion_like(q)) return Kind::Motion;
  return q == Quantity::Ratio ? Kind::Ratio : Kind::Own;
}

}  // namespace

double value_at(const CsvTable& table, std::size_t time_column, std::size_t column, double time) {
  const auto& rows = table.rows;
  // The first row at or after `time` (total_time never decreases).
  const auto after = std::lower_bound(
      rows.begin(), rows.end(), time,
      [&](const std::vector<double>& row, double t) { return row[time_column] < t; });
  if (after == rows.end()) return rows.back()[column];
  if ((*after)[time_column] == time || after == rows.begin()) return (*after)[column];
  const std::vector<double>& a = *(after - 1);
  const std::vector<double>& b = *after;
  const double w = (time - a[time_column]) / (b[time_column] - a[time_column]);
  return a[column] + w * (b[column] - a[column]);
}

std::optional<StudyEstimate> estimate_errors(const std::vector<const CsvTable*>& tables,
                                             const std::vector<double>& scales, double ratio,
                                             const std::vector<std::string>& columns,
                                             bool keep_negligible, std::string* error) {
  StudyEstimate estimate;
  const std::size_t runs = tables.size();
  if (runs == 0) {
    *error = "no completed run to compare";
    return std::nullopt;
  }
  std::vector<std::size_t> time_index;
  for (const CsvTable* table : tables) {
    const std::optional<std::size_t> t = table->column_index("total_time");
    if (!t || table->rows.empty()) {
      *error = fmt::format("{}: no total_time column or no rows", table->path);
      return std::nullopt;
    }
    time_index.push_back(*t);
  }
  const CsvTable& coarsest = *tables.front();
  for (const auto& row : coarsest.rows) {
    if (estimate.times.empty() || row[time_index[0]] > estimate.times.back()) {
      estimate.times.push_back(row[time_index[0]]);
    }
  }
  std::vector<std::string> names = columns;
  if (names.empty()) {
    names.assign(coarsest.columns.begin() + std::min(kKeyColumns, coarsest.columns.size()),
                 coarsest.columns.end());
  }
  // The order needs the three finest runs one ratio apart.
  const bool consecutive = runs >= 3 &&
                           std::abs(scales[runs - 3] / scales[runs - 2] / ratio - 1.0) < 1e-9 &&
                           std::abs(scales[runs - 2] / scales[runs - 1] / ratio - 1.0) < 1e-9;
  estimate.worst_difference.assign(runs, 0.0);
  estimate.worst_estimated.assign(runs, 0.0);
  estimate.worst_column.assign(runs, "");
  estimate.estimate_is_bound.assign(runs, false);

  // The scale of each kind over every column of the tables (the model's forces and motions,
  // whatever --columns selects), then each selected column's values at the comparison times
  // (values[run][time]) and its own peak.
  const auto column_values = [&](const std::string& name, std::vector<std::vector<double>>& values,
                                 double& peak) {
    values.assign(runs, {});
    peak = 0.0;
    for (std::size_t r = 0; r < runs; ++r) {
      const std::optional<std::size_t> index = tables[r]->column_index(name);
      if (!index) {
        *error = fmt::format("{}: no column '{}'", tables[r]->path, name);
        return false;
      }
      for (double t : estimate.times) {
        const double v = value_at(*tables[r], time_index[r], *index, t);
        values[r].push_back(v);
        peak = std::max(peak, std::abs(v));
      }
    }
    return true;
  };
  std::map<Kind, double> kind_scale{{Kind::Ratio, 1.0}};
  for (std::size_t c = std::min(kKeyColumns, coarsest.columns.size()); c < coarsest.columns.size();
       ++c) {
    const std::string& name = coarsest.columns[c];
    const Kind kind = kind_of(name);
    if (kind == Kind::Own) continue;
    double& scale = kind_scale[kind];
    for (std::size_t r = 0; r < runs; ++r) {
      const std::optional<std::size_t> index = tables[r]->column_index(name);
      if (!index) continue;  // a selected column missing somewhere is reported below
      for (const std::vector<double>& row : tables[r]->rows) {
        if (std::isfinite(row[*index])) scale = std::max(scale, std::abs(row[*index]));
      }
    }
  }
  std::vector<std::vector<std::vector<double>>> all_values(names.size());
  std::vector<double> peaks(names.size());
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (!column_values(names[k], all_values[k], peaks[k])) return std::nullopt;
  }

  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::string& name = names[k];
    ColumnEstimate c;
    c.name = name;
    c.peak = peaks[k];
    const Kind kind = kind_of(name);
    c.scale = kind == Kind::Own ? c.peak : kind_scale[kind];
    const std::vector<std::vector<double>>& values = all_values[k];
    const auto distance = [&](const std::vector<double>& a, const std::vector<double>& b) {
      double d = 0.0;
      for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
      return d;
    };
    const std::vector<double>& finest = values[runs - 1];
    c.difference.assign(runs, 0.0);
    c.estimated.assign(runs, 0.0);
    if (c.peak == 0.0) {
      c.status = OrderStatus::ZeroColumn;
      estimate.columns.push_back(std::move(c));
      continue;
    }
    if (!keep_negligible && c.peak <= kNegligibleColumn * c.scale) {
      c.status = OrderStatus::Negligible;
      estimate.columns.push_back(std::move(c));
      continue;
    }
    for (std::size_t r = 0; r < runs; ++r) c.difference[r] = distance(values[r], finest) / c.scale;
    std::vector<double> limit = finest;
    if (consecutive) {
      const double d1 = distance(values[runs - 3], values[runs - 2]) / c.scale;
      const double d2 = c.difference[runs - 2];
      if (d2 <= kRoundOff) {
        c.status = OrderStatus::Agree;
      } else if (d1 > d2) {
        c.order = std::log(d1 / d2) / std::log(ratio);
        c.status = c.order >= kMinOrder && c.order <= kMaxOrder ? OrderStatus::Observed
                                                                : OrderStatus::NotObserved;
      } else {
        c.status = OrderStatus::NotObserved;
      }
      if (c.status == OrderStatus::Observed) {
        const double factor = 1.0 / (std::pow(ratio, c.order) - 1.0);
        for (std::size_t i = 0; i < limit.size(); ++i) {
          limit[i] += (finest[i] - values[runs - 2][i]) * factor;
        }
      }
    }
    for (std::size_t r = 0; r < runs; ++r) c.estimated[r] = distance(values[r], limit) / c.scale;
    const bool bound = c.status == OrderStatus::NotObserved || c.status == OrderStatus::TooFewRuns;
    for (std::size_t r = 0; r < runs; ++r) {
      estimate.worst_difference[r] = std::max(estimate.worst_difference[r], c.difference[r]);
      if (bound) estimate.estimate_is_bound[r] = true;
      if (c.estimated[r] > estimate.worst_estimated[r] || estimate.worst_column[r].empty()) {
        estimate.worst_estimated[r] = std::max(estimate.worst_estimated[r], c.estimated[r]);
        estimate.worst_column[r] = c.name;
      }
    }
    estimate.columns.push_back(std::move(c));
  }
  return estimate;
}

}  // namespace clinch
