#include "src/output/history_recorder.hpp"

#include <cmath>
#include <limits>

namespace clinch {

void HistoryRecorder::converged(int step, int increment, double step_time, double total_time,
                                bool last) {
  if (!columns_.due(increment, step_time, last)) return;
  columns_.evaluate(system_, increment, step_time, last, values_);
  table_.write_row(step, increment, step_time, total_time, values_);
}

bool HistoryRecorder::perturbation(int step, double total_time, double h,
                                   const std::function<bool(double)>& at) {
  // NaN marks the columns not due in this step: they keep their last values, as in any row.
  std::vector<double> plus(values_.size(), std::numeric_limits<double>::quiet_NaN());
  std::vector<double> minus = plus;
  if (!at(h)) return false;
  columns_.evaluate(system_, 1, 0.0, true, plus);
  if (!at(-h)) return false;
  columns_.evaluate(system_, 1, 0.0, true, minus);
  values_.resize(plus.size(), 0.0);
  for (std::size_t i = 0; i < plus.size(); ++i) {
    if (!std::isnan(plus[i]) || !std::isnan(minus[i])) values_[i] = (plus[i] - minus[i]) / (2 * h);
  }
  table_.write_row(step, 1, 0.0, total_time, values_);
  return true;
}

}  // namespace clinch
