// The Euclidean norm of values given one at a time, kept as a scale and a sum of squares relative
// to it (as LAPACK's dnrm2 does): a plain sum of squares overflows past entries of about 1e154 and
// loses entries below about 1e-154, so that a finite residual would be judged by an infinite or a
// zero norm. A NaN makes the norm NaN and an infinity makes it infinite.
#pragma once

#include <cmath>
#include <limits>

namespace clinch {

class ScaledNorm {
 public:
  void add(double value) {
    const double a = std::abs(value);
    if (std::isnan(a)) {
      nan_ = true;
    } else if (std::isinf(a)) {
      infinite_ = true;
    } else if (a > scale_) {
      const double r = scale_ / a;
      sum_ = 1.0 + sum_ * r * r;
      scale_ = a;
    } else if (a > 0.0) {
      const double r = a / scale_;
      sum_ += r * r;
    }
  }
  double value() const {
    if (nan_) return std::numeric_limits<double>::quiet_NaN();
    if (infinite_) return std::numeric_limits<double>::infinity();
    return scale_ * std::sqrt(sum_);
  }

 private:
  double scale_ = 0.0, sum_ = 0.0;
  bool nan_ = false, infinite_ = false;
};

}  // namespace clinch
