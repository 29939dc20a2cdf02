// The overall damage of one component from the mechanisms that affect it (behaviors.md §7.3):
// d = 1 − (1 − d_max) Π_MULTIPLICATIVE (1 − d_m), d_max the largest DEGRADATION=MAXIMUM damage.
#pragma once

#include "src/behavior/damage/motion_sensitive.hpp"
#include "src/model/behavior_model.hpp"

namespace clinch {

class DamageDegradation {
 public:
  void add(const MotionSensitive& d, DamageEvolution::Degradation degradation) {
    if (degradation == DamageEvolution::Degradation::Maximum) {
      largest_ = larger(largest_, d);
    } else {
      intact_ = intact_ * (MotionSensitive(1.0) - d);
    }
  }
  MotionSensitive damage() const {
    return MotionSensitive(1.0) - (MotionSensitive(1.0) - largest_) * intact_;
  }

 private:
  MotionSensitive largest_{0.0};
  MotionSensitive intact_{1.0};  // Π (1 − d_m) over the MULTIPLICATIVE mechanisms
};

}  // namespace clinch
