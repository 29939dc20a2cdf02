// The yield size F_y(ū) of one connector plasticity (behaviors.md §6.1): an isotropic table
// (piecewise linear, CONSTANT or LINEAR beyond the last point, softening allowed), the exponential
// law, or, without an isotropic option, the constant F_0 of the kinematic option. The return
// mappings evaluate it at every local iteration, on the segment that holds the current iterate.
#pragma once

#include <optional>

#include "src/behavior/piecewise_linear_table.hpp"
#include "src/behavior/yield_function.hpp"
#include "src/model/behavior_model.hpp"

namespace clinch {

class IsotropicHardeningLaw {
 public:
  // §6.1 yield size rule: the ISOTROPIC option when there is one, else the kinematic F_0.
  // A plasticity with neither has failed validation; that is a bug (std::invalid_argument).
  static IsotropicHardeningLaw from_plasticity(const ConnectorPlasticity& plasticity);
  static IsotropicHardeningLaw constant(double f0);

  // Inline: the return mappings call it at every local iteration.
  YieldSample at(double equivalent_plastic) const {
    if (kind_ == Kind::Tabular) {
      const TableSample s = table_->evaluate(equivalent_plastic);
      return {s.value, s.slope};
    }
    return kind_ == Kind::Constant ? YieldSample{f0_, 0.0} : exponential(equivalent_plastic);
  }
  double initial() const { return at(0.0).value; }
  // The table of a tabular law (nullptr otherwise), for callers that evaluate it their way.
  const PiecewiseLinearTable* table() const { return table_ ? &*table_ : nullptr; }

 private:
  YieldSample exponential(double equivalent_plastic) const;
  enum class Kind { Constant, Tabular, Exponential };
  Kind kind_ = Kind::Constant;
  double f0_ = 0, q_inf_ = 0, b_ = 0;
  std::optional<PiecewiseLinearTable> table_;
};

}  // namespace clinch
