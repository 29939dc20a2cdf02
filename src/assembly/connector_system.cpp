#include "src/assembly/connector_system.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/kinematics/rotation_math.hpp"

namespace clinch {

struct ConnectorSystem::LocalSystem {
  KinematicsResult kinematics;
  // The behaviour's input (behaviors.md §1.1: u = p − ref): the last converged motion and the
  // increment from it.
  Vector6 motion_old, increment;
  Eigen::Matrix<double, kMaxLocalEquations, 1> r;
  Eigen::Matrix<double, kMaxLocalEquations, kMaxLocalEquations> k;
  std::array<std::uint8_t, 6> active{};  // multiplier rows in use
};

namespace {

constexpr DofMask kRotationDofs = 0b111000;

}  // namespace

ConnectorSystem::ConnectorSystem(const Model& model, const AnalysisPlan& plan)
    : model_(model),
      plan_(plan),
      nlgeom_(!plan.small_displacement),
      local_storage_(std::make_unique<LocalSystem>()),
      local_(*local_storage_) {
  const int n = plan_.dofs.equations();
  x_ = Eigen::VectorXd::Zero(n);
  x_n_ = x_;
  dx_n_ = x_;
  target_ = x_;
  internal_ = x_;
  external_ = x_;
  predictor_ = x_;
  prescribed_.assign(static_cast<std::size_t>(n), 0);
  multiplier_active_.assign(static_cast<std::size_t>(n), 0);
  rotation_.assign(plan_.dofs.nodes(), Matrix3::Identity());
  rotation_n_ = rotation_;
  history_.assign(plan_.history_size, 0.0);
  history_n_ = history_;
  dynamic_of_connector_.assign(plan_.connectors.size(), -1);
  for (std::size_t c = 0; c < plan_.connectors.size(); ++c) {
    if (needs_dynamic(plan_.connectors[c])) ensure_dynamic(c);
  }
}

ConnectorSystem::~ConnectorSystem() = default;

bool ConnectorSystem::needs_dynamic(const ConnectorRecord& r) const {
  constexpr ComponentMask kRotational = 0b111000;
  return r.multiplier_count > 0 || ((r.available | r.constrained) & kRotational) ||
         (r.behavior && r.behavior->history_size() > 0);
}

ConnectorSystem::Dynamic* ConnectorSystem::dynamic(std::size_t c) {
  const std::int32_t d = dynamic_of_connector_[c];
  return d < 0 ? nullptr : &dynamics_[static_cast<std::size_t>(d)];
}
const ConnectorSystem::Dynamic* ConnectorSystem::dynamic(std::size_t c) const {
  const std::int32_t d = dynamic_of_connector_[c];
  return d < 0 ? nullptr : &dynamics_[static_cast<std::size_t>(d)];
}

ConnectorSystem::Dynamic& ConnectorSystem::ensure_dynamic(std::size_t c) {
  if (Dynamic* d = dynamic(c)) return *d;
  const ConnectorRecord& r = plan_.connectors[c];
  Dynamic d;
  d.position_n = plan_.kinematics[r.kinematics].initial_position();
  d.motion_n = d.position_n - r.reference;
  dynamic_of_connector_[c] = static_cast<std::int32_t>(dynamics_.size());
  dynamics_.push_back(d);
  return dynamics_.back();
}

void ConnectorSystem::set_nlgeom(bool nlgeom) {
  if (nlgeom && !nlgeom_) {
    // Small rotations become finite ones (NLGEOM stays on once set, keywords.md §13).
    for (std::size_t node = 0; node < plan_.dofs.nodes(); ++node) {
      if (!(plan_.dofs.active(static_cast<std::int32_t>(node)) & kRotationDofs)) continue;
      Vector3 theta = Vector3::Zero();
      for (int k = 0; k < 3; ++k) {
        const int eq = plan_.dofs.equation(static_cast<std::int32_t>(node), 4 + k);
        if (eq >= 0) theta[k] = x_[eq];
      }
      rotation_[node] = rotation_exp(theta);
    }
    rotation_n_ = rotation_;
  }
  nlgeom_ = nlgeom;
}

void ConnectorSystem::clear_conditions() {
  for (int eq : prescribed_list_) prescribed_[static_cast<std::size_t>(eq)] = 0;
  prescribed_list_.clear();
  external_.setZero();
  for (Dynamic& d : dynamics_) {
    d.motion = 0;
    d.connector_load.setZero();
  }
}

void ConnectorSystem::prescribe(int equation, double value) {
  if (!prescribed_[static_cast<std::size_t>(equation)]) {
    prescribed_[static_cast<std::size_t>(equation)] = 1;
    prescribed_list_.push_back(equation);
  }
  target_[equation] = value;
}

void ConnectorSystem::add_load(int equation, double value) { external_[equation] += value; }

void ConnectorSystem::prescribe_motion(int connector, int component, double value) {
  Dynamic& d = ensure_dynamic(static_cast<std::size_t>(connector));
  d.motion |= component_bit(component);
  d.motion_target[component - 1] = value;
}

void ConnectorSystem::add_connector_load(int connector, int component, double value) {
  ensure_dynamic(static_cast<std::size_t>(connector)).connector_load[component - 1] += value;
}

void ConnectorSystem::start_increment(double extrapolate_scale) {
  if (extrapolate_scale != 0) {
    // Prescribed DOFs too, so that the extrapolated state is consistent; what is left of their
    // increment (none under a steady ramp) the first correction takes.
    for (int eq = 0; eq < plan_.dofs.node_equations(); ++eq) {
      if (is_finite_rotation(eq)) continue;
      const double before = x_[eq];
      x_[eq] += extrapolate_scale * dx_n_[eq];
      if (prescribed_[static_cast<std::size_t>(eq)]) snap_to_target(eq, before);
    }
  }
  // Prescribed values stay where they are: the first correction moves them to their targets,
  // with the free DOFs following on the tangent at the start of the increment (docs/decisions.md
  // "Prescribed increments"). Finite rotations are the exception: they jump to their targets.
  snap_prescribed_rotations();
  update_prescribed_predictor();
}

bool ConnectorSystem::is_finite_rotation(int equation) const {
  return nlgeom_ && plan_.dofs.field(equation) == EquationField::Rotation;
}

void ConnectorSystem::snap_to_target(int equation, double before) {
  // u + (target − u) may miss the target by an ulp: a move that was the whole remaining
  // increment lands on it exactly (a partial step, s < 1 of a line search, stays well outside).
  const double target = target_[equation];
  const double scale = std::max(std::abs(target), std::abs(before));
  if (std::abs(x_[equation] - target) <= 1e-12 * scale) x_[equation] = target;
}

void ConnectorSystem::update_prescribed_predictor() {
  predicting_ = false;
  for (int eq : prescribed_list_) predicting_ = predicting_ || x_[eq] != target_[eq];
}

void ConnectorSystem::snap_prescribed_rotations() {
  if (!nlgeom_) return;
  for (int eq : prescribed_list_) {
    if (is_finite_rotation(eq)) x_[eq] = target_[eq];
  }
  apply_prescribed_rotations();
}

void ConnectorSystem::apply_prescribed_rotations() {
  if (!nlgeom_) return;
  // keywords.md §9: under NLGEOM the prescribed values are components of the total rotation
  // vector φ, R = exp(φ̂). A node with some components prescribed and others free keeps its free
  // components of φ (the reaction then acts on spins; documented in docs/decisions.md).
  for (int eq : prescribed_list_) {
    if (plan_.dofs.field(eq) != EquationField::Rotation) continue;
    const std::int32_t node = plan_.dofs.node_of(eq);
    Vector3 phi;
    for (int k = 0; k < 3; ++k) {
      const int e = plan_.dofs.equation(node, 4 + k);
      phi[k] = e >= 0 ? x_[e] : 0.0;
    }
    rotation_[static_cast<std::size_t>(node)] = rotation_exp(phi);
  }
}

NodePose ConnectorSystem::pose(std::int32_t node) const {
  NodePose p;
  if (node < 0) return p;
  for (int k = 0; k < 3; ++k) {
    const int eu = plan_.dofs.equation(node, 1 + k);
    if (eu >= 0) p.u[k] = x_[eu];
    const int er = plan_.dofs.equation(node, 4 + k);
    if (er >= 0) p.theta[k] = x_[er];
  }
  p.rotation = rotation_[static_cast<std::size_t>(node)];
  return p;
}

EvalStatus ConnectorSystem::evaluate_connector(std::size_t c, LocalSystem& local, bool want_tangent,
                                               ConnectorOutput* output) {
  BehaviorOutput behavior;
  EvalStatus status = prepare_connector(c, local, want_tangent, behavior);
  const ConnectorRecord& r = plan_.connectors[c];
  if (status.ok && r.behavior) {
    const BehaviorInput in = behavior_input(c, local);
    status = behavior_status(c, behavior, r.behavior->integrate(in, behavior));
  }
  return status.ok ? finish_connector(c, local, behavior, want_tangent, output) : status;
}

EvalStatus ConnectorSystem::prepare_connector(std::size_t c, LocalSystem& local, bool want_tangent,
                                              BehaviorOutput& behavior) {
  const ConnectorRecord& r = plan_.connectors[c];
  const ConnectorKinematics& kinematics = plan_.kinematics[r.kinematics];
  const Dynamic* d = dynamic(c);
  KinematicsResult& k = local.kinematics;
  kinematics.evaluate(pose(r.nodes[0]), pose(r.nodes[1]), nlgeom_,
                      d ? d->position_n : kinematics.initial_position(), want_tangent && nlgeom_,
                      k);
  if (!k.ok) return {false, fmt::format("connector element {}: {}", label(c), k.message)};
  behavior.force.setZero();
  behavior.tangent.setZero();
  if (!r.behavior) return {};
  local.motion_old = d ? d->motion_n : Vector6(kinematics.initial_position() - r.reference);
  local.increment = k.position - r.reference - local.motion_old;
  behavior.history_new = std::span<double>(history_.data() + r.history,
                                           static_cast<std::size_t>(r.behavior->history_size()));
  return {};
}

BehaviorInput ConnectorSystem::behavior_input(std::size_t c, const LocalSystem& local) const {
  const ConnectorRecord& r = plan_.connectors[c];
  const std::size_t h = static_cast<std::size_t>(r.behavior->history_size());
  return {local.motion_old,
          local.increment,
          time_,
          dt_,
          std::span<const double>(history_n_.data() + r.history, h),
          TangentRequest::Consistent};
}

EvalStatus ConnectorSystem::behavior_status(std::size_t c, const BehaviorOutput& behavior,
                                            IntegrationStatus status) const {
  if (status != IntegrationStatus::Failure) return {};
  return {false, fmt::format("connector element {}: {}", label(c), behavior.message)};
}

std::string ConnectorSystem::label(std::size_t c) const {
  const Element& element = model_.elements[static_cast<std::size_t>(plan_.connectors[c].element)];
  return qualified_label(model_, element.instance, element.label);
}

EvalStatus ConnectorSystem::finish_connector(std::size_t c, LocalSystem& local,
                                             const BehaviorOutput& behavior, bool want_tangent,
                                             ConnectorOutput* output) {
  const ConnectorRecord& r = plan_.connectors[c];
  Dynamic* d = dynamic(c);
  const KinematicsResult& k = local.kinematics;
  const Vector6 u = k.position - r.reference;  // behaviors.md §1.1
  Vector6 elastic = behavior.force;
  const Matrix6& stiffness = behavior.tangent;
  // Multiplier rows (connection-types.md §3.8, behaviors.md §4.4, §5): one per component that
  // can be constrained; inactive rows hold λ = 0.
  Vector6 constraint_force = Vector6::Zero();
  const int n = r.column_count;
  Vector6 gap = Vector6::Zero();
  for (int j = 0; j < r.multiplier_count; ++j) {
    const int i = r.multiplier_components[static_cast<std::size_t>(j)];
    const int eq = r.local.equation[static_cast<std::size_t>(n + j)];
    const double lambda = x_[eq];
    bool active = true;
    double g = 0;
    const auto status =
        d ? static_cast<StopStatus>(d->status[static_cast<std::size_t>(i - 1)]) : StopStatus::Free;
    if (has_component(r.constrained | r.rigid, i)) {
      g = k.change[i - 1];
    } else if (d && has_component(d->motion, i)) {
      g = k.change[i - 1] - d->motion_target[i - 1];
    } else if (status == StopStatus::Locked) {
      g = k.position[i - 1] - d->lock_position[i - 1];
    } else if (status == StopStatus::Lower) {
      g = k.position[i - 1] - *r.stops[static_cast<std::size_t>(i - 1)].lower;
    } else if (status == StopStatus::Upper) {
      g = k.position[i - 1] - *r.stops[static_cast<std::size_t>(i - 1)].upper;
    } else {
      active = false;
    }
    local.active[static_cast<std::size_t>(j)] = active;
    gap[i - 1] = active ? g : lambda;
    if (!active) continue;
    (has_component(r.rigid, i) ? elastic : constraint_force)[i - 1] += lambda;
  }
  const Vector6 applied = d ? d->connector_load : Vector6::Zero();
  const Vector6 total = elastic + constraint_force - applied;  // connection-types.md §4

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
    const Eigen::Matrix<double, 6, 12> db = stiffness * bc;
    local.k.topLeftCorner(n, n) = bc.leftCols(n).transpose() * db.leftCols(n);
    if (nlgeom_) {
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
    for (int j = 0; j < r.multiplier_count; ++j) {
      const int i = r.multiplier_components[static_cast<std::size_t>(j)];
      if (local.active[static_cast<std::size_t>(j)]) {
        for (int a = 0; a < n; ++a) local.k(a, n + j) = local.k(n + j, a) = bc(i - 1, a);
      } else {
        local.k(n + j, n + j) = 1.0;
      }
    }
  }
  if (output) {
    if (r.behavior) {
      const std::size_t h = static_cast<std::size_t>(r.behavior->history_size());
      r.behavior->describe_state(std::span<const double>(history_.data() + r.history, h),
                                 output->behavior);
    }
    const ComponentMask existing = k.existing;
    for (int i = 0; i < 6; ++i) {
      if (!has_component(existing, i + 1)) continue;
      output->position[i] = k.position[i];
      output->change[i] = k.change[i];
      if (has_component(r.available, i + 1)) output->constitutive[i] = u[i];
      output->elastic[i] = elastic[i];
      output->multiplier[i] = constraint_force[i];
      output->applied[i] = applied[i];
      output->total[i] = total[i];
      if (d) output->status[static_cast<std::size_t>(i)] = d->status[static_cast<std::size_t>(i)];
    }
  }
  return {};
}

void ConnectorSystem::evaluate_spring(const SpringRecord& s, LocalSystem& local, bool want_tangent,
                                      double* force_out, double* delta_out) const {
  const SpringLaw& law = *plan_.spring_laws[s.law];
  auto node_vector = [&](std::int32_t node, int first_dof) {
    Vector3 v = Vector3::Zero();
    if (node < 0) return v;
    for (int k = 0; k < 3; ++k) {
      const int eq = plan_.dofs.equation(node, first_dof + k);
      if (eq >= 0) v[k] = x_[eq];
    }
    return v;
  };
  Eigen::Matrix<double, 6, 1> g;  // ∂Δ/∂(node values) on the 6 spring columns
  Eigen::Matrix<double, 6, 6> kg = Eigen::Matrix<double, 6, 6>::Zero();  // geometric part / F
  double delta = 0;
  if (s.type == ElementType::SpringA) {
    // keywords.md §7: exact axial kinematics under NLGEOM, initial direction otherwise.
    const Vector3 du = node_vector(s.nodes[1], 1) - node_vector(s.nodes[0], 1);
    const double l0 = s.d0.norm();
    Vector3 n = s.d0 / l0;
    if (nlgeom_) {
      const Vector3 d = s.d0 + du;
      const double l = d.norm();
      n = d / l;
      delta = l - l0;
      const Matrix3 lateral = (Matrix3::Identity() - n * n.transpose()) / l;
      kg.topLeftCorner<3, 3>() = lateral;
      kg.bottomRightCorner<3, 3>() = lateral;
      kg.topRightCorner<3, 3>() = -lateral;
      kg.bottomLeftCorner<3, 3>() = -lateral;
    } else {
      delta = n.dot(du);
    }
    g << -n, n;
  } else {
    const int first = s.rotational ? 4 : 1;
    g.head<3>() = s.direction[0];
    g.tail<3>() = s.type == ElementType::Spring2 ? Vector3(-s.direction[1]) : Vector3::Zero();
    delta = s.direction[0].dot(node_vector(s.nodes[0], first));
    if (s.type == ElementType::Spring2) delta -= s.direction[1].dot(node_vector(s.nodes[1], first));
  }
  const SpringResponse response = law.evaluate(delta);
  if (force_out) *force_out = response.force;
  if (delta_out) *delta_out = delta;
  for (int a = 0; a < s.column_count; ++a) {
    local.r[a] = response.force * g[s.columns[static_cast<std::size_t>(a)]];
  }
  if (!want_tangent) return;
  for (int b = 0; b < s.column_count; ++b) {
    const int cb = s.columns[static_cast<std::size_t>(b)];
    for (int a = 0; a < s.column_count; ++a) {
      const int ca = s.columns[static_cast<std::size_t>(a)];
      local.k(a, b) = response.stiffness * g[ca] * g[cb] + response.force * kg(ca, cb);
    }
  }
}

void ConnectorSystem::scatter(const LocalEquations& l, const LocalSystem& local,
                              SparseMatrix* tangent) {
  for (int a = 0; a < l.count; ++a)
    internal_[l.equation[static_cast<std::size_t>(a)]] += local.r[a];
  if (!tangent) return;
  const int* position = plan_.positions.data() + l.positions;
  double* values = tangent->values.data();
  for (int b = 0; b < l.count; ++b) {
    const int eb = l.equation[static_cast<std::size_t>(b)];
    const bool fixed_b = prescribed_[static_cast<std::size_t>(eb)];
    for (int a = 0; a <= b; ++a, ++position) {
      const int ea = l.equation[static_cast<std::size_t>(a)];
      const bool fixed_a = prescribed_[static_cast<std::size_t>(ea)];
      if (!fixed_a && !fixed_b) {
        values[*position] += local.k(a, b);
      } else if (predicting_ && fixed_a != fixed_b) {
        // The prescribed column leaves the matrix for the right-hand side: K_fp·Δu_p.
        const int free = fixed_a ? eb : ea, fixed = fixed_a ? ea : eb;
        predictor_[free] += local.k(a, b) * (target_[fixed] - x_[fixed]);
      }
    }
  }
}

void ConnectorSystem::finish_scatter(std::size_t c, const LocalSystem& local,
                                     SparseMatrix* tangent) {
  const ConnectorRecord& r = plan_.connectors[c];
  for (int j = 0; j < r.multiplier_count; ++j) {
    multiplier_active_[static_cast<std::size_t>(
        r.local.equation[static_cast<std::size_t>(r.column_count + j)])] =
        local.active[static_cast<std::size_t>(j)];
  }
  scatter(r.local, local, tangent);
}

EvalStatus ConnectorSystem::evaluate(Eigen::VectorXd& residual, SparseMatrix* tangent) {
  internal_.setZero();
  if (predicting_) predictor_.setZero();
  if (tangent) std::fill(tangent->values.begin(), tangent->values.end(), 0.0);
  const bool want_tangent = tangent != nullptr;
  LocalSystem& local = local_;
  for (std::size_t c = 0; c < plan_.connectors.size(); ++c) {
    const EvalStatus status = evaluate_connector(c, local, want_tangent, nullptr);
    if (!status.ok) return status;
    finish_scatter(c, local, tangent);
  }
  for (const SpringRecord& s : plan_.springs) {
    evaluate_spring(s, local, want_tangent, nullptr, nullptr);
    scatter(s.local, local, tangent);
  }
  residual = internal_ - external_;
  if (predicting_ && tangent) residual += predictor_;
  for (int eq : prescribed_list_) {
    // Newton's row of a prescribed DOF is Δu = target − u.
    residual[eq] = x_[eq] - target_[eq];
    if (tangent)
      tangent->values[static_cast<std::size_t>(plan_.diagonal[static_cast<std::size_t>(eq)])] = 1.0;
  }
  return {};
}

void ConnectorSystem::apply_correction(const Eigen::VectorXd& dx) {
  if (!nlgeom_) {
    x_ += dx;
    finish_prescribed_correction(dx);
    return;
  }
  for (int eq = 0; eq < size(); ++eq) {
    if (plan_.dofs.field(eq) != EquationField::Rotation) x_[eq] += dx[eq];
  }
  // Finite rotations: R ← exp(Δθ̂) R with Δθ a spatial spin (connection-types.md §3.2); the
  // reported φ = log R is kept on the branch of the previous value.
  for (std::size_t node = 0; node < plan_.dofs.nodes(); ++node) {
    const auto n = static_cast<std::int32_t>(node);
    if (!(plan_.dofs.active(n) & kRotationDofs)) continue;
    Vector3 spin = Vector3::Zero(), previous = Vector3::Zero();
    std::array<int, 3> eqs{};
    for (int k = 0; k < 3; ++k) {
      eqs[static_cast<std::size_t>(k)] = plan_.dofs.equation(n, 4 + k);
      if (eqs[static_cast<std::size_t>(k)] >= 0) {
        spin[k] = dx[eqs[static_cast<std::size_t>(k)]];
        previous[k] = x_[eqs[static_cast<std::size_t>(k)]];
      }
    }
    rotation_[node] = rotation_exp(spin) * rotation_[node];
    Vector3 phi = rotation_log(rotation_[node]);
    if (const int turns = rotation_vector_turns(phi, previous); turns != 0) {
      phi *= 1.0 + 2.0 * std::numbers::pi * turns / phi.norm();
    }
    for (int k = 0; k < 3; ++k) {
      if (eqs[static_cast<std::size_t>(k)] >= 0) x_[eqs[static_cast<std::size_t>(k)]] = phi[k];
    }
  }
  snap_prescribed_rotations();
  finish_prescribed_correction(dx);
}

void ConnectorSystem::finish_prescribed_correction(const Eigen::VectorXd& dx) {
  for (int eq : prescribed_list_) snap_to_target(eq, x_[eq] - dx[eq]);
  update_prescribed_predictor();
}

void ConnectorSystem::measure(const Eigen::VectorXd& residual, const Eigen::VectorXd* correction,
                              IterationNorms& norms) const {
  double flux_sum[2] = {0, 0};
  int flux_count[2] = {0, 0};
  double residual_sq = 0, correction_sq = 0;
  for (int eq = 0; eq < size(); ++eq) {
    const EquationField field = plan_.dofs.field(eq);
    if (field == EquationField::TranslationalMultiplier ||
        field == EquationField::RotationalMultiplier) {
      if (!multiplier_active_[static_cast<std::size_t>(eq)]) continue;
      // keywords.md §16: |g| ≤ 1e-8·L̄ (translations) or 1e-8 rad (rotations).
      const double tolerance =
          1e-8 * (field == EquationField::TranslationalMultiplier ? plan_.length_scale : 1.0);
      norms.constraint_violation =
          std::max(norms.constraint_violation, std::abs(residual[eq]) / tolerance);
      continue;
    }
    const int f = field == EquationField::Translation ? 0 : 1;
    const double force = std::abs(internal_[eq]) + std::abs(external_[eq]);
    if (force > 0) {
      flux_sum[f] += force;
      ++flux_count[f];
    }
    if (prescribed_[static_cast<std::size_t>(eq)]) continue;
    norms.largest_residual[f] = std::max(norms.largest_residual[f], std::abs(residual[eq]));
    residual_sq += residual[eq] * residual[eq];
    norms.largest_increment[f] = std::max(norms.largest_increment[f], std::abs(x_[eq] - x_n_[eq]));
    if (correction) {
      const double dx = (*correction)[eq];
      norms.largest_correction[f] = std::max(norms.largest_correction[f], std::abs(dx));
      correction_sq += dx * dx;
    }
  }
  for (int f = 0; f < 2; ++f) norms.flux[f] = flux_count[f] ? flux_sum[f] / flux_count[f] : 0.0;
  norms.resolution[0] = 1e-12 * plan_.length_scale;
  norms.resolution[1] = 1e-12;
  const double force_scale = std::max(norms.flux[0], norms.flux[1] / plan_.length_scale);
  norms.force_resolution[0] = 1e-12 * force_scale;
  norms.force_resolution[1] = 1e-12 * force_scale * plan_.length_scale;
  norms.residual_norm = std::sqrt(residual_sq);
  norms.correction_norm = std::sqrt(correction_sq);
}

void ConnectorSystem::commit() {
  dx_n_ = x_ - x_n_;
  x_n_ = x_;
  rotation_n_ = rotation_;
  // The evaluation below starts from the old committed state, so it reproduces the converged
  // trial history; the history is committed after it.
  LocalSystem local;
  for (std::size_t c = 0; c < plan_.connectors.size(); ++c) {
    Dynamic* d = dynamic(c);
    if (!d) continue;
    ConnectorOutput out;
    evaluate_connector(c, local, false, &out);
    const ConnectorRecord& r = plan_.connectors[c];
    d->position_n = out.position;
    d->motion_n = out.position - r.reference;
    d->status_n = d->status;
  }
  history_n_ = history_;
}

void ConnectorSystem::revert() {
  x_ = x_n_;
  rotation_ = rotation_n_;
  history_ = history_n_;
  for (Dynamic& d : dynamics_) d.status = d.status_n;
}

bool ConnectorSystem::update_stops() {
  bool changed = false;
  LocalSystem local;
  for (std::size_t c = 0; c < plan_.connectors.size(); ++c) {
    const ConnectorRecord& r = plan_.connectors[c];
    Dynamic* d = dynamic(c);
    if (!d) continue;
    ConnectorOutput out;
    bool evaluated = false;
    for (int i = 1; i <= 6; ++i) {
      const ConnectorStopLimits& stop = r.stops[static_cast<std::size_t>(i - 1)];
      if (!stop.lower && !stop.upper) continue;
      if (has_component(d->motion, i)) continue;
      auto& status = d->status[static_cast<std::size_t>(i - 1)];
      if (status == static_cast<std::uint8_t>(StopStatus::Locked)) continue;
      if (!evaluated) {
        evaluate_connector(c, local, false, &out);
        evaluated = true;
      }
      // behaviors.md §5.1: tol_p = 1e-8·max(1, |limit|), tol_f = 1e-8·max(1, max|f|).
      const double p = out.position[i - 1];
      const double lambda = out.multiplier[i - 1];
      const double tol_f = 1e-8 * std::max(1.0, out.total.cwiseAbs().maxCoeff());
      auto violated = [&](const std::optional<double>& limit, double sign) {
        return limit && sign * (p - *limit) > 1e-8 * std::max(1.0, std::abs(*limit));
      };
      std::uint8_t next = status;
      if (status == static_cast<std::uint8_t>(StopStatus::Upper) && lambda < -tol_f) next = 0;
      if (status == static_cast<std::uint8_t>(StopStatus::Lower) && lambda > tol_f) next = 0;
      if (next == 0 && violated(stop.upper, 1.0))
        next = static_cast<std::uint8_t>(StopStatus::Upper);
      if (next == 0 && violated(stop.lower, -1.0))
        next = static_cast<std::uint8_t>(StopStatus::Lower);
      if (next != status) {
        status = next;
        changed = true;
      }
    }
  }
  return changed;
}

void ConnectorSystem::engage_locks() {
  LocalSystem local;
  for (std::size_t c = 0; c < plan_.connectors.size(); ++c) {
    const ConnectorRecord& r = plan_.connectors[c];
    if (r.locks.empty()) continue;
    Dynamic& d = *dynamic(c);
    ConnectorOutput out;
    evaluate_connector(c, local, false, &out);
    for (const ConnectorLockRule& rule : r.locks) {
      const double p = out.position[rule.component - 1];
      const double f = out.total[rule.component - 1];
      const ConnectorCriterionBounds& b = rule.bounds;
      const bool met = (b.position_lower && p <= *b.position_lower) ||
                       (b.position_upper && p >= *b.position_upper) ||
                       (b.force_lower && f <= *b.force_lower) ||
                       (b.force_upper && f >= *b.force_upper);
      if (!met) continue;
      for (int i = 1; i <= 6; ++i) {
        if (!has_component(rule.locks, i)) continue;
        d.status[static_cast<std::size_t>(i - 1)] = static_cast<std::uint8_t>(StopStatus::Locked);
        d.status_n[static_cast<std::size_t>(i - 1)] = d.status[static_cast<std::size_t>(i - 1)];
        d.lock_position[i - 1] = out.position[i - 1];
      }
    }
  }
}

double ConnectorSystem::nodal_value(std::int32_t node, int dof) const {
  const int eq = plan_.dofs.equation(node, dof);
  return eq >= 0 ? x_[eq] : 0.0;
}

double ConnectorSystem::reaction(std::int32_t node, int dof) const {
  const int eq = plan_.dofs.equation(node, dof);
  if (eq < 0 || !prescribed_[static_cast<std::size_t>(eq)]) return 0.0;
  return internal_[eq] - external_[eq];
}

double ConnectorSystem::applied_load(std::int32_t node, int dof) const {
  const int eq = plan_.dofs.equation(node, dof);
  return eq >= 0 ? external_[eq] : 0.0;
}

ConnectorOutput ConnectorSystem::connector_output(std::size_t connector) {
  ConnectorOutput out;
  LocalSystem local;
  evaluate_connector(connector, local, false, &out);
  return out;
}

void ConnectorSystem::spring_output(std::size_t spring, double& force, double& delta) const {
  LocalSystem local;
  evaluate_spring(plan_.springs[spring], local, false, &force, &delta);
}

}  // namespace clinch
