#include "src/behavior/piecewise_linear_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace clinch {

PiecewiseLinearTable::PiecewiseLinearTable(std::vector<double> x, std::vector<double> y,
                                           Extrapolation extrapolation)
    : x_(std::move(x)), y_(std::move(y)), extrapolation_(extrapolation) {
  if (x_.empty() || x_.size() != y_.size()) {
    throw std::invalid_argument(fmt::format(
        "piecewise-linear table with {} abscissae and {} values", x_.size(), y_.size()));
  }
  slope_.reserve(x_.size() - 1);
  for (std::size_t k = 0; k + 1 < x_.size(); ++k) {
    if (!(x_[k + 1] > x_[k])) {
      throw std::invalid_argument(
          fmt::format("piecewise-linear table abscissae not strictly increasing ({} after {})",
                      x_[k + 1], x_[k]));
    }
    slope_.push_back((y_[k + 1] - y_[k]) / (x_[k + 1] - x_[k]));
  }
}

PiecewiseLinearTable PiecewiseLinearTable::from_points(std::span<const TablePoint> points,
                                                       Extrapolation extrapolation) {
  std::vector<double> x, y;
  x.reserve(points.size());
  y.reserve(points.size());
  for (const TablePoint& p : points) {
    x.push_back(p.at);
    y.push_back(p.value);
  }
  return PiecewiseLinearTable(std::move(x), std::move(y), extrapolation);
}

TableSample PiecewiseLinearTable::evaluate_outside(double x) const {
  // A NaN motion must reach the caller's convergence checks rather than become an end value.
  if (std::isnan(x)) return {x, x, true};
  const std::size_t n = x_.size();
  // A one-row table is a constant (§1.2): no end segment to continue.
  if (n == 1) return {y_[0], 0.0, x != x_[0]};
  const bool linear = extrapolation_ == Extrapolation::Linear;
  if (x < x_[0]) {
    return linear ? TableSample{y_[0] + slope_[0] * (x - x_[0]), slope_[0], true}
                  : TableSample{y_[0], 0.0, true};
  }
  // At the last abscissa the segment on the right is the extrapolated one (§4.2 rule), so its
  // slope applies there too; the point itself is still inside the table.
  const double end_slope = linear ? slope_[n - 2] : 0.0;
  return {y_[n - 1] + end_slope * (x - x_[n - 1]), end_slope, x > x_[n - 1]};
}

std::size_t PiecewiseLinearTable::interior_segment(double x) const {
  const auto above = std::upper_bound(x_.begin(), x_.end(), x);
  return static_cast<std::size_t>(above - x_.begin()) - 1;
}

}  // namespace clinch
