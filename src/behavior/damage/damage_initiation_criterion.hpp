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
  // f^c = f^eff + λ: the undamaged elastic-plastic force plus the constraint forces (stops, locks,
  // connector motions) of each component, the total force of §7.1 without friction.
  const SensitiveVector& total_force;
  const SensitiveVector& motion;     // u
  const TrialSensitive& equivalent;  // ū^pl of the component's plasticity (PLASTIC MOTION)
};

struct CriterionValue {
  TrialSensitive r;        // ≥ 1: initiated
  TrialSensitive measure;  // the signed measure v: f_i, u_i, P(f), P(u) or ū^pl
  double limit = 0;        // the limit on v's side (0: none on that side, r = 0)
  double sign = 1;         // sign of v (s_0 at initiation)
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
  // FORCE/MOTION: the limit on each side (0 without one: that side never initiates).
  double lower_ = 0, upper_ = 0;
  double plastic_motion_ = 0;  // PLASTIC MOTION: ū^pl_0
  std::optional<ConnectorPotential> potential_;
};

}  // namespace clinch
