#include "src/behavior/plastic/elastic_plastic_behavior.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "src/behavior/potential/connector_potential.hpp"
#include "src/behavior/plastic/coupled_return_mapping.hpp"
#include "src/behavior/elastic/elastic_behavior.hpp"
#include "src/behavior/plastic/grouped_return.hpp"
#include "src/behavior/plastic/isotropic_hardening.hpp"
#include "src/behavior/plastic/kinematic_hardening.hpp"
#include "src/behavior/plastic/multi_surface_return.hpp"
#include "src/behavior/plastic/uncoupled_return_mapping.hpp"

namespace clinch {
namespace {

// History of one element (behaviors.md §6.2), a fixed layout of 19 doubles:
//   [0, 6)   u^pl per component (CUP); zero for components without plasticity
//   [6, 12)  ū^pl of the uncoupled plasticity of each component (CUPEQ)
//   [12]     ū^pl of the coupled plasticity (CUPEQ of the coupled one)
//   [13, 19) α, the back force per component (CALPHAF)
constexpr int kPlasticMotion = 0;
constexpr int kUncoupledEquivalent = 6;
constexpr int kCoupledEquivalent = 12;
constexpr int kBackForce = 13;
constexpr int kHistorySize = 19;

struct UncoupledPlasticity {
  int slot = 0;  // component − 1
  IsotropicHardeningLaw yield;
  std::optional<KinematicHardeningLaw> kinematic;
};

struct CoupledPlasticity {
  ConnectorPotential potential;
  IsotropicHardeningLaw yield;
  ComponentMask components = 0;
  std::optional<GroupedReturn> grouped;  // the reduced return, where it applies
};

class ElasticPlasticBehavior final : public Behavior {
 public:
  ElasticPlasticBehavior(const LinearStiffness& linear, std::vector<UncoupledPlasticity> uncoupled,
                         std::optional<CoupledPlasticity> coupled,
                         std::unique_ptr<Behavior> nonlinear)
      : k_(linear.k),
        stiffness_diagonal_(linear.k.diagonal()),
        linear_(linear.components),
        diagonal_(linear.diagonal),
        uncoupled_(std::move(uncoupled)),
        coupled_(std::move(coupled)),
        nonlinear_(std::move(nonlinear)) {
    // The padded elastic space of the coupled returns (plastic_return_types.hpp).
    Matrix6 padded = k_;
    for (int i = 0; i < 6; ++i) {
      if (!has_component(linear_, i + 1)) padded(i, i) = 1.0;
    }
    space_.stiffness = padded;
    space_.compliance = padded.llt().solve(Matrix6::Identity());
    compliance_diagonal_ = space_.compliance.diagonal();
    if (coupled_) {
      // With a diagonal K the coupled return only sees its own components; with a coupled K it
      // works in the whole linear space, where u^pl of the potential's components moves the
      // forces of the others (§6.4).
      coupled_space_ = diagonal_ ? coupled_->components : linear_;
      for (int i = 0; i < 6; ++i) coupled_slots_[i] = has_component(coupled_space_, i + 1);
      if (diagonal_ && !coupled_->potential.is_max()) {
        coupled_->grouped = GroupedReturn::create(coupled_->potential, space_);
      }
      if (!diagonal_ && !uncoupled_.empty()) {
        throw std::invalid_argument(
            "coupled plasticity together with an uncoupled plasticity and a coupled (non-diagonal) "
            "elasticity is not supported");
      }
    }
    for (const UncoupledPlasticity& p : uncoupled_) uncoupled_mask_ |= component_bit(p.slot + 1);
    mask_ = linear_;
    if (nonlinear_) mask_ |= nonlinear_->components();
    // Output names of the slots (output-variables.md §2); CUPEQ of a component without uncoupled
    // plasticity and CUPEQC without a coupled one hold nothing.
    for (int i = 0; i < 6; ++i) {
      layout_[kPlasticMotion + i] = {"CUP", i + 1};
      if (has_component(uncoupled_mask_, i + 1)) layout_[kUncoupledEquivalent + i] = {"CUPEQ", i + 1};
      layout_[kBackForce + i] = {"CALPHAF", i + 1};
    }
    if (coupled_) layout_[kCoupledEquivalent] = {"CUPEQC", 0};
  }

  ComponentMask components() const override { return mask_; }
  std::span<const HistoryVariable> history_layout() const override { return layout_; }
  bool tangent_is_symmetric() const override { return true; }

  IntegrationStatus integrate(const BehaviorInput& in, BehaviorOutput& out) const override {
    Vector6 plastic;
    const Vector6 trial = predict(in, out, plastic);
    const CoupledReturn r = coupled_ ? coupled_return(trial, out.history_new[kCoupledEquivalent],
                                                      in.tangent == TangentRequest::Consistent)
                                     : CoupledReturn{};
    return correct(in, out, trial, r, plastic);
  }

 private:
  // The start of an update: history_old into history_new, u^pl_n into `plastic`, the elastic
  // predictor F^tr = K (u − u^pl_n) into out.force (§6.3 and §6.4 step 1; correct() writes
  // the tangent). Returns F^tr on the coupled plasticity's components (0 elsewhere).
  Vector6 predict(const BehaviorInput& in, BehaviorOutput& out, Vector6& plastic) const {
    // Read from history_old, not from the copy just written (that would wait on the copy).
    const double* old = in.history_old.data();
    std::memcpy(out.history_new.data(), old, kHistorySize * sizeof(double));
    plastic = Eigen::Map<const Vector6>(old + kPlasticMotion);
    const Vector6 u = in.motion_old + in.increment;
    const Vector6 force = diagonal_ ? Vector6(stiffness_diagonal_.cwiseProduct(u - plastic))
                                    : Vector6(k_ * (u - plastic));
    out.force = force;
    return force.cwiseProduct(coupled_slots_);
  }

  // The rest of an update from the coupled return `r` of `trial` (a default CoupledReturn
  // without coupled plasticity): its flow, then the uncoupled plasticities and the nonlinear
  // elastic components.
  IntegrationStatus correct(const BehaviorInput& in, BehaviorOutput& out, const Vector6& trial,
                            const CoupledReturn& r, Vector6& plastic) const {
    const bool tangent = in.tangent != TangentRequest::None;
    const bool consistent = in.tangent == TangentRequest::Consistent;
    double* h = out.history_new.data();
    if (coupled_ && !r.converged) {
      out.message = "connector return mapping did not converge (coupled plasticity)";
      return IntegrationStatus::Failure;
    }
    const bool coupled_flow = coupled_ && r.plastic;
    // The tangent is K, with the coupled return's on its components where it flowed (written
    // once: where the return covers every linear component, it is the return's).
    if (tangent) {
      if (coupled_flow && consistent && coupled_space_ == linear_) {
        out.tangent = r.tangent;
      } else {
        out.tangent = k_;
        if (coupled_flow && consistent) {
          for (int i = 0; i < 6; ++i) {
            for (int j = 0; j < 6; ++j) {
              if (coupled_slots_[i] * coupled_slots_[j] != 0) out.tangent(i, j) = r.tangent(i, j);
            }
          }
        }
      }
    }
    if (coupled_flow) {
      // §6.4 step 4: u^pl = u^pl_n + K⁻¹(F^tr − F), ū = ū_n + Δλ.
      if (diagonal_) {
        plastic += (trial - r.force).cwiseProduct(compliance_diagonal_);
      } else {
        plastic.noalias() += space_.compliance * (trial - r.force);
      }
      h[kCoupledEquivalent] = in.history_old[kCoupledEquivalent] + r.multiplier;
      out.force = (coupled_slots_.array() != 0).select(r.force, out.force);
    }

    for (const UncoupledPlasticity& p : uncoupled_) {
      const int i = p.slot;
      UncoupledReturnInput ri;
      ri.stiffness = k_(i, i);
      ri.trial_force = out.force[i];
      ri.equivalent_old = h[kUncoupledEquivalent + i];
      ri.back_old = h[kBackForce + i];
      ri.yield = p.yield;
      ri.kinematic = p.kinematic ? &*p.kinematic : nullptr;
      const UncoupledReturn u = uncoupled_return(ri);
      if (!u.converged) {
        out.message =
            "connector return mapping did not converge (uncoupled plasticity, component " +
            std::to_string(i + 1) + ")";
        return IntegrationStatus::Failure;
      }
      if (!u.plastic) continue;
      // §6.3 step 3; with a coupled K the flow s e_i changes every force by −sΔλ K e_i.
      const double dl = u.sign * u.multiplier;
      plastic[i] += dl;
      h[kUncoupledEquivalent + i] += u.multiplier;
      h[kBackForce + i] = u.back;
      if (diagonal_) {
        out.force[i] -= k_(i, i) * dl;
        if (consistent) {
          out.tangent(i, i) = k_(i, i) - k_(i, i) * k_(i, i) / u.tangent_denominator;
        }
      } else {
        out.force.noalias() -= dl * k_.col(i);
        if (consistent)
          out.tangent.noalias() -= k_.col(i) * (k_.col(i).transpose() / u.tangent_denominator);
      }
    }
    Eigen::Map<Vector6>(h + kPlasticMotion) = plastic;

    if (nonlinear_) {
      BehaviorOutput extra;
      const BehaviorInput nin{in.motion_old, in.increment, in.time, in.dt, {}, in.tangent};
      const IntegrationStatus s = nonlinear_->integrate(nin, extra);
      if (s == IntegrationStatus::Failure) {
        out.message = extra.message;
        return s;
      }
      out.force += extra.force;
      if (tangent) out.tangent += extra.tangent;
    }
    return IntegrationStatus::Success;
  }

  // §6.4/§6.6: the multi-surface return for a MAX potential; the grouped return where it
  // applies, with the general closest-point return as its fallback.
  // Which return solves the coupled equations, and why (behaviors.md §6.4, §6.6): a MAX potential
  // takes the multi-surface return; a SUM potential whose terms form disjoint groups over a
  // diagonal elasticity takes the grouped return (closed-form shares, no 6×6 solve: the spot
  // weld); any other SUM potential, and a grouped return that does not settle, take the general
  // closest-point return (kink active set, cutting-plane fallback). GroupedReturn::create decides
  // at set-up whether a potential has the group structure.
  CoupledReturn coupled_return(const Vector6& trial, double ubar, bool consistent) const {
    const CoupledPlasticity& c = *coupled_;
    if (c.potential.is_max()) {
      return multi_surface_return(space_, c.potential, c.yield, trial, ubar, consistent);
    }
    if (c.grouped) {
      CoupledReturn r = c.grouped->solve(c.yield, trial, ubar, consistent);
      if (r.converged) return r;
    }
    return closest_point_return(space_, c.potential, c.yield, trial, ubar, consistent);
  }

  Matrix6 k_;                    // K on the linear components, zero elsewhere
  Vector6 stiffness_diagonal_;   // its diagonal, contiguous
  Vector6 compliance_diagonal_;  // that of space_.compliance (diagonal K: 1/k)
  ComponentMask linear_;
  bool diagonal_;
  ElasticSpace space_;
  ComponentMask coupled_space_ = 0;
  Vector6 coupled_slots_ = Vector6::Zero();  // 1 on the components of coupled_space_, else 0
  std::vector<UncoupledPlasticity> uncoupled_;
  ComponentMask uncoupled_mask_ = 0;
  std::array<HistoryVariable, kHistorySize> layout_{};
  std::optional<CoupledPlasticity> coupled_;
  std::unique_ptr<Behavior> nonlinear_;  // nonlinear elastic components without plasticity
  ComponentMask mask_ = 0;
};

const Potential* potential_of(const ConnectorBehavior& behavior, std::size_t plasticity) {
  for (const PotentialOwner& o : behavior.potential_owners) {
    if (o.kind == PotentialOwner::Kind::Plasticity && o.index == static_cast<int>(plasticity) &&
        o.potential >= 0) {
      return &behavior.potentials[static_cast<std::size_t>(o.potential)];
    }
  }
  return nullptr;
}

}  // namespace

std::unique_ptr<Behavior> make_connector_behavior(const ConnectorBehavior& behavior,
                                                  ComponentMask available) {
  const LinearStiffness linear = linear_stiffness(behavior, available);
  std::vector<UncoupledPlasticity> uncoupled;
  std::optional<CoupledPlasticity> coupled;
  for (std::size_t k = 0; k < behavior.plasticities.size(); ++k) {
    const ConnectorPlasticity& p = behavior.plasticities[k];
    if (!p.coupled()) {
      if (!has_component(available, p.component)) continue;
      UncoupledPlasticity u;
      u.slot = p.component - 1;
      u.yield = IsotropicHardeningLaw::from_plasticity(p);
      if (p.kinematic) u.kinematic = KinematicHardeningLaw{p.kinematic->c, p.kinematic->gamma};
      uncoupled.push_back(std::move(u));
      continue;
    }
    const Potential* potential = potential_of(behavior, k);
    if (potential == nullptr) continue;
    CoupledPlasticity c{ConnectorPotential::compile(behavior, *potential),
                        IsotropicHardeningLaw::from_plasticity(p), 0, std::nullopt};
    c.components = static_cast<ComponentMask>(c.potential.components() & available);
    if (c.components != 0) coupled = std::move(c);
  }
  if (uncoupled.empty() && !coupled) return make_elastic_behavior(behavior, available);

  // Components with nonlinear elasticity keep their elastic law (validation keeps plasticity
  // off them); make_elastic_behavior builds it on those components alone.
  ComponentMask nonlinear = 0;
  for (const ConnectorElasticity& e : behavior.elasticities) {
    if (e.kind == ConnectorElasticity::Kind::Nonlinear && has_component(available, e.component)) {
      nonlinear |= component_bit(e.component);
    }
  }
  std::unique_ptr<Behavior> nonlinear_law =
      nonlinear != 0 ? make_nonlinear_elastic_behavior(behavior, nonlinear) : nullptr;
  return std::make_unique<ElasticPlasticBehavior>(linear, std::move(uncoupled), std::move(coupled),
                                                  std::move(nonlinear_law));
}

}  // namespace clinch
