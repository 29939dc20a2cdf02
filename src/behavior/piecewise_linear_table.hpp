// A piecewise-linear table y(x) with its end extrapolation (behaviors.md §1.2). Nonlinear
// elasticity (§4.2), nonlinear springs (keywords.md §7) and tabular hardening and damage read
// their data through it during the constitutive update, so evaluation does not allocate.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "src/model/behavior_model.hpp"

namespace clinch {

struct TableSample {
  double value = 0;
  double slope = 0;      // dy/dx; at a breakpoint, the slope of the segment on the right
  bool outside = false;  // x lies strictly before the first or after the last abscissa
};

class PiecewiseLinearTable {
 public:
  // `x` strictly increasing, `y` of the same non-zero size (the reader has checked both; a
  // violation is a bug and throws std::invalid_argument).
  PiecewiseLinearTable(std::vector<double> x, std::vector<double> y, Extrapolation extrapolation);
  // The dependent variable is TablePoint::value, the independent one TablePoint::at.
  static PiecewiseLinearTable from_points(std::span<const TablePoint> points,
                                          Extrapolation extrapolation);

  TableSample evaluate(double x) const;

  std::size_t size() const { return x_.size(); }
  Extrapolation extrapolation() const { return extrapolation_; }

 private:
  std::vector<double> x_, y_;
  std::vector<double> slope_;  // slope_[k]: segment [x_k, x_{k+1}]
  Extrapolation extrapolation_;
};

}  // namespace clinch
