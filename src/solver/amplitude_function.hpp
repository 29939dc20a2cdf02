// Evaluation of an *AMPLITUDE (keywords.md §8) at a point of the step: the step driver scales the
// magnitudes of boundary conditions and loads by it (§13). The reader has already applied the
// SCALE/SHIFT parameters (to the points, or to the constants of a formula) and generated the
// times of EQUALLY SPACED data.
#pragma once

#include <vector>

#include "src/model/history_model.hpp"

namespace clinch {

class AmplitudeFunction {
 public:
  // `amplitude` must be valid, with at least one point unless it is a formula; otherwise
  // std::invalid_argument.
  explicit AmplitudeFunction(const Amplitude& amplitude);

  // The value at the amplitude's own time variable (TIME=STEP TIME or TOTAL TIME).
  double value(double step_time, double total_time) const {
    return value_at(total_time_ ? total_time : step_time);
  }
  // The value at time t of that variable.
  double value_at(double t) const;

 private:
  AmplitudeDefinition definition_;
  bool total_time_;
  std::vector<double> times_, values_;
  AmplitudeFormula formula_;

  double formula_value(double t) const;
};

}  // namespace clinch
