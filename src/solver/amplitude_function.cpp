#include "src/solver/amplitude_function.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace clinch {

AmplitudeFunction::AmplitudeFunction(const Amplitude& amplitude)
    : definition_(amplitude.definition),
      total_time_(amplitude.total_time),
      times_(amplitude.times),
      values_(amplitude.values) {
  if (!amplitude.valid || times_.empty() || times_.size() != values_.size()) {
    throw std::invalid_argument(
        fmt::format("amplitude '{}' evaluated without valid data", amplitude.name.display));
  }
}

double AmplitudeFunction::value_at(double t) const {
  // Index of the last point with time ≤ t. With a repeated time (a TABULAR jump) this is the
  // later of the two points, so the later value applies from that time on (§8).
  const auto above = std::upper_bound(times_.begin(), times_.end(), t);
  if (above == times_.begin()) return values_.front();  // before t₁: a₁
  const auto j = static_cast<std::size_t>(above - times_.begin()) - 1;
  if (j + 1 == times_.size()) return values_.back();  // at or after tₙ: aₙ
  // t_j ≤ t < t_{j+1}, so the interval has positive length.
  const double xi = (t - times_[j]) / (times_[j + 1] - times_[j]);
  const double da = values_[j + 1] - values_[j];
  if (definition_ == AmplitudeDefinition::SmoothStep) {
    return values_[j] + da * xi * xi * xi * (10.0 - 15.0 * xi + 6.0 * xi * xi);
  }
  // TABULAR, and EQUALLY SPACED on its generated points.
  return values_[j] + da * xi;
}

}  // namespace clinch
