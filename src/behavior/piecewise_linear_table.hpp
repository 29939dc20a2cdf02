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

  // evaluate() at x[l] into value[l] and slope[l] for l < kLanes, without branches on x, so
  // that the loops over lanes vectorise (inline: compiled for the vector width of its caller).
  template <int kLanes>
  [[gnu::always_inline]] inline void evaluate_lanes(const double* __restrict x,
                                                    double* __restrict value,
                                                    double* __restrict slope) const;

  std::size_t size() const { return x_.size(); }
  Extrapolation extrapolation() const { return extrapolation_; }

 private:
  static constexpr std::size_t kScannedSegments = 8;
  TableSample evaluate_outside(double x) const;  // x before x_0, at or after x_last, or NaN
  std::size_t interior_segment(double x) const;  // bisection, x_0 ≤ x < x_last
  std::vector<double> x_, y_;
  std::vector<double> slope_;  // slope_[k]: segment [x_k, x_{k+1}]
  // For evaluate_lanes: the slope from x_k on (slope_[k], then the end segment's, §1.2 and the
  // §4.2 rule) and before x_0 (the first segment's under LINEAR, else 0).
  std::vector<double> segment_slope_;
  double before_slope_ = 0;
  Extrapolation extrapolation_;
};

template <int kLanes>
inline void PiecewiseLinearTable::evaluate_lanes(const double* __restrict x,
                                                 double* __restrict value,
                                                 double* __restrict slope) const {
  // Each lane starts on the segment before x_0 and moves to segment k wherever x ≥ x_k; the
  // running segment stays in registers.
  double base[kLanes], start[kLanes], rate[kLanes];
  for (int l = 0; l < kLanes; ++l) {
    base[l] = x_[0];
    start[l] = y_[0];
    rate[l] = before_slope_;
  }
  const std::size_t n = x_.size();
  const double* xs = x_.data();
  const double* ys = y_.data();
  const double* ss = segment_slope_.data();
  for (std::size_t k = 0; k < n; ++k) {
    const double xk = xs[k], yk = ys[k], sk = ss[k];
    for (int l = 0; l < kLanes; ++l) {
      const bool beyond = x[l] >= xk;
      base[l] = beyond ? xk : base[l];
      start[l] = beyond ? yk : start[l];
      rate[l] = beyond ? sk : rate[l];
    }
  }
  for (int l = 0; l < kLanes; ++l) {
    const bool nan = x[l] != x[l];  // a NaN motion reaches the caller's checks, as in evaluate()
    value[l] = nan ? x[l] : start[l] + rate[l] * (x[l] - base[l]);
    slope[l] = nan ? x[l] : rate[l];
  }
}

}  // namespace clinch
