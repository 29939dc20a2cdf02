#include "src/behavior/damage/damage_initiation_criterion.hpp"

#include <utility>

namespace clinch {

DamageInitiationCriterion::DamageInitiationCriterion(const DamageInitiation& initiation,
                                                     std::optional<ConnectorPotential> potential)
    : criterion_(initiation.criterion),
      component_(initiation.component),
      potential_(std::move(potential)) {
  // §7.1: a blank limit is no limit (∓1e36), so that side gives r = 0.
  if (initiation.lower && *initiation.lower != 0) inverse_lower_ = 1.0 / *initiation.lower;
  if (initiation.upper && *initiation.upper != 0) inverse_upper_ = 1.0 / *initiation.upper;
  if (initiation.plastic_motion > 0) inverse_plastic_motion_ = 1.0 / initiation.plastic_motion;
}

ComponentMask DamageInitiationCriterion::components() const {
  if (component_ > 0) return component_bit(component_);
  return potential_ ? potential_->components() : ComponentMask{0};
}

CriterionValue DamageInitiationCriterion::evaluate(const CriterionInput& in) const {
  if (criterion_ == DamageInitiation::Criterion::PlasticMotion) {
    return {in.equivalent * MotionSensitive(inverse_plastic_motion_), 1.0};
  }
  const SensitiveVector& x =
      criterion_ == DamageInitiation::Criterion::Force ? in.force : in.motion;
  MotionSensitive v;
  if (component_ > 0) {
    v = x[static_cast<std::size_t>(component_ - 1)];
  } else {
    v = evaluate_potential(*potential_, x);
  }
  // r = v/limit on the side of its sign (F_L ≤ 0 makes r ≥ 0 in compression).
  const double sign = v.value >= 0 ? 1.0 : -1.0;
  return {v * MotionSensitive(sign > 0 ? inverse_upper_ : inverse_lower_), sign};
}

}  // namespace clinch
