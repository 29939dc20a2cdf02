// One damage mechanism of a connector (behaviors.md §7): a *CONNECTOR DAMAGE INITIATION with its
// optional *CONNECTOR DAMAGE EVOLUTION. From the committed history and the trial state it finds
// whether and where damage initiates (the initiation point interpolated inside the increment,
// §7.1), the post-initiation motion δ and its history maximum κ, the work W after initiation
// (ENERGY), and the mechanism's damage d_m, which never decreases (§7.2).
#pragma once

#include <optional>
#include <span>

#include "src/behavior/damage/damage_evolution_law.hpp"
#include "src/behavior/damage/damage_initiation_criterion.hpp"

namespace clinch {

// The committed state of the element that every mechanism reads, and the trial one with its
// gradients against the trial motion.
struct MechanismInput {
  const Vector6& motion_old;           // u_n
  const Vector6& force_old;            // f^eff_n
  const SensitiveVector& motion;       // u
  const SensitiveVector& force;        // f^eff
  const SensitiveVector& total_force;  // f^eff + λ (the FORCE criterion)
  const Matrix6& compliance;           // K⁻¹ of the linear elasticity, padded (PLASTIC MOTION)
  // ū^pl of the coupled plasticity at the trial state, read from the law below (CUPEQC); NaN
  // when there is none.
  double coupled_equivalent;
};

class DamageMechanism {
 public:
  // History of one mechanism (§7.4 "History per mechanism"), kHistorySize doubles.
  static constexpr int kInitiated = 0;
  static constexpr int kCriterionMax = 1;  // r_max (CDIF, CDIM, CDIP)
  static constexpr int kMeasureOld = 2;  // the criterion's signed measure v at the committed state
  static constexpr int kSign = 3;        // s_0
  static constexpr int kMeasure = 4;     // m_0 = s_0 u_0,i or P_e(u_0)
  static constexpr int kKappa = 5;       // κ = max δ
  static constexpr int kWork = 6;        // W (ENERGY)
  static constexpr int kDamage = 7;      // d_m
  static constexpr int kPlasticMotion = 8;  // u^pl of the criterion's component (PLASTIC MOTION)
  static constexpr int kEquivalent = 9;     // ū^pl of that component
  static constexpr int kInitiationMotion = 10;  // u_0, six values
  static constexpr int kHistorySize = 16;

  DamageMechanism(const ConnectorBehavior& behavior, std::size_t initiation,
                  ComponentMask available);

  // Writes the trial history into `history` (kHistorySize values, starting from `old`) and
  // returns d_m with its gradient.
  TrialSensitive update(const MechanismInput& in, std::span<const double> old,
                        std::span<double> history) const;

  ComponentMask affected() const { return affected_; }
  // Its damage depends on the path within an increment: the work of an ENERGY evolution is
  // integrated over the increment (trapezoidal), the other laws are functions of κ (§7.2).
  bool path_dependent() const { return law_ && law_->energy_based(); }
  DamageEvolution::Degradation degradation() const { return degradation_; }
  const DamageInitiationCriterion& criterion() const { return criterion_; }

 private:
  // δ's measure of the motion: s_0 u_i (uncoupled) or P_e(u) (coupled).
  TrialSensitive motion_measure(const SensitiveVector& u, double sign) const;
  // ū^pl of the criterion's component at the trial state (uncoupled plasticity: Δū = |Δu^pl|).
  TrialSensitive equivalent_plastic(const MechanismInput& in, std::span<const double> old,
                                    TrialSensitive& plastic) const;
  // ū^pl of the coupled plasticity at the trial state.
  TrialSensitive coupled_equivalent_plastic(const MechanismInput& in,
                                            std::span<const double> old) const;
  // The size of the effective force on the yield surface: |f_i| (uncoupled), P(f) (coupled).
  TrialSensitive yield_measure(const SensitiveVector& force) const;

  DamageInitiationCriterion criterion_;
  std::optional<DamageEvolutionLaw> law_;  // none: initiation is only monitored
  DamageEvolution::Degradation degradation_ = DamageEvolution::Degradation::Maximum;
  ComponentMask affected_ = 0;
  // Coupled FORCE/MOTION: P_e, the evolution potential, or the Euclidean norm of the affected
  // components' motions without one (§7.2, not confirmed).
  std::optional<ConnectorPotential> evolution_potential_;
  ComponentMask work_components_ = 0;     // the motions whose work W integrates
  double initiation_plastic_motion_ = 0;  // ū^pl_0
  // Coupled PLASTIC MOTION: the potential of the coupled plasticity.
  std::optional<ConnectorPotential> plastic_potential_;
};

}  // namespace clinch
