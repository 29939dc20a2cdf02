#include "src/assembly/active_set_updates.hpp"

#include <algorithm>
#include <cmath>

namespace clinch {

bool update_stops(const AnalysisPlan& plan, const IncrementConditions& conditions,
                  AnalysisState& state) {
  bool changed = false;
  for (std::size_t c = 0; c < plan.connectors.size(); ++c) {
    const ConnectorRecord& r = plan.connectors[c];
    const ConnectorResult& out = state.results[c];
    const ComponentMask motion = conditions.connector(plan.first_connector + c).motion;
    for (int i = 1; i <= 6; ++i) {
      const ConnectorStopLimits& stop = r.stop(i);
      if ((!stop.lower && !stop.upper) || has_component(motion, i)) continue;
      auto& status = state.active_sets[c].status[static_cast<std::size_t>(i - 1)];
      if (status == static_cast<std::uint8_t>(StopStatus::Locked)) continue;
      // §5.1: tol_p = 1e-8·max(1, |limit|), tol_f = 1e-8·max(1, max|f|).
      const double p = out.position[i - 1];
      const double lambda = out.multiplier[i - 1];
      const double tol_f = 1e-8 * std::max(1.0, out.total.cwiseAbs().maxCoeff());
      auto violated = [&](const std::optional<double>& limit, double sign) {
        return limit && sign * (p - *limit) > 1e-8 * std::max(1.0, std::abs(*limit));
      };
      std::uint8_t next = status;
      if (status == static_cast<std::uint8_t>(StopStatus::Upper) && lambda < -tol_f) next = 0;
      if (status == static_cast<std::uint8_t>(StopStatus::Lower) && lambda > tol_f) next = 0;
      if (next == 0 && violated(stop.upper, 1.0)) {
        next = static_cast<std::uint8_t>(StopStatus::Upper);
      }
      if (next == 0 && violated(stop.lower, -1.0)) {
        next = static_cast<std::uint8_t>(StopStatus::Lower);
      }
      if (next != status) {
        status = next;
        changed = true;
      }
    }
  }
  return changed;
}

void engage_locks(const AnalysisPlan& plan, AnalysisState& state) {
  for (std::size_t c = 0; c < plan.connectors.size(); ++c) {
    const ConnectorRecord& r = plan.connectors[c];
    if (r.locks.empty()) continue;
    const ConnectorResult& out = state.results[c];
    ConnectorActiveSet& set = state.active_sets[c];
    for (const ConnectorLockRule& rule : r.locks) {
      const double p = out.position[rule.component - 1];
      const double f = out.total[rule.component - 1];
      const ConnectorCriterionBounds& b = rule.bounds;
      const bool met = (b.position_lower && p <= *b.position_lower) ||
                       (b.position_upper && p >= *b.position_upper) ||
                       (b.force_lower && f <= *b.force_lower) ||
                       (b.force_upper && f >= *b.force_upper);
      if (!met) continue;
      for (int i = 1; i <= 6; ++i) {
        if (!has_component(rule.locks, i)) continue;
        const auto slot = static_cast<std::size_t>(i - 1);
        set.status[slot] = set.status_n[slot] = static_cast<std::uint8_t>(StopStatus::Locked);
        set.lock_position[i - 1] = out.position[i - 1];
      }
    }
  }
}

}  // namespace clinch
