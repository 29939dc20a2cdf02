// The history rows of a run (output-variables.md §1.4): at each converged increment, the columns
// due there, evaluated on the connector system's converged state and written to the table. The
// step driver tells it when an increment converged and never sees the system it reads.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "src/output/history_columns.hpp"
#include "src/output/history_table.hpp"

namespace clinch {

class HistoryRecorder {
 public:
  HistoryRecorder(HistoryColumns& columns, HistoryTable& table, ConnectorSystem& system)
      : columns_(columns), table_(table), system_(system) {}

  void begin_step(std::size_t step) { columns_.begin_step(step); }
  // The row of increment `increment` of step `step` (0: the initial state), if one is due.
  void converged(int step, int increment, double step_time, double total_time, bool last);
  // The row of a linear perturbation step (increment 1, step time 0): each column due there as
  // (y(+h) − y(−h))/2h over the states that `at(±h)` sets, the derivative along the response
  // (docs/perturbation.md). False when `at` failed; no row is written then.
  bool perturbation(int step, double total_time, double h, const std::function<bool(double)>& at);
  const OutputFile& file() const { return table_.file(); }
  bool sync() { return table_.sync(); }

 private:
  HistoryColumns& columns_;
  HistoryTable& table_;
  ConnectorSystem& system_;
  std::vector<double> values_;
};

}  // namespace clinch
