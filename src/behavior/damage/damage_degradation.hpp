// The overall damage of one component from the mechanisms that affect it (behaviors.md §7.3):
// d = 1 − (1 − d_max) Π_MULTIPLICATIVE (1 − d_m), d_max the largest DEGRADATION=MAXIMUM damage.
#pragma once

#include "src/behavior/damage/trial_sensitive.hpp"
#include "src/model/behavior_model.hpp"

namespace clinch {

class DamageDegradation {
 public:
  void add(const TrialSensitive& d, DamageEvolution::Degradation degradation) {
    if (degradation == DamageEvolution::Degradation::Maximum) {
      largest_ = larger(largest_, d);
    } else {
      intact_ = intact_ * (TrialSensitive(1.0) - d);
    }
  }
  TrialSensitive damage() const {
    return TrialSensitive(1.0) - (TrialSensitive(1.0) - largest_) * intact_;
  }

 private:
  TrialSensitive largest_{0.0};
  TrialSensitive intact_{1.0};  // Π (1 − d_m) over the MULTIPLICATIVE mechanisms
};

}  // namespace clinch
