#include "src/assembly/connector_element.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace clinch {
namespace {

// The constraint equation g of a multiplier row and whether it is active (connection-types.md
// §3.8, behaviors.md §4.4, §5): constrained and RIGID components hold c_i = 0, a connector motion
// holds c_i at its target, a lock at its position, a stop at its limit; an inactive row holds
// λ = 0, and so does every row of a component released by *CONNECTOR FAILURE.
bool constraint_gap(const ConnectorRecord& r, const ConnectorConditions& conditions,
                    const ConnectorActiveSet& set, const KinematicsResult& k, int i, double& g) {
  const auto slot = static_cast<std::size_t>(i - 1);
  const auto status = static_cast<StopStatus>(set.status[slot]);
  if (has_component(r.constrained, i)) {
    g = k.change[i - 1];
  } else if (has_component(set.released, i)) {
    return false;  // §5.3: free from then on
  } else if (has_component(r.rigid, i)) {
    g = k.change[i - 1];
  } else if (has_component(conditions.motion, i)) {
    g = k.change[i - 1] - conditions.motion_target[i - 1];
  } else if (status == StopStatus::Locked) {
    g = k.position[i - 1] - set.lock_position[i - 1];
  } else if (status == StopStatus::Lower) {
    g = k.position[i - 1] - *r.stop(i).lower;
  } else if (status == StopStatus::Upper) {
    g = k.position[i - 1] - *r.stop(i).upper;
  } else {
    return false;
  }
  return true;
}

}  // namespace

NodePose node_pose(const DofMap& dofs, const AnalysisState& state, std::int32_t node) {
  NodePose p;
  if (node < 0) return p;
  for (int k = 0; k < 3; ++k) {
    const int eu = dofs.equation(node, 1 + k);
    if (eu >= 0) p.u[k] = state.x[eu];
    const int er = dofs.equation(node, 4 + k);
    if (er >= 0) p.theta[k] = state.x[er];
  }
  if (!state.rotation.empty()) p.rotation = state.rotation[static_cast<std::size_t>(node)];
  return p;
}

std::string ConnectorElements::label(std::size_t c) const {
  const Element& element = model_.elements[static_cast<std::size_t>(plan_.connectors[c].element)];
  return qualified_label(model_, element.instance, element.label);
}

bool is_deleted(const ConnectorRecord& r, const AnalysisState& state) {
  for (const LawSlot& slot : r.laws) {
    if (slot.law->deletes_element(slot.history_in(state.history_n))) return true;
  }
  return false;
}

namespace {

// CP, CU and CCU of an evaluation (output-variables.md §2): the constitutive motion only on the
// available components that exist.
void record_motions(const ConnectorRecord& r, const KinematicsResult& k, ConnectorResult& result) {
  result.position = k.position;
  result.change = k.change;
  const Vector6 u = k.position - r.reference;
  for (int i = 0; i < 6; ++i) {
    const bool exists = has_component(k.existing, i + 1);
    result.constitutive[i] = exists && has_component(r.available, i + 1) ? u[i] : 0.0;
  }
}

}  // namespace

// A deleted element (behaviors.md §7.4): no force, no stiffness, every multiplier row inactive
// (λ = 0), its laws' history frozen at deletion and its forces reported as 0. Its motions go on
// reporting the kinematics of its nodes (output-variables.md §2), so that an analyst sees how far
// the parts separated; where the kinematics is undefined (an AXIAL connector whose nodes meet)
// they keep their last values, since a deleted element cannot stop the run.
EvalStatus ConnectorElements::evaluate_deleted(std::size_t c, const ElementContext& context,
                                               AnalysisState& state, bool want_tangent,
                                               LocalSystem& local) const {
  const ConnectorRecord& r = plan_.connectors[c];
  const int n = r.column_count;
  for (const LawSlot& slot : r.laws) {
    std::copy_n(state.history_n.begin() + static_cast<std::ptrdiff_t>(slot.history),
                slot.law->history_size(),
                state.history.begin() + static_cast<std::ptrdiff_t>(slot.history));
  }
  for (int a = 0; a < n; ++a) local.r[a] = 0.0;
  for (int j = 0; j < r.multiplier_count; ++j) {
    local.active[static_cast<std::size_t>(j)] = 0;
    local.r[n + j] = state.x[r.local.equation[static_cast<std::size_t>(n + j)]];
  }
  if (want_tangent) {
    const int m = n + r.multiplier_count;
    local.k.topLeftCorner(m, m).setZero();
    for (int j = 0; j < r.multiplier_count; ++j) local.k(n + j, n + j) = 1.0;
  }
  ConnectorResult& result = state.results[c];
  KinematicsResult& k = local.kinematics;
  plan_.kinematics[r.kinematics].evaluate(node_pose(plan_.dofs, state, r.nodes[0]),
                                          node_pose(plan_.dofs, state, r.nodes[1]), context.nlgeom,
                                          state.position_n[c], false, k);
  if (k.ok) record_motions(r, k, result);
  for (Vector6* v : {&result.elastic, &result.multiplier, &result.friction, &result.viscous,
                     &result.applied, &result.total, &result.velocity, &result.acceleration}) {
    v->setZero();
  }
  return {};
}

EvalStatus ConnectorElements::evaluate(std::size_t c, const ElementContext& context,
                                       AnalysisState& state, bool want_tangent,
                                       LocalSystem& local) const {
  const ConnectorRecord& r = plan_.connectors[c];
  if (is_deleted(r, state)) return evaluate_deleted(c, context, state, want_tangent, local);
  KinematicsResult& k = local.kinematics;
  plan_.kinematics[r.kinematics].evaluate(node_pose(plan_.dofs, state, r.nodes[0]),
                                          node_pose(plan_.dofs, state, r.nodes[1]), context.nlgeom,
                                          state.position_n[c], want_tangent && context.nlgeom, k);
  if (!k.ok) return {false, fmt::format("connector element {}: {}", label(c), k.message)};

  // The multipliers first: the laws may read the constraint forces they give.
  const ConnectorConditions& conditions = context.conditions.connector(plan_.first_connector + c);
  const ConnectorActiveSet& set = state.active_sets[c];
  const int n = r.column_count;
  Vector6 reaction = Vector6::Zero(), gap = Vector6::Zero();
  for (int j = 0; j < r.multiplier_count; ++j) {
    const int i = r.multiplier_components[static_cast<std::size_t>(j)];
    const double lambda = state.x[r.local.equation[static_cast<std::size_t>(n + j)]];
    double g = 0;
    const bool active = constraint_gap(r, conditions, set, k, i, g);
    local.active[static_cast<std::size_t>(j)] = active;
    gap[i - 1] = active ? g : lambda;
    if (active) reaction[i - 1] += lambda;
  }

  // The law stack (§1.3), on the constitutive motion u = p − ref (§1.1). A released component
  // (§5.3) is held at its motion at release, so that its laws' history stays frozen.
  const Vector6 u = k.position - r.reference;
  Vector6 motion_old = state.position_n[c] - r.reference;
  Vector6 law_motion = u;
  for (int i = 0; i < 6; ++i) {
    if (has_component(set.released, i + 1)) law_motion[i] = motion_old[i] = set.release_motion[i];
  }
  const Vector6 increment = law_motion - motion_old;
  // The rates of the components from the nodal rates (those of a dynamic step's operator, the
  // initial velocities in the initial state, 0 in a static step): B v and B a (CV, CA;
  // docs/dynamics.md); a released component's damping sees none.
  Vector6 velocity = Vector6::Zero(), acceleration = Vector6::Zero();
  if (state.v.size() > 0) {
    for (int a = 0; a < n; ++a) {
      const int eq = r.local.equation[static_cast<std::size_t>(a)];
      if (eq < 0 || eq >= state.v.size()) continue;
      const auto column = k.b.col(r.columns[static_cast<std::size_t>(a)]);
      velocity += column * state.v[eq];
      acceleration += column * state.a[eq];
    }
  }
  state.results[c].velocity = velocity;
  state.results[c].acceleration = acceleration;
  for (int i = 0; i < 6; ++i) {
    if (has_component(set.released, i + 1)) velocity[i] = 0.0;
  }
  // Connector damping reads its velocity as increment/Δt and its tangent as 1/Δt (the laws'
  // contract): in a dynamic step it gets the increment v Δt' over Δt' = 1/(∂v₁/∂u₁), so that it
  // sees the true velocity and its tangent the operator's ∂v₁/∂u₁, as a dashpot does.
  const double rate_dt = context.dv_du > 0.0 ? 1.0 / context.dv_du : 1.0;
  const Vector6 rate_increment = velocity * rate_dt;
  Vector6 law_force = Vector6::Zero(), friction = Vector6::Zero(), viscous = Vector6::Zero();
  Matrix6 stiffness = Matrix6::Zero(), force_stiffness = Matrix6::Zero();
  const TangentRequest request = want_tangent ? TangentRequest::Consistent : TangentRequest::None;
  bool first = true;
  const LawSlot* below = nullptr;
  for (const LawSlot& slot : r.laws) {
    const std::size_t size = slot.law->history_size();
    BehaviorOutput out;
    out.history_new = std::span<double>(state.history.data() + slot.history, size);
    const bool true_rate = context.dynamic && slot.law->force_kind() == ForceKind::Viscous;
    const BehaviorInput in{
        motion_old,
        true_rate ? rate_increment : increment,
        context.time,
        true_rate ? rate_dt : context.dt,
        std::span<const double>(state.history_n.data() + slot.history, size),
        request,
        first ? nullptr : &law_force,
        first ? nullptr : &stiffness,
        first || !r.laws.needs_connector_forces ? nullptr : &force_stiffness,
        r.laws.needs_connector_forces ? &reaction : nullptr,
        below ? std::span<const double>(state.history.data() + below->history,
                                        below->law->history_size())
              : std::span<const double>(),
        below ? below->law->history_layout() : std::span<const HistoryVariable>()};
    const IntegrationStatus status = slot.law->integrate(in, out);
    if (status == IntegrationStatus::Failure) {
      return {false, fmt::format("connector element {}: {}", label(c), out.message)};
    }
    if (status == IntegrationStatus::Unreliable || std::isfinite(out.suggested_dt_ratio)) {
      merge_step_request(state.request, out.suggested_dt_ratio,
                         status == IntegrationStatus::Unreliable,
                         fmt::format("connector element {}: {}", label(c), out.message));
    }
    if (!out.warning.empty()) {
      state.request.warnings.push_back(
          {plan_.first_connector + c,
           fmt::format("connector element {}: {}", label(c), out.warning)});
    }
    law_force += out.force;
    if (slot.law->force_kind() == ForceKind::Friction) friction += out.force;
    if (slot.law->force_kind() == ForceKind::Viscous) viscous += out.force;
    if (want_tangent) {
      stiffness += out.tangent;
      if (slot.law->needs_connector_forces()) force_stiffness += out.force_tangent;
    }
    first = false;
    below = &slot;
  }

  // §5.3: every behaviour force on a released component is zero, and nothing depends on its
  // (frozen) motion.
  for (int i = 0; i < 6; ++i) {
    if (!has_component(set.released, i + 1)) continue;
    law_force[i] = friction[i] = viscous[i] = 0.0;
    if (want_tangent) {
      stiffness.row(i).setZero();
      stiffness.col(i).setZero();
      force_stiffness.row(i).setZero();
    }
  }

  // Forces (connection-types.md §4): RIGID multipliers are elastic forces (CEF), the others CRF;
  // viscous forces CVF and friction forces CSF (output-variables.md §2).
  Vector6 elastic = law_force - friction - viscous, constraint_force = Vector6::Zero();
  for (int i = 0; i < 6; ++i) {
    (has_component(r.rigid, i + 1) ? elastic : constraint_force)[i] += reaction[i];
  }
  const Vector6& applied = conditions.load;
  const Vector6 total = elastic + viscous + friction + constraint_force - applied;

  for (int a = 0; a < n; ++a) {
    local.r[a] = k.b.col(r.columns[static_cast<std::size_t>(a)]).dot(total);
  }
  for (int j = 0; j < r.multiplier_count; ++j) {
    local.r[n + j] = gap[r.multiplier_components[static_cast<std::size_t>(j)] - 1];
  }
  if (want_tangent) {
    const int m = n + r.multiplier_count;
    local.k.topLeftCorner(m, m).setZero();
    Eigen::Matrix<double, 6, 12> bc;
    for (int a = 0; a < n; ++a) bc.col(a) = k.b.col(r.columns[static_cast<std::size_t>(a)]);
    local.k.topLeftCorner(n, n) = bc.leftCols(n).transpose() * (stiffness * bc.leftCols(n));
    if (context.nlgeom) {
      // Geometric stiffness Σ f_i H_i (connection-types.md §3.7).
      for (int i = 0; i < 6; ++i) {
        if (total[i] == 0 || !has_component(k.existing, i + 1)) continue;
        for (int b = 0; b < n; ++b) {
          for (int a = 0; a < n; ++a) {
            local.k(a, b) +=
                total[i] * k.h[static_cast<std::size_t>(i)](r.columns[static_cast<std::size_t>(a)],
                                                            r.columns[static_cast<std::size_t>(b)]);
          }
        }
      }
    }
    // The laws' force against the constraint forces: unsymmetric columns of the multipliers.
    Eigen::Matrix<double, 12, 6> against_reaction;
    if (r.laws.needs_connector_forces) {
      against_reaction.topRows(n) = bc.leftCols(n).transpose() * force_stiffness;
    }
    for (int j = 0; j < r.multiplier_count; ++j) {
      const int i = r.multiplier_components[static_cast<std::size_t>(j)];
      if (!local.active[static_cast<std::size_t>(j)]) {
        local.k(n + j, n + j) = 1.0;
        continue;
      }
      for (int a = 0; a < n; ++a) local.k(a, n + j) = local.k(n + j, a) = bc(i - 1, a);
      if (r.laws.needs_connector_forces) {
        for (int a = 0; a < n; ++a) local.k(a, n + j) += against_reaction(a, i - 1);
      }
    }
  }

  ConnectorResult& result = state.results[c];
  record_motions(r, k, result);
  for (int i = 0; i < 6; ++i) {
    const bool exists = has_component(k.existing, i + 1);
    result.elastic[i] = exists ? elastic[i] : 0.0;
    result.multiplier[i] = exists ? constraint_force[i] : 0.0;
    result.friction[i] = exists ? friction[i] : 0.0;
    result.viscous[i] = exists ? viscous[i] : 0.0;
    result.applied[i] = exists ? applied[i] : 0.0;
    result.total[i] = exists ? total[i] : 0.0;
  }
  return {};
}

}  // namespace clinch
