// A compiled derived component g(c) (derived-components-and-potentials.md §1): the terms of one
// NAME in one behaviour block, flattened after *PARAMETER substitution, with value, gradient and
// Hessian with respect to the six intrinsic components (§1.3, §1.4) and the subgradient choices
// of the non-smooth points (§1.4 table). Evaluation never allocates.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "base/small_types.hpp"
#include "src/model/behavior_model.hpp"
#include "src/model/section_model.hpp"

namespace clinch {

class DerivedComponent {
 public:
  // The terms of `behavior` named `key` (Name::key identity), in deck order. The model must have
  // passed validation; an unknown name is a bug and throws std::invalid_argument.
  static DerivedComponent compile(const ConnectorBehavior& behavior, std::string_view key);

  // g(c). `gradient` and `hessian` (when not null) receive ∂g/∂c and ∂²g/∂c² (6×6, zero outside
  // the listed components). Zero tests use the relative threshold of §1.4 (r ≤ 1e-12·m, m the
  // largest |y_j| over the whole derived component).
  double evaluate(const Vector6& c, Vector6* gradient, Matrix6* hessian) const;
  double value(const Vector6& c) const { return evaluate(c, nullptr, nullptr); }

  ComponentMask components() const { return components_; }  // union of the listed components
  DerivedType type() const { return type_; }
  bool has_hessian() const { return has_norm_term_; }  // only NORM terms have curvature

 private:
  friend class ConnectorPotential;

  // The work of evaluate for a caller that owns the output: `gradient` (when not null) is
  // overwritten, and `weight`·∂²g/∂c² is added to `hessian` (when not null) on the listed
  // components only. The potential's chain rule (§2.4) adds n_i·∇²E_i this way.
  double evaluate_into(const Vector6& c, Vector6* gradient, Matrix6* hessian, double weight) const;

  struct Term {
    DerivedOperator op = DerivedOperator::Norm;
    double sign = 1.0;
    int count = 0;
    std::array<int, 6> slot{};  // component − 1
    std::array<double, 6> coefficient{};
  };
  std::vector<Term> terms_;
  ComponentMask components_ = 0;
  DerivedType type_ = DerivedType::Norm;
  bool has_norm_term_ = false;
};

}  // namespace clinch
