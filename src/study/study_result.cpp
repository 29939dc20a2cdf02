#include "src/study/study_result.hpp"

#include <fmt/format.h>

#include <cmath>

namespace clinch {

int setting_work(const StatusRecord& status) {
  return static_cast<int>(status.attempts.size()) + status.total_iterations();
}

std::optional<std::size_t> cheapest_setting(const StudyResult& result, double rtol) {
  if (!result.estimate) return std::nullopt;
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < result.settings.size(); ++i) {
    const StudySetting& s = result.settings[i];
    if (s.run < 0 || !s.status) continue;
    if (!(result.estimate->worst_estimated[static_cast<std::size_t>(s.run)] < rtol)) continue;
    if (!best) {
      best = i;
      continue;
    }
    const StudySetting& b = result.settings[*best];
    const int work = setting_work(*s.status), best_work = setting_work(*b.status);
    if (work < best_work ||
        (work == best_work && s.outcome.wall_seconds < b.outcome.wall_seconds)) {
      best = i;
    }
  }
  return best;
}

std::string scale_text(double scale) {
  if (scale == 1.0) return "1";
  const double inverse = 1.0 / scale;
  if (scale < 1.0 && std::abs(inverse - std::round(inverse)) < 1e-9 * inverse) {
    return fmt::format("1/{}", static_cast<long long>(std::round(inverse)));
  }
  return fmt::format("{:.4g}", scale);
}

}  // namespace clinch
