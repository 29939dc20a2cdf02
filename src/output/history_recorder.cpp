#include "src/output/history_recorder.hpp"

namespace clinch {

void HistoryRecorder::converged(int step, int increment, double step_time, double total_time,
                                bool last) {
  if (!columns_.due(increment, last)) return;
  columns_.evaluate(system_, increment, last, values_);
  table_.write_row(step, increment, step_time, total_time, values_);
}

}  // namespace clinch
