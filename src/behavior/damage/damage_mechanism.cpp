#include "src/behavior/damage/damage_mechanism.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace clinch {
namespace {

const Potential* owned_potential(const ConnectorBehavior& behavior, PotentialOwner::Kind kind,
                                 std::int32_t index) {
  for (const PotentialOwner& o : behavior.potential_owners) {
    if (o.kind == kind && o.index == index && o.potential >= 0) {
      return &behavior.potentials[static_cast<std::size_t>(o.potential)];
    }
  }
  return nullptr;
}

std::optional<ConnectorPotential> compiled(const ConnectorBehavior& behavior,
                                           PotentialOwner::Kind kind, std::int32_t index) {
  if (index < 0) return std::nullopt;
  const Potential* p = owned_potential(behavior, kind, index);
  if (p == nullptr) return std::nullopt;
  return ConnectorPotential::compile(behavior, *p);
}

TrialSensitive magnitude(const TrialSensitive& x) { return x.value < 0 ? -x : x; }

}  // namespace

DamageMechanism::DamageMechanism(const ConnectorBehavior& behavior, std::size_t initiation,
                                 ComponentMask available)
    : criterion_(behavior.damage_initiations[initiation],
                 compiled(behavior, PotentialOwner::Kind::DamageInitiation,
                          static_cast<std::int32_t>(initiation))) {
  const DamageInitiation& init = behavior.damage_initiations[initiation];
  initiation_plastic_motion_ = init.plastic_motion;
  affected_ = criterion_.components();
  if (init.coupled() && init.criterion == DamageInitiation::Criterion::PlasticMotion) {
    // §7.1: a coupled PLASTIC MOTION criterion follows the behaviour's coupled plasticity; without
    // AFFECTED COMPONENTS it degrades the components of its potential.
    for (std::size_t k = 0; k < behavior.plasticities.size() && !plastic_potential_; ++k) {
      if (behavior.plasticities[k].coupled()) {
        plastic_potential_ =
            compiled(behavior, PotentialOwner::Kind::Plasticity, static_cast<std::int32_t>(k));
      }
    }
    if (plastic_potential_) affected_ = plastic_potential_->components();
  }
  if (init.evolution >= 0) {
    const DamageEvolution& evo =
        behavior.damage_evolutions[static_cast<std::size_t>(init.evolution)];
    law_.emplace(evo, init.criterion == DamageInitiation::Criterion::PlasticMotion);
    degradation_ = evo.degradation;
    // §7.2: AFFECTED COMPONENTS, else the initiation's component or its potential's components.
    if (evo.affected != 0) affected_ = evo.affected;
    evolution_potential_ =
        compiled(behavior, PotentialOwner::Kind::DamageEvolution, init.evolution);
  }
  affected_ = static_cast<ComponentMask>(affected_ & available);
  if (init.coupled()) {
    work_components_ = evolution_potential_ ? evolution_potential_->components() : affected_;
  } else {
    work_components_ = component_bit(init.component);
  }
  work_components_ = static_cast<ComponentMask>(work_components_ & available);
}

TrialSensitive DamageMechanism::motion_measure(const SensitiveVector& u, double sign) const {
  const int i = criterion_.component();
  if (i > 0) return TrialSensitive(sign) * u[static_cast<std::size_t>(i - 1)];
  if (evolution_potential_) return evaluate_potential(*evolution_potential_, u);
  // The Euclidean norm of the affected components' motions (§7.2, not confirmed).
  TrialSensitive square;
  for (int j = 0; j < 6; ++j) {
    if (has_component(affected_, j + 1)) {
      square = square + u[static_cast<std::size_t>(j)] * u[static_cast<std::size_t>(j)];
    }
  }
  if (square.value <= 0) return 0.0;
  const double norm = std::sqrt(square.value);
  return {norm, square.gradient / (2.0 * norm)};
}

TrialSensitive DamageMechanism::equivalent_plastic(const MechanismInput& in,
                                                   std::span<const double> old,
                                                   TrialSensitive& plastic) const {
  // u^pl = u − K⁻¹ f^eff on the component; uncoupled backward-Euler flow moves u^pl_i by
  // ±Δλ and ū by Δλ (§6.3), so Δū = |Δu^pl_i|.
  const auto i = static_cast<std::size_t>(criterion_.component() - 1);
  plastic = in.motion[i];
  for (std::size_t j = 0; j < 6; ++j) {
    const double c = in.compliance(static_cast<int>(i), static_cast<int>(j));
    if (c != 0) plastic = plastic - TrialSensitive(c) * in.force[j];
  }
  const TrialSensitive flow = plastic - TrialSensitive(old[kPlasticMotion]);
  // Round-off of an elastic increment is not flow.
  const double noise = 1e-13 * (std::fabs(in.motion[i].value) + std::fabs(plastic.value));
  if (std::fabs(flow.value) <= noise) {
    plastic = TrialSensitive(old[kPlasticMotion]);
    return old[kEquivalent];
  }
  return TrialSensitive(old[kEquivalent]) + magnitude(flow);
}

TrialSensitive DamageMechanism::coupled_equivalent_plastic(const MechanismInput& in,
                                                           std::span<const double> old) const {
  // ū = ū_n + Δλ with Δu^pl = Δλ n, n = ∂P/∂f at the returned force (§6.4). The value is the
  // coupled return's own (CUPEQC of the law below); its gradient comes from
  // Δλ = n·Δu^pl/(n·n), Δu^pl = Δu − K⁻¹ Δf^eff, exact on a smooth part of the surface (at a
  // kink or a MAX corner the flow is a combination of directions and the tangent is inexact).
  const double unchanged = old[kEquivalent];
  if (!plastic_potential_ || std::isnan(in.coupled_equivalent) ||
      in.coupled_equivalent <= unchanged) {
    return unchanged;
  }
  Vector6 f;
  for (int j = 0; j < 6; ++j) f[j] = in.force[static_cast<std::size_t>(j)].value;
  PotentialValue p;
  plastic_potential_->evaluate(f, p, true);
  TrialSensitive along, length;
  for (int k = 0; k < 6; ++k) {
    if (p.gradient[k] == 0 && p.hessian.row(k).isZero()) continue;
    TrialSensitive n(p.gradient[k]);
    for (int j = 0; j < 6; ++j) {
      if (p.hessian(k, j) != 0) {
        n.gradient += p.hessian(k, j) * in.force[static_cast<std::size_t>(j)].gradient;
      }
    }
    TrialSensitive flow = in.motion[static_cast<std::size_t>(k)] - TrialSensitive(in.motion_old[k]);
    for (int j = 0; j < 6; ++j) {
      const double c = in.compliance(k, j);
      if (c != 0) {
        flow = flow - TrialSensitive(c) *
                          (in.force[static_cast<std::size_t>(j)] - TrialSensitive(in.force_old[j]));
      }
    }
    along = along + n * flow;
    length = length + n * n;
  }
  if (length.value <= 0) return in.coupled_equivalent;
  TrialSensitive equivalent = TrialSensitive(unchanged) + along / length;
  equivalent.value = in.coupled_equivalent;
  return equivalent;
}

TrialSensitive DamageMechanism::yield_measure(const SensitiveVector& force) const {
  if (plastic_potential_) return evaluate_potential(*plastic_potential_, force);
  return magnitude(force[static_cast<std::size_t>(criterion_.component() - 1)]);
}

TrialSensitive DamageMechanism::update(const MechanismInput& in, std::span<const double> old,
                                       std::span<double> history) const {
  std::memcpy(history.data(), old.data(), kHistorySize * sizeof(double));
  const bool plastic_criterion =
      criterion_.criterion() == DamageInitiation::Criterion::PlasticMotion;
  TrialSensitive plastic, equivalent;
  if (plastic_criterion && criterion_.component() == 0) {
    equivalent = coupled_equivalent_plastic(in, old);
    history[kEquivalent] = equivalent.value;
  } else if (plastic_criterion) {
    equivalent = equivalent_plastic(in, old, plastic);
    history[kPlasticMotion] = plastic.value;
    history[kEquivalent] = equivalent.value;
  }
  const CriterionValue now = criterion_.evaluate({in.total_force, in.motion, equivalent});
  history[kMeasureOld] = now.measure.value;
  history[kCriterionMax] = std::max(old[kCriterionMax], now.r.value);

  // §7.1: the initiation point, interpolated linearly inside the increment that crosses r = 1.
  // The signed measure v is interpolated to its limit on the trial's side, θ = (L − v_n)/(v − v_n):
  // the same point as θ = (1 − r_n)/(r − r_n) when v_n lies on that side, and the crossing of
  // the limit, not of the other side's r, when the increment starts on the other side.
  const bool crossing = old[kInitiated] == 0;
  TrialSensitive theta;  // where in the increment the crossing lies (crossing only)
  SensitiveVector initiation_motion;
  double sign = old[kSign];
  TrialSensitive measure(old[kMeasure]);
  if (crossing) {
    if (now.r.value < 1.0) return 0.0;
    const double v_old = old[kMeasureOld];
    theta = TrialSensitive(now.limit - v_old) / (now.measure - TrialSensitive(v_old));
    for (std::size_t j = 0; j < 6; ++j) {
      const TrialSensitive u_old(in.motion_old[static_cast<int>(j)]);
      initiation_motion[j] = u_old + theta * (in.motion[j] - u_old);
      history[static_cast<std::size_t>(kInitiationMotion) + j] = initiation_motion[j].value;
    }
    sign = now.sign;
    measure = plastic_criterion ? TrialSensitive(initiation_plastic_motion_)
                                : motion_measure(initiation_motion, sign);
    history[kInitiated] = 1;
    history[kSign] = sign;
    history[kMeasure] = measure.value;
  }
  if (!law_) return 0.0;

  // §7.2: δ, the post-initiation motion, and κ = max δ.
  const TrialSensitive delta = plastic_criterion
                                   ? equivalent - TrialSensitive(initiation_plastic_motion_)
                                   : motion_measure(in.motion, sign) - measure;
  const double kappa_old = old[kKappa];
  const TrialSensitive kappa = larger(TrialSensitive(kappa_old), delta);
  history[kKappa] = kappa.value;

  // ENERGY: W grows over the part of the increment beyond the envelope, from δ = κ_n (or the
  // initiation point) to δ, by the trapezoidal rule with the start interpolated (§7.2).
  TrialSensitive work(old[kWork]);
  if (law_->energy_based() && delta.value > kappa_old) {
    TrialSensitive start = theta;
    if (!crossing) {
      const double delta_old =
          plastic_criterion
              ? old[kEquivalent] - initiation_plastic_motion_
              : motion_measure(constant_vector(in.motion_old), sign).value - measure.value;
      start = delta_old < kappa_old
                  ? TrialSensitive(kappa_old - delta_old) / (delta - TrialSensitive(delta_old))
                  : TrialSensitive(0.0);
    }
    const auto at_start = [&](double old_value, const TrialSensitive& value) {
      return TrialSensitive(old_value) + start * (value - TrialSensitive(old_value));
    };
    if (plastic_criterion) {
      // W = ∫ F_y dū^pl with F_y = |f^eff| (uncoupled) or P(f^eff) (coupled) on the surface.
      const TrialSensitive yield = yield_measure(in.force);
      const TrialSensitive yield_start =
          at_start(yield_measure(constant_vector(in.force_old)).value, yield);
      work = work + TrialSensitive(0.5) * (yield_start + yield) *
                        (equivalent - at_start(old[kEquivalent], equivalent));
    } else {
      // W = ∫ f^eff · du over the components δ measures.
      for (std::size_t j = 0; j < 6; ++j) {
        if (!has_component(work_components_, static_cast<int>(j) + 1)) continue;
        const int jj = static_cast<int>(j);
        work = work + TrialSensitive(0.5) *
                          (at_start(in.force_old[jj], in.force[j]) + in.force[j]) *
                          (in.motion[j] - at_start(in.motion_old[jj], in.motion[j]));
      }
    }
  }
  history[kWork] = work.value;

  const TrialSensitive d = larger(TrialSensitive(old[kDamage]), law_->damage(kappa, measure, work));
  history[kDamage] = d.value;
  return d;
}

}  // namespace clinch
