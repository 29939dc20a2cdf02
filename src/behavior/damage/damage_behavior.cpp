#include "src/behavior/damage/damage_behavior.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <optional>
#include <vector>

#include "src/behavior/damage/damage_degradation.hpp"
#include "src/behavior/damage/damage_mechanism.hpp"
#include "src/behavior/elastic/elastic_behavior.hpp"

namespace clinch {
namespace {

// Increment control (§7.4): an increment in which a component's damage grows by more than
// kDamageJump skips most of its softening branch, so it is retried smaller, aiming at
// kDamageTarget; above kDamageSteady the next increment does not grow.
constexpr double kDamageJump = 0.75;
constexpr double kDamageTarget = 0.5;
constexpr double kDamageSteady = 0.25;
// Regularised damage this close to the largest damage counts as having reached it.
constexpr double kViscousFailure = 1e-3;

// The criterion outputs (output-variables.md §2): the scalar, per component, coupled.
constexpr const char* kCriterionNames[3][2] = {
    {"CDIF", "CDIFC"}, {"CDIM", "CDIMC"}, {"CDIP", "CDIPC"}};

class DamageBehavior final : public Behavior {
 public:
  DamageBehavior(std::vector<DamageMechanism> mechanisms, const Matrix6& compliance,
                 const DamageControls& controls)
      : mechanisms_(std::move(mechanisms)), compliance_(compliance), controls_(controls) {
    increment_sensitive_ = controls_.viscosity > 0;
    for (const DamageMechanism& m : mechanisms_) {
      increment_sensitive_ = increment_sensitive_ || m.path_dependent();
      affected_ |= m.affected();
      force_criterion_ =
          force_criterion_ || m.criterion().criterion() == DamageInitiation::Criterion::Force;
    }
    const std::size_t element = mechanisms_.size() * DamageMechanism::kHistorySize;
    damage_ = element;
    force_ = damage_ + 7;
    deleted_ = force_ + 6;
    criteria_ = deleted_ + 1;
    inviscid_ = criteria_ + 3 * 8;
    regularisation_ = inviscid_ + 6;
    layout_.resize(regularisation_ + 1);
    if (controls_.viscosity > 0) layout_[regularisation_] = {"regularisation energy", 0};
    for (int i = 0; i <= 6; ++i) layout_[damage_ + static_cast<std::size_t>(i)] = {"CDMG", i};
    layout_[deleted_] = {"deleted", 0};
    for (std::size_t k = 0; k < 3; ++k) {
      for (int i = 0; i <= 6; ++i) {
        layout_[criteria_ + 8 * k + static_cast<std::size_t>(i)] = {kCriterionNames[k][0], i};
      }
      layout_[criteria_ + 8 * k + 7] = {kCriterionNames[k][1], 0};
    }
  }

  ComponentMask components() const override { return affected_; }
  std::span<const HistoryVariable> history_layout() const override { return layout_; }
  // The f^eff ⊗ ∂d/∂u term (§7.4) is unsymmetric, and softening makes the system indefinite:
  // the step takes the LU solver.
  bool tangent_is_symmetric() const override { return false; }
  // The FORCE criterion reads the total force, constraint forces included (§7.1).
  bool needs_connector_forces() const override { return force_criterion_; }
  bool deletes_element(std::span<const double> history) const override {
    return history[deleted_] != 0;
  }
  double damage(std::span<const double> history) const override { return history[damage_]; }
  // The energy the viscous regularisation dissipated, so that an analyst can judge the
  // VISCOSITY against the energy of the model.
  std::optional<StepTotal> step_total(std::span<const double> history) const override {
    if (controls_.viscosity <= 0) return std::nullopt;
    return StepTotal{"energy dissipated by the viscous regularisation of damage so far",
                     "connectors with VISCOSITY", history[regularisation_]};
  }

  IntegrationStatus integrate(const BehaviorInput& in, BehaviorOutput& out) const override {
    std::memcpy(out.history_new.data(), in.history_old.data(), layout_.size() * sizeof(double));
    double* h = out.history_new.data();
    const double* old = in.history_old.data();
    // Without an elastic law below there is no force to degrade (the criteria still run).
    static const Vector6 kNoForce = Vector6::Zero();
    static const Matrix6 kNoStiffness = Matrix6::Zero();
    const Vector6& feff = in.force_below ? *in.force_below : kNoForce;
    const Matrix6& deff = in.tangent_below ? *in.tangent_below : kNoStiffness;
    const bool tangent = in.tangent != TangentRequest::None;
    if (old[deleted_] != 0) {
      // A deleted element carries no force (the assembly leaves it out altogether).
      out.force = -feff;
      if (tangent) out.tangent = -deff;
      return IntegrationStatus::Success;
    }
    const Vector6 u = in.motion_old + in.increment;
    SensitiveVector force, total_force, motion = motion_vector(u);
    for (int j = 0; j < 6; ++j) {
      const auto s = static_cast<std::size_t>(j);
      force[s] = TrialSensitive::of_motion(feff[j], deff.row(j).transpose());
      total_force[s] = in.connector_forces
                           ? force[s] + TrialSensitive::constraint_force(*in.connector_forces, j)
                           : force[s];
    }
    const Vector6 force_old = Eigen::Map<const Vector6>(old + force_);
    const int below = history_slot(in.layout_below, "CUPEQC", 0);
    const double coupled_equivalent = below >= 0 ? in.history_below[static_cast<std::size_t>(below)]
                                                 : std::numeric_limits<double>::quiet_NaN();
    const MechanismInput input{in.motion_old, force_old,         motion, force, total_force,
                               compliance_,   coupled_equivalent};
    std::array<DamageDegradation, 6> degradation;
    for (std::size_t m = 0; m < mechanisms_.size(); ++m) {
      const std::size_t at = m * DamageMechanism::kHistorySize;
      const TrialSensitive d =
          mechanisms_[m].update(input, in.history_old.subspan(at, DamageMechanism::kHistorySize),
                                out.history_new.subspan(at, DamageMechanism::kHistorySize));
      for (int i = 0; i < 6; ++i) {
        if (has_component(mechanisms_[m].affected(), i + 1)) {
          degradation[static_cast<std::size_t>(i)].add(d, mechanisms_[m].degradation());
        }
      }
    }

    // §7.3, §7.4: f^el = (1 − d) f^eff on the affected components; this law adds −d f^eff.
    const double d_max = controls_.max_degradation;
    double largest = 0, growth = 0;
    bool failed = affected_ != 0;
    for (int i = 0; i < 6; ++i) {
      if (!has_component(affected_, i + 1)) continue;
      const double d_old = old[damage_ + static_cast<std::size_t>(i) + 1];
      TrialSensitive d = degradation[static_cast<std::size_t>(i)].damage();
      if (controls_.viscosity > 0) {
        const auto slot = inviscid_ + static_cast<std::size_t>(i);
        h[slot] = std::min(d.value, d_max);
        d = regularized(d, d_old, in.dt);
        // The work of the force the regularised element carries beyond the inviscid one,
        // (d − d_v) f^eff, along the motion (trapezoidal over the increment).
        const double excess = (h[slot] - std::min(d.value, d_max)) * feff[i];
        const double excess_old = (old[slot] - d_old) * old[force_ + static_cast<std::size_t>(i)];
        h[regularisation_] += 0.5 * (excess + excess_old) * in.increment[i];
      }
      if (d.value >= d_max) d = TrialSensitive(d_max);
      out.force[i] = -d.value * feff[i];
      if (tangent) {
        out.tangent.row(i) = -(d.value * deff.row(i) + feff[i] * d.gradient.head<6>().transpose());
        // Through the FORCE criterion's constraint forces (the initiation point, §7.1).
        out.force_tangent.row(i) = -feff[i] * d.gradient.tail<6>().transpose();
      }
      h[damage_ + static_cast<std::size_t>(i) + 1] = d.value;
      largest = std::max(largest, d.value);
      growth = std::max(growth, d.value - d_old);
      failed = failed && d.value >= d_max;
    }
    h[damage_] = largest;
    // §7.4 deletion: at the end of the increment in which every affected component reached the
    // largest damage, unless the section controls keep the element (ELEMENT DELETION=NO).
    h[deleted_] = failed && controls_.element_deletion ? 1.0 : 0.0;
    Eigen::Map<Vector6>(h + force_) = feff;
    record_criteria(h);
    if (growth > kDamageJump && increment_sensitive_) {
      out.suggested_dt_ratio = kDamageTarget / growth;
      out.message = fmt::format("damage grew by {:.3g} in one increment (at most {} allowed)",
                                growth, kDamageJump);
    } else if (growth > kDamageSteady) {
      out.suggested_dt_ratio = 1.0;
      out.message = fmt::format("damage grew by {:.3g} in one increment", growth);
    }
    return IntegrationStatus::Success;
  }

 private:
  // VISCOSITY η (keywords.md §5): the damage used is d_v with d_v' = (d − d_v)/η, integrated by
  // backward Euler over the increment: d_v = (η d_v,n + Δt d)/(η + Δt). It lags the inviscid d
  // over a time scale η and reaches d_max only asymptotically, so within kViscousFailure of it
  // it is taken as reached (the element can then be deleted).
  TrialSensitive regularized(const TrialSensitive& d, double d_old, double dt) const {
    const double eta = controls_.viscosity;
    const double weight = dt / (eta + dt);
    TrialSensitive v(eta / (eta + dt) * d_old + weight * d.value, weight * d.gradient);
    if (v.value < d_old) v = TrialSensitive(d_old);  // d_v never decreases
    if (v.value >= controls_.max_degradation - kViscousFailure) {
      v = TrialSensitive(controls_.max_degradation);
    }
    return v;
  }

  // CDIF/CDIM/CDIP: the history maximum of r per kind of criterion, as the scalar (every
  // mechanism of that kind), per component (uncoupled) and coupled (output-variables.md §2).
  void record_criteria(double* h) const {
    for (std::size_t m = 0; m < mechanisms_.size(); ++m) {
      const double r = h[m * DamageMechanism::kHistorySize + DamageMechanism::kCriterionMax];
      const auto kind = static_cast<std::size_t>(mechanisms_[m].criterion().criterion());
      const int component = mechanisms_[m].criterion().component();
      double* slots = h + criteria_ + 8 * kind;
      slots[0] = std::max(slots[0], r);
      double& own = component > 0 ? slots[component] : slots[7];
      own = std::max(own, r);
    }
  }

  std::vector<DamageMechanism> mechanisms_;
  bool increment_sensitive_ = false;
  Matrix6 compliance_;
  DamageControls controls_;
  ComponentMask affected_ = 0;
  bool force_criterion_ = false;
  std::size_t damage_ = 0;          // the scalar CDMG, then d_i of components 1…6
  std::size_t force_ = 0;           // f^eff at the committed state, six values
  std::size_t deleted_ = 0;         // 1 once the element is deleted (§7.4)
  std::size_t criteria_ = 0;        // CDIF, CDIF1…6, CDIFC, then CDIM…, CDIP…
  std::size_t inviscid_ = 0;        // VISCOSITY: the damage before regularisation, per component
  std::size_t regularisation_ = 0;  // VISCOSITY: the energy the regularisation dissipated
  std::vector<HistoryVariable> layout_;
};

}  // namespace

std::unique_ptr<Behavior> make_damage_behavior(const ConnectorBehavior& behavior,
                                               ComponentMask available,
                                               const DamageControls& controls) {
  if (behavior.damage_initiations.empty()) return nullptr;
  std::vector<DamageMechanism> mechanisms;
  for (std::size_t k = 0; k < behavior.damage_initiations.size(); ++k) {
    mechanisms.emplace_back(behavior, k, available);
  }
  // The compliance of the linear elasticity, padded with 1 where it has no stiffness, turns f^eff
  // back into the elastic motion for PLASTIC MOTION criteria.
  const LinearStiffness linear = linear_stiffness(behavior, available);
  Matrix6 padded = linear.k;
  for (int i = 0; i < 6; ++i) {
    if (!has_component(linear.components, i + 1)) padded(i, i) = 1.0;
  }
  return std::make_unique<DamageBehavior>(std::move(mechanisms),
                                          padded.ldlt().solve(Matrix6::Identity()), controls);
}

}  // namespace clinch
