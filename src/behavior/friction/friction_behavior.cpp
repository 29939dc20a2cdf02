#include "src/behavior/friction/friction_behavior.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "src/behavior/friction/contact_force_measure.hpp"
#include "src/behavior/friction/friction_capacity.hpp"
#include "src/behavior/plastic/coupled_return_mapping.hpp"
#include "src/behavior/plastic/multi_surface_return.hpp"
#include "src/behavior/plastic/uncoupled_return_mapping.hpp"
#include "src/behavior/potential/connector_potential.hpp"
#include "src/model/default_stick_stiffness.hpp"

namespace clinch {
namespace {

// §4.1 step 3: an exact tie (trial on the surface) sticks.
constexpr double kStickTolerance = 1e-12;
// A stick–slip switch can send Newton back and forth across the narrow stick band (slip tangents
// on both sides); a line search stops the cycle (docs/decisions.md "Friction").
constexpr int kLineSearchIterations = 5;

class FrictionBehavior final : public Behavior {
 public:
  FrictionBehavior(ComponentMask components, const Vector6& stiffness,
                   std::optional<ConnectorPotential> potential, ContactForceMeasure contact,
                   FrictionCapacityLaw capacity, std::string name)
      : name_(std::move(name)),
        components_(components),
        stiffness_(stiffness),
        potential_(std::move(potential)),
        contact_(std::move(contact)),
        capacity_(std::move(capacity)) {
    // History (§4, §6): u_s per component of J, then γ, F_N and the slip flag per component
    // (CASU, CNF, CSLIPST repeat the definition's values), then for a coupled definition
    // P(f^fr), F_N and γ once (CSFC, CNFC, CASUC).
    for (int i = 1; i <= 6; ++i) {
      if (has_component(components_, i)) layout_.push_back({"slip", i});
    }
    count_ = static_cast<int>(layout_.size());
    for (const char* output : {"CASU", "CNF", "CSLIPST"}) {
      for (int i = 1; i <= 6; ++i) {
        if (has_component(components_, i)) layout_.push_back({output, i});
      }
    }
    if (potential_) {
      for (const char* output : {"CSFC", "CNFC", "CASUC"}) layout_.push_back({output, 0});
    }
    space_.stiffness = Matrix6::Identity();
    space_.compliance = Matrix6::Identity();
    for (int i = 0; i < 6; ++i) {
      if (!has_component(components_, i + 1)) continue;
      space_.stiffness(i, i) = stiffness_[i];
      space_.compliance(i, i) = 1.0 / stiffness_[i];
    }
  }

  ComponentMask components() const override { return components_; }
  std::span<const HistoryVariable> history_layout() const override { return layout_; }
  bool tangent_is_symmetric() const override { return !contact_.present(); }
  bool needs_connector_forces() const override { return contact_.present(); }
  ForceKind force_kind() const override { return ForceKind::Friction; }
  ProcedureNeeds procedure_needs() const override {
    ProcedureNeeds needs{kLineSearchIterations, "the step has friction", {}};
    if (capacity_.coefficient.depends_on_rate()) {
      needs.notes.push_back(
          "the friction is rate dependent; in a *STATIC step the slip rate is the slip of an "
          "increment over its step time (friction.md §3.3)");
    }
    return needs;
  }

  IntegrationStatus integrate(const BehaviorInput& in, BehaviorOutput& out) const override;

 private:
  // The slip of the increment: force, Δλ, ∂f/∂u and ∂f/∂F_lim at fixed u.
  struct Slip {
    Vector6 force = Vector6::Zero();
    double multiplier = 0;
    Matrix6 tangent = Matrix6::Zero();
    Vector6 sensitivity = Vector6::Zero();
  };
  IntegrationStatus radial_slip(const Vector6& trial, const FrictionCapacity& capacity,
                                double slip_old, bool want_tangent, Slip& slip,
                                std::string& message) const;
  // §7.3: with rate weakening the update is unique only while k > F_N·d_c·(μ_s − μ_k)/Δt.
  void rate_stiffness_warning(double normal, double dt, BehaviorOutput& out) const {
    const double weakening = capacity_.coefficient.steepest_weakening();
    if (weakening <= 0 || !(dt > 0)) return;
    const double bound = normal * weakening / dt;
    double k = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 6; ++i) {
      if (has_component(components_, i + 1)) k = std::min(k, stiffness_[i]);
    }
    if (k > bound) return;
    out.warning = fmt::format(
        "{}: STICK STIFFNESS {} does not exceed F_N·d_c·(μ_s − μ_k)/Δt = {} "
        "[friction-rate-stiffness]; the slip update may have several solutions and the answer "
        "depends on the increment size (friction.md §7.3)",
        name_, k, bound);
  }
  double measure(const Vector6& force) const {
    return potential_ ? potential_->value(force) : force.norm();
  }

  std::string name_;  // for messages: "*CONNECTOR FRICTION 1 of behavior 'B'"
  ComponentMask components_;
  Vector6 stiffness_;
  std::optional<ConnectorPotential> potential_;  // none: P = |f_J| (COMPONENT=, predefined)
  ContactForceMeasure contact_;
  FrictionCapacityLaw capacity_;
  ElasticSpace space_;  // K_s on J, padded with the identity (plastic_return_types.hpp)
  std::vector<HistoryVariable> layout_;
  int count_ = 0;  // |J|
};

// §4.1 step 4, closed form: with P = |f_J| and K_s = k·I the return is radial, and
// |f_tr| − kΔλ − F_lim(γ_n + Δλ) = 0 is the scalar equation of the uncoupled plastic return.
IntegrationStatus FrictionBehavior::radial_slip(const Vector6& trial,
                                                const FrictionCapacity& capacity, double slip_old,
                                                bool want_tangent, Slip& slip,
                                                std::string& message) const {
  int first = 0;
  while (!has_component(components_, first + 1)) ++first;
  const double k = stiffness_[first];
  const double size = trial.norm();
  UncoupledReturnInput ri;
  ri.stiffness = k;
  ri.trial_force = size;
  ri.equivalent_old = slip_old;
  ri.yield = capacity;
  const UncoupledReturn r = uncoupled_return(ri);
  if (!r.converged) {
    message = name_ + ": friction return mapping did not converge";
    return IntegrationStatus::Failure;
  }
  if (!(r.tangent_denominator > 0)) {
    message = name_ +
              ": friction softening exceeds stick stiffness; increase STICK STIFFNESS "
              "or the time increment";
    return IntegrationStatus::Failure;
  }
  const Vector6 e = trial / size;
  // The closed form f = F_lim·f_tr/|f_tr| of §4.1 step 4: |f| is the capacity at the root, also
  // when F_lim is far below |f_tr| and |f_tr| − kΔλ would be round-off of either sign.
  const double magnitude = capacity.at(slip_old + r.multiplier).value;
  slip.force = magnitude * e;
  slip.multiplier = r.multiplier;
  if (want_tangent) {
    // d|f| = k h/(k + h) eᵀdu + k/(k + h) dF_lim, de = (k/|f_tr|)(I − e eᵀ) du on J.
    const double h = r.tangent_denominator - k;
    const Matrix6 radial = e * e.transpose();
    const Matrix6 on_j = mask_vector(components_).asDiagonal();
    slip.tangent =
        (k * h / r.tangent_denominator) * radial + (magnitude * k / size) * (on_j - radial);
    slip.sensitivity = (k / r.tangent_denominator) * e;
  }
  return IntegrationStatus::Success;
}

IntegrationStatus FrictionBehavior::integrate(const BehaviorInput& in, BehaviorOutput& out) const {
  const bool want_tangent = in.tangent == TangentRequest::Consistent;
  const Vector6 u = in.motion_old + in.increment;
  const auto old_value = [&](int slot) { return in.history_old[static_cast<std::size_t>(slot)]; };
  Vector6 slip_old = Vector6::Zero();
  for (int s = 0; s < count_; ++s)
    slip_old[layout_[static_cast<std::size_t>(s)].component - 1] = old_value(s);
  const double gamma_old = old_value(count_);

  // §2.2: the contact measure on the connector force without this definition's own friction:
  // the laws below it in the stack and the constraint forces.
  Vector6 connector_force = Vector6::Zero();
  if (in.force_below) connector_force += *in.force_below;
  if (in.connector_forces) connector_force += *in.connector_forces;
  Vector6 contact_gradient = Vector6::Zero();
  const double n = contact_.evaluate(connector_force, want_tangent ? &contact_gradient : nullptr);
  const double contact = std::abs(n);
  if (n < 0) contact_gradient = -contact_gradient;
  if (n == 0) contact_gradient.setZero();
  const FrictionCapacity capacity(capacity_, contact, gamma_old, in.dt);

  const Vector6 trial =
      stiffness_.cwiseProduct(u - slip_old).cwiseProduct(mask_vector(components_));
  const double size = measure(trial);
  const YieldSample stick_capacity = capacity.at(gamma_old);

  Slip slip;
  // §4.1 step 5: no capacity (F_N = 0, and F_lim cannot grow with the slip) means no force, all
  // of the motion is slip, and the tangent is 0 (the stick range has zero width). A capacity below
  // the stick test's resolution of the trial, 1e-12·P(f_tr) (step 3), counts as none: a contact
  // force that is a constraint reaction of round-off size gives such a capacity.
  const bool no_capacity =
      stick_capacity.slope <= 0 && stick_capacity.value <= kStickTolerance * size;
  // §6: CSLIPST = 1 when the increment slips, which without capacity is any motion at all.
  bool slipping = no_capacity ? size > 0
                              : size - stick_capacity.value >
                                    kStickTolerance * std::max(stick_capacity.value, size);
  double gamma = gamma_old;
  Vector6 slip_new = slip_old;
  if (no_capacity) {
    slip_new = u.cwiseProduct(mask_vector(components_));
    double mean = 0;
    for (int s = 0; s < count_; ++s)
      mean += stiffness_[layout_[static_cast<std::size_t>(s)].component - 1];
    gamma = gamma_old + size / (mean / count_);
  } else if (!slipping) {
    slip.force = trial;
    if (want_tangent) slip.tangent = mask_vector(components_).asDiagonal() * space_.stiffness;
  } else if (!potential_) {
    const IntegrationStatus status =
        radial_slip(trial, capacity, gamma_old, want_tangent, slip, out.message);
    if (status != IntegrationStatus::Success) return status;
    gamma = gamma_old + slip.multiplier;
    slip_new = slip_old + space_.compliance * (trial - slip.force);
  } else {
    const CoupledReturn r =
        potential_->is_max()
            ? multi_surface_return(space_, *potential_, capacity, trial, gamma_old, want_tangent)
            : closest_point_return(space_, *potential_, capacity, trial, gamma_old, want_tangent);
    if (!r.converged) {
      out.message = name_ + ": friction return mapping did not converge";
      return IntegrationStatus::Failure;
    }
    slipping = r.plastic;
    slip.force = r.force;
    // The padded slots of the elastic space are not friction components (plastic_return_types.hpp).
    const Matrix6 on_j = mask_vector(components_).asDiagonal();
    slip.tangent = on_j * (r.plastic ? r.tangent : space_.stiffness) * on_j;
    slip.sensitivity = on_j * r.yield_sensitivity;
    gamma = gamma_old + r.multiplier;
    slip_new = slip_old + space_.compliance * (trial - slip.force);
  }

  out.force = slip.force.cwiseProduct(mask_vector(components_));
  if (want_tangent) {
    out.tangent = slip.tangent;
    // §4.2: df = … + (A n)(∂F_lim/∂F_N)/D · dF_N, with dF_N = sgn·∇N·df^N and f^N the force
    // of the laws below plus the constraint forces.
    // Without capacity the force is 0 for every F_N up to the threshold above: no coupling.
    const double c = slipping && !no_capacity ? capacity.contact_sensitivity(gamma) : 0.0;
    if (c != 0 && contact_.present()) {
      const Vector6 column = c * slip.sensitivity;
      const Eigen::Matrix<double, 1, 6> row = contact_gradient.transpose();
      if (in.tangent_below) out.tangent.noalias() += column * (row * *in.tangent_below);
      Eigen::Matrix<double, 1, 6> against_forces = row;
      if (in.force_tangent_below) against_forces += row * *in.force_tangent_below;
      out.force_tangent = column * against_forces;
    }
  }

  rate_stiffness_warning(capacity.contact_force(gamma), in.dt, out);

  std::span<double> h = out.history_new;
  for (int s = 0; s < count_; ++s) {
    h[static_cast<std::size_t>(s)] = slip_new[layout_[static_cast<std::size_t>(s)].component - 1];
  }
  const double normal = capacity.contact_force(gamma);
  for (int s = 0; s < count_; ++s) {
    h[static_cast<std::size_t>(count_ + s)] = gamma;
    h[static_cast<std::size_t>(2 * count_ + s)] = normal;
    h[static_cast<std::size_t>(3 * count_ + s)] = slipping ? 1.0 : 0.0;
  }
  if (potential_) {
    h[static_cast<std::size_t>(4 * count_)] = measure(out.force);
    h[static_cast<std::size_t>(4 * count_ + 1)] = normal;
    h[static_cast<std::size_t>(4 * count_ + 2)] = gamma;
  }
  return IntegrationStatus::Success;
}

const Potential* friction_potential(const ConnectorBehavior& behavior,
                                    const FrictionDefinition& f) {
  if (f.owner < 0) return nullptr;
  const PotentialOwner& owner = behavior.potential_owners[static_cast<std::size_t>(f.owner)];
  return owner.potential >= 0 ? &behavior.potentials[static_cast<std::size_t>(owner.potential)]
                              : nullptr;
}

}  // namespace

std::unique_ptr<Behavior> make_friction_behavior(const ConnectorBehavior& behavior,
                                                 std::size_t index, ComponentMask available,
                                                 ComponentMask constrained) {
  const FrictionDefinition& f = behavior.frictions[index];
  const auto components = static_cast<ComponentMask>(f.friction_components & available);
  if (components == 0) return nullptr;
  Vector6 stiffness = Vector6::Ones();
  if (f.stick_stiffness) {
    stiffness.setConstant(*f.stick_stiffness);
  } else {
    const DefaultStickStiffness defaults = default_stick_stiffness(behavior);
    for (int i = 0; i < 6; ++i) stiffness[i] = defaults.value[static_cast<std::size_t>(i)];
  }
  std::optional<ConnectorPotential> potential;
  if (!f.predefined && f.component == 0) {
    if (const Potential* p = friction_potential(behavior, f)) {
      potential = ConnectorPotential::compile(behavior, *p);
    }
  }
  ContactForceMeasure contact;
  if (f.predefined) {
    // §2.3: SLOT and SLIDE-PLANE press on their constrained translational components.
    contact = ContactForceMeasure::norm(
        static_cast<ComponentMask>(constrained & 0b111 & ~f.friction_components));
  } else if (f.contact == FrictionDefinition::Contact::Component) {
    contact = ContactForceMeasure::component(f.contact_component);
  } else if (f.contact == FrictionDefinition::Contact::Derived) {
    contact = ContactForceMeasure::derived(DerivedComponent::compile(behavior, f.contact_name.key));
  }
  FrictionCapacityLaw capacity{FrictionCoefficient(f.law), std::nullopt, f.law.taumax};
  if (!f.internal_force.empty()) {
    capacity.internal_force.emplace(
        f.slip, f.internal_force,
        f.extrapolation == "LINEAR" ? Extrapolation::Linear : Extrapolation::Constant);
  }
  return std::make_unique<FrictionBehavior>(
      components, stiffness, std::move(potential), std::move(contact), std::move(capacity),
      fmt::format("*CONNECTOR FRICTION {} of behavior '{}'", index + 1, behavior.name.display));
}

}  // namespace clinch
