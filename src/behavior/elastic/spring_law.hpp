// The force law of a *SPRING, F(Δ), or of a *DASHPOT, F(v) (keywords.md §7, behaviors.md §8):
// linear F = kΔ (c v) with k of any sign, or a piecewise-linear table held constant, with zero
// tangent, outside its range. The element kinematics (spring_element) turn Δ, or its rate, into
// nodal forces and stiffness.
#pragma once

#include <optional>

#include "src/behavior/piecewise_linear_table.hpp"
#include "src/model/section_model.hpp"

namespace clinch {

struct SpringResponse {
  double force = 0;      // F
  double stiffness = 0;  // k' = dF/dΔ (right-hand slope at a table breakpoint)
  bool outside = false;  // Δ beyond the table (W0705 once the increment converges)
};

class SpringLaw {
 public:
  // `spring` must be valid (validation filled stiffness or table); otherwise
  // std::invalid_argument, because running an unvalidated model is a bug.
  explicit SpringLaw(const SpringProperty& spring);

  SpringResponse evaluate(double delta) const {
    if (!table_) return {stiffness_ * delta, stiffness_, false};
    const TableSample s = table_->evaluate(delta);
    return {s.value, s.slope, s.outside};
  }

  bool nonlinear() const { return table_.has_value(); }

 private:
  double stiffness_ = 0;
  std::optional<PiecewiseLinearTable> table_;
};

}  // namespace clinch
