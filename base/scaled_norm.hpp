// The Euclidean norm of values given one at a time, kept as a scale and a sum of squares relative
// to it (as LAPACK's dnrm2 does): a plain sum of squares overflows past entries of about 1e154 and
// loses entries below about 1e-154, so that a finite residual would be judged by an infinite or a
// zero norm. A NaN makes the norm NaN and an infinity makes it infinite.
#pragma once

#include <array>
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
  // The norm of this one's values and those `other` was given (another process's share).
  void merge(const ScaledNorm& other) {
    nan_ = nan_ || other.nan_;
    infinite_ = infinite_ || other.infinite_;
    if (other.scale_ > scale_) {
      const double r = scale_ / other.scale_;
      sum_ = other.sum_ + sum_ * r * r;
      scale_ = other.scale_;
    } else if (other.scale_ > 0.0) {
      const double r = other.scale_ / scale_;
      sum_ += other.sum_ * r * r;
    }
  }
  // The state as four numbers, and back (to send it to another process).
  std::array<double, 4> parts() const {
    return {scale_, sum_, nan_ ? 1.0 : 0.0, infinite_ ? 1.0 : 0.0};
  }
  static ScaledNorm of_parts(const double* parts) {
    ScaledNorm n;
    n.scale_ = parts[0];
    n.sum_ = parts[1];
    n.nan_ = parts[2] != 0.0;
    n.infinite_ = parts[3] != 0.0;
    return n;
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
