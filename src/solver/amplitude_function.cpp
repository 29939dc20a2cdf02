#include "src/solver/amplitude_function.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace clinch {

AmplitudeFunction::AmplitudeFunction(const Amplitude& amplitude)
    : definition_(amplitude.definition),
      total_time_(amplitude.total_time),
      times_(amplitude.times),
      values_(amplitude.values),
      formula_(amplitude.formula) {
  if (!amplitude.valid || (!is_formula(definition_) && times_.empty()) || times_.size() != values_.size()) {
    throw std::invalid_argument(
        fmt::format("amplitude '{}' evaluated without valid data", amplitude.name.display));
  }
}

double AmplitudeFunction::value_at(double t) const {
  if (is_formula(definition_)) return formula_value(t);
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

// The formulas of keywords.md §8 (Abaqus "Amplitude curves"): A0 until the start time t0.
double AmplitudeFunction::formula_value(double t) const {
  const AmplitudeFormula& f = formula_;
  const double s = t - f.start_time;
  switch (definition_) {
    case AmplitudeDefinition::Periodic: {
      if (s < 0) return f.initial;
      double a = f.initial;
      for (std::size_t n = 0; n < f.cosines.size(); ++n) {
        const double phase = static_cast<double>(n + 1) * f.omega * s;
        a += f.cosines[n] * std::cos(phase) + f.sines[n] * std::sin(phase);
      }
      return a;
    }
    case AmplitudeDefinition::Modulated:
      if (s <= 0) return f.initial;
      return f.initial + f.magnitude * std::sin(f.omega * s) * std::sin(f.omega2 * s);
    default:  // Decay
      if (s < 0) return f.initial;
      return f.initial + f.magnitude * std::exp(-s / f.decay_time);
  }
}

}  // namespace clinch
