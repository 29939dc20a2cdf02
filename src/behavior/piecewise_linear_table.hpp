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

  // Inline for the interior, which the constitutive updates hit at every local iteration; a
  // short table is scanned, a long one bisected.
  TableSample evaluate(double x) const {
    const std::size_t last = x_.size() - 1;
    if (!(x >= x_[0] && x < x_[last])) return evaluate_outside(x);  // NaN included
    // x lies in [x_k, x_{k+1}) with k + 1 the first abscissa greater than x, which gives the
    // right-hand segment at a breakpoint.
    std::size_t k = 0;
    if (last <= kScannedSegments) {
      while (!(x < x_[k + 1])) ++k;
    } else {
      k = interior_segment(x);
    }
    return {y_[k] + slope_[k] * (x - x_[k]), slope_[k], false};
  }

  std::size_t size() const { return x_.size(); }
  Extrapolation extrapolation() const { return extrapolation_; }

 private:
  static constexpr std::size_t kScannedSegments = 8;
  TableSample evaluate_outside(double x) const;  // x before x_0, at or after x_last, or NaN
  std::size_t interior_segment(double x) const;  // bisection, x_0 ≤ x < x_last
  std::vector<double> x_, y_;
  std::vector<double> slope_;  // slope_[k]: segment [x_k, x_{k+1}]
  Extrapolation extrapolation_;
};

}  // namespace clinch
