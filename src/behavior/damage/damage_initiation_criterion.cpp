#include "src/behavior/damage/damage_initiation_criterion.hpp"

#include <utility>

namespace clinch {

DamageInitiationCriterion::DamageInitiationCriterion(const DamageInitiation& initiation,
                                                     std::optional<ConnectorPotential> potential)
    : criterion_(initiation.criterion),
      component_(initiation.component),
      potential_(std::move(potential)) {
  // §7.1: a blank limit is no limit (∓1e36), so that side gives r = 0.
  if (initiation.lower) lower_ = *initiation.lower;
  if (initiation.upper) upper_ = *initiation.upper;
  plastic_motion_ = initiation.plastic_motion;
}

ComponentMask DamageInitiationCriterion::components() const {
  if (component_ > 0) return component_bit(component_);
  return potential_ ? potential_->components() : ComponentMask{0};
}

CriterionValue DamageInitiationCriterion::evaluate(const CriterionInput& in) const {
  if (criterion_ == DamageInitiation::Criterion::PlasticMotion) {
    return {in.equivalent / TrialSensitive(plastic_motion_), in.equivalent, plastic_motion_, 1.0};
  }
  const SensitiveVector& x =
      criterion_ == DamageInitiation::Criterion::Force ? in.total_force : in.motion;
  TrialSensitive v;
  if (component_ > 0) {
    v = x[static_cast<std::size_t>(component_ - 1)];
  } else {
    v = evaluate_potential(*potential_, x);
  }
  // r = v/limit on the side of its sign (F_L ≤ 0 makes r ≥ 0 in compression).
  const double sign = v.value >= 0 ? 1.0 : -1.0;
  const double limit = sign > 0 ? upper_ : lower_;
  return {limit != 0 ? v / TrialSensitive(limit) : TrialSensitive(0.0), v, limit, sign};
}

}  // namespace clinch
