// The damage initiation criterion of one *CONNECTOR DAMAGE INITIATION (behaviors.md §7.1): the
// criterion value r (CDIF, CDIM, CDIP) from the undamaged force, the constitutive motion or the
// equivalent plastic motion, uncoupled (one component) or coupled (a potential), and the sign of
// the measure, which fixes the direction damage evolves in.
#pragma once

#include <array>
#include <optional>

#include "src/behavior/damage/sensitive_potential.hpp"
#include "src/model/behavior_model.hpp"

namespace clinch {

// What a criterion reads at one state, each with its gradient against the trial motion.
struct CriterionInput {
  const SensitiveVector& force;        // f^eff, the undamaged elastic-plastic force
  const SensitiveVector& motion;       // u
  const MotionSensitive& equivalent;   // ū^pl of the component's plasticity (PLASTIC MOTION)
};

struct CriterionValue {
  MotionSensitive r;  // ≥ 1: initiated
  double sign = 1;    // sign of the measure (s_0 at initiation)
};

class DamageInitiationCriterion {
 public:
  // `potential`: the initiation potential of a coupled FORCE/MOTION criterion.
  DamageInitiationCriterion(const DamageInitiation& initiation,
                            std::optional<ConnectorPotential> potential);

  CriterionValue evaluate(const CriterionInput& in) const;

  DamageInitiation::Criterion criterion() const { return criterion_; }
  int component() const { return component_; }  // 0: coupled
  // The components the criterion reads (its COMPONENT, or those of its potential).
  ComponentMask components() const;

 private:
  DamageInitiation::Criterion criterion_;
  int component_;
  // FORCE/MOTION: 1/limit on each side (0 without a limit: that side never initiates).
  double inverse_lower_ = 0, inverse_upper_ = 0;
  double inverse_plastic_motion_ = 0;  // PLASTIC MOTION: 1/ū^pl_0
  std::optional<ConnectorPotential> potential_;
};

}  // namespace clinch
