#include "src/assembly/connector_system.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "base/scaled_norm.hpp"
#include "src/assembly/active_set_updates.hpp"
#include "src/assembly/rotary_inertia_finite.hpp"
#include "src/assembly/sparsity_pattern.hpp"
#include "src/kinematics/rotation_math.hpp"

namespace clinch {
namespace {

constexpr DofMask kRotationDofs = 0b111000;

// std::max(a, NaN) is a: the norms keep a NaN, so that the log shows it instead of a zero.
double max_keeping_nan(double a, double b) { return std::isnan(b) ? b : std::max(a, b); }

// v·0 is 0 for a finite v and NaN for an infinite or NaN one: one sum tests every value at once,
// cheaply enough for the hot path, and without the overflow a sum of the values could make.
template <typename Vector>
double zero_unless_non_finite(const Vector& v) {
  return (v.array() * 0.0).sum();
}

}  // namespace

double ConnectorOutput::history_value(std::string_view output, int component) const {
  for (const LawHistory& law : laws) {
    const int slot = history_slot(law.layout, output, component);
    if (slot >= 0) return law.values[static_cast<std::size_t>(slot)];
  }
  return 0.0;
}

double ConnectorOutput::scalar_equivalent_plastic() const {
  for (const LawHistory& law : laws) {
    const int slot = history_slot(law.layout, "CUPEQC", 0);
    if (slot >= 0) return law.values[static_cast<std::size_t>(slot)];
  }
  double largest = 0;
  for (int i = 1; i <= 6; ++i) largest = std::max(largest, history_value("CUPEQ", i));
  return largest;
}

ConnectorSystem::ConnectorSystem(const Model& model, const AnalysisPlan& plan)
    : model_(model),
      plan_(plan),
      elements_(model, plan),
      state_(plan),
      conditions_(plan),
      context_{conditions_, !plan.small_displacement},
      local_(std::make_unique<LocalSystem>()),
      springs_(plan.springs.size()),
      multiplier_active_(static_cast<std::size_t>(plan.dofs.equations()), 0),
      internal_(Eigen::VectorXd::Zero(plan.dofs.equations())),
      predictor_(internal_),
      deleted_(plan.connectors.size(), 0),
      owned_connectors_{0, plan.connectors.size()},
      owned_springs_{plan.first_spring, plan.first_spring + plan.springs.size()},
      motion_(plan.dependents, plan.dofs),
      constraint_load_(Eigen::VectorXd::Zero(plan.dependents.empty() ? 0 : plan.dofs.equations())),
      inertia_force_(Eigen::VectorXd::Zero(plan.dynamic ? plan.dofs.equations() : 0)),
      stabilization_(plan.dofs, plan.dependents, plan.length_scale),
      stabilization_force_(Eigen::VectorXd::Zero(plan.stabilized ? plan.dofs.equations() : 0)) {
  if (plan.energies) {
    std::vector<bool> dashpots;
    for (const SpringRecord& s : plan.springs) dashpots.push_back(s.dashpot);
    energy_.emplace(plan.dofs.node_equations(), plan.connectors.size(), std::move(dashpots));
  }
  // *INITIAL CONDITIONS, TYPE=VELOCITY: the velocities of the initial state.
  for (const InitialVelocity& velocity : model.history.initial_velocities) {
    for (std::int32_t node : velocity.resolved) {
      const int eq = plan.dofs.equation(node, velocity.dof);
      if (eq >= 0 && state_.v.size() > 0) state_.v[eq] = state_.v_n[eq] = velocity.value;
    }
  }
  if (state_.v_n.size() > 0 && !plan.dependents.empty()) {
    // A constrained node moves with the DOFs it depends on: its initial velocity is theirs
    // through the constraint, whatever was given on it (docs/dynamics.md).
    motion_.update_gradients(state_.x, state_.rotation, false);
    follow_constraint_rates(plan.dependents, motion_, state_.x, state_.rotation, false, state_.v_n,
                            nullptr);
    state_.v = state_.v_n;
  }
  if (plan_.dynamic) initial_kinetic_ = kinetic(state_.v_n, state_.rotation_n);
  if (energy_) energy_->set_kinetic(initial_kinetic_);
}

void ConnectorSystem::set_integration(const DynamicProcedure* procedure, double dt) {
  if (procedure) {
    newmark_ = NewmarkIncrement::of(*procedure, dt);
    return;
  }
  newmark_.reset();
  state_.v.setZero();
  state_.a.setZero();
  inertia_force_.setZero();
}

void ConnectorSystem::start_dynamic_step(bool initial_acceleration) {
  newmark_ = NewmarkIncrement{};
  rates_frozen_ = true;
  state_.v = state_.v_n;
  state_.a = state_.a_n;
  Eigen::VectorXd residual(size());
  // A failure here fails the first Newton evaluation of the increment again, which reports it.
  const EvalStatus status = evaluate(residual, nullptr);
  rates_frozen_ = false;
  if (!status.ok) return;
  const Eigen::VectorXd condensed = static_residual();
  if (energy_) energy_->restart(energy_forces());
  // Without INITIAL=YES the step starts from the accelerations it has.
  if (initial_acceleration) {
    initial_accelerations(plan_.own_inertia(), conditions_, condensed, state_.a_n);
    // Under vectors by rows each constraint lies on one rank: inertia on some rank's dependent
    // DOFs has every rank's dependent accelerations follow, as in one process.
    std::array<std::uint8_t, 1> constrained{!constrained_inertia_.empty()};
    if (halo_) communicator_->max(constrained);
    if (constrained[0] != 0) {
      // The velocity-product terms first (the independent accelerations zero), then the
      // condensed solve, then the dependent accelerations that follow from it.
      for (const MappedInertiaBlock& b : constrained_inertia_) {
        for (const int column : b.columns) state_.a_n[column] = 0.0;
      }
      follow_constraint_rates(plan_.dependents, motion_, state_.x, state_.rotation, context_.nlgeom,
                              state_.v_n, &state_.a_n);
      constrained_initial_accelerations(plan_.own_inertia(), constrained_inertia_, conditions_,
                                        condensed, state_.a_n);
      follow_constraint_rates(plan_.dependents, motion_, state_.x, state_.rotation, context_.nlgeom,
                              state_.v_n, &state_.a_n);
      state_.v = state_.v_n;
    }
    // Only the owners of the rows solved for their accelerations: the ghosts take them.
    if (halo_)
      halo_->copy_to_ghosts({state_.a_n.data(), static_cast<std::size_t>(state_.a_n.size())});
    state_.a = state_.a_n;
  }
  state_.r_n = hht_residual(condensed, true);
  r_before_ = state_.r_n;
  if (initial_acceleration) {
    // Once more at the initial accelerations, so that CA and the results hold them.
    rates_frozen_ = true;
    evaluate(residual, nullptr);
    rates_frozen_ = false;
  }
  keep_converged_components();
}

void ConnectorSystem::keep_converged_components() {
  converged_components_.resize(state_.results.size());
  for (std::size_t c = 0; c < state_.results.size(); ++c) {
    const ConnectorResult& r = state_.results[c];
    converged_components_[c] = {r.change, r.velocity, r.acceleration};
  }
}

ConnectorSystem::HalfIncrementResidual ConnectorSystem::half_increment_residual() {
  HalfIncrementResidual out;
  if (!newmark_) return out;
  const std::vector<Matrix3> end_rotation = state_.rotation;
  newmark_->set_half_increment_state(state_, plan_.dofs);
  // Finite rotations: half of the increment's spin, R = exp(½ log(R₁R₀ᵀ)) R₀.
  for (std::size_t node = 0; node < state_.rotation.size(); ++node) {
    const Matrix3& start = state_.rotation_n[node];
    state_.rotation[node] =
        rotation_exp(0.5 * rotation_log(end_rotation[node] * start.transpose())) * start;
  }
  update_dependents();
  rates_frozen_ = true;
  Eigen::VectorXd residual(size());
  out.status = evaluate(residual, nullptr);
  rates_frozen_ = false;
  if (!out.status.ok) return out;
  const Eigen::VectorXd& full = plan_.dependents.empty() ? residual : full_residual_;
  // The nodal rows this rank owns (ConnectorStepProblem joins the ranks' largest).
  for (int eq = 0; eq < plan_.dofs.equations(); ++eq) {
    if (plan_.dofs.node_of(eq) < 0 || !reports(eq) || conditions_.is_prescribed(eq) ||
        plan_.dependents.is_dependent(eq)) {
      continue;
    }
    // clinch's rows are the HHT equation divided by 1 + α, with −α r₀ (dynamic_terms.hpp):
    // back to the HHT form, and the lagged term at the half increment −(α/2)(r₀ + r₋₁).
    const double alpha = newmark_->alpha;
    const double r =
        std::abs(full[eq] * (1.0 + alpha) + 0.5 * alpha * (state_.r_n[eq] - r_before_[eq]));
    if (out.equation < 0 || r > out.value) {
      out.value = r;
      out.equation = eq;
    }
  }
  return out;
}

void ConnectorSystem::begin_stabilization(const StaticStabilization* settings, double period) {
  if (std::string line = stabilization_.begin_step(settings, period); !line.empty()) {
    events_.push_back(std::move(line));
  }
}

void ConnectorSystem::commit() {
  if (energy_) {
    const ModelEnergies before = energy_->energies();
    energy_->add_increment(state_.x - state_.x_n, energy_forces());
    energy_->set_kinetic(plan_.dynamic ? kinetic(state_.v, state_.rotation) : 0.0);
    const ModelEnergies& after = energy_->energies();
    const double element_work = (after.internal + after.frictional + after.viscous) -
                                (before.internal + before.frictional + before.viscous);
    stabilization_.converged(state_.x - state_.x_n, context_.dt, element_work, after, events_,
                             warnings_);
  }
  state_.commit();
  keep_converged_components();
  if (!newmark_) return;
  // The converged I − P of this increment is the next increment's HHT α term.
  r_before_ = state_.r_n;
  state_.r_n = hht_residual(static_residual(), false);
}

Eigen::VectorXd ConnectorSystem::hht_residual(Eigen::VectorXd r, bool start) const {
  // The multipliers' rows are constraints, not forces: no α term (analysis_state.hpp).
  for (Eigen::Index eq = 0; eq < r.size(); ++eq) {
    if (plan_.dofs.node_of(static_cast<int>(eq)) < 0) r[eq] = 0.0;
  }
  if (plan_.dependents.empty()) return r;
  // HHT α on the DOFs' own rows, as with the constraint's reaction as a multiplier (the index-3
  // form of Negrut, Rampalli, Ottarsson and Sajdak 2007, second order in Δt): the force at a
  // dependent DOF, the reaction included, is R = −M a at the start and R₁ = (α R₀ − M a₁)/(1 + α)
  // after an increment (its row of M a + (1 + α) R₁ − α R₀ = 0); the independent rows keep the
  // condensed residual less TᵀR (docs/dynamics.md "Inertia on constrained nodes").
  Eigen::VectorXd inertia;
  if (start) {
    inertia.setZero(r.size());
    dependent_inertia_forces(constrained_inertia_, plan_.dependents, state_.a_n, inertia);
  }
  const double alpha = newmark_ ? newmark_->alpha : 0.0;
  for (const DependentDof& d : plan_.dependents.dofs) {
    const double held =
        start ? -inertia[d.equation]
              : (alpha * state_.r_n[d.equation] - inertia_force_[d.equation]) / (1.0 + alpha);
    r[d.equation] = held;
    const std::span<const double> gradient = motion_.gradient(d);
    for (std::uint32_t e = 0; e < d.resolved_count; ++e) {
      r[plan_.dependents.resolved_equation[d.first_resolved + e]] -= gradient[e] * held;
    }
  }
  return r;
}

Eigen::VectorXd ConnectorSystem::static_residual() const {
  const auto n = state_.r_n.size();
  Eigen::VectorXd r = internal_.head(n) - conditions_.external().head(n);
  if (constraint_load_.size() > 0) r -= constraint_load_.head(n);
  return r;
}

DependentMotion ConnectorSystem::dependent_motion() const {
  DependentMotion motion(plan_.dependents, plan_.dofs);
  if (!plan_.dependents.empty()) {
    motion.update_gradients(state_.x, state_.rotation, context_.nlgeom);
  }
  return motion;
}

double ConnectorSystem::dependent_inertia(int eq) const {
  if (!newmark_ || inertia_force_.size() == 0) return 0.0;
  return inertia_force_[eq] / (1.0 + newmark_->alpha);
}

void ConnectorSystem::use_storage(bool symmetric) { pattern_ = &build_storage(symmetric); }

const AssemblyPattern& ConnectorSystem::storage() const {
  if (!pattern_) pattern_ = &build_storage(true);
  return *pattern_;
}

const AssemblyPattern& ConnectorSystem::build_storage(bool symmetric) const {
  std::unique_ptr<AssemblyPattern>& p = symmetric ? symmetric_pattern_ : full_pattern_;
  if (!p) {
    // Under assembly by rows, this rank's part (docs/parallel.md).
    std::optional<RowAssemblyShare> share;
    if (by_rows_) {
      share = RowAssemblyShare{owned_connectors_, owned_springs_, communicator_->rank(),
                               communicator_->size()};
    }
    p = std::make_unique<AssemblyPattern>(
        build_assembly_pattern(plan_, symmetric, share ? &*share : nullptr));
  }
  return *p;
}

ConnectorSystem::Snapshot ConnectorSystem::snapshot() const {
  return {state_,           conditions_,      internal_,          predictor_,
          predicting_,      springs_,         multiplier_active_, element_forces_,
          inertia_entries_, constraint_load_, dependent_failure_};
}

void ConnectorSystem::restore(const Snapshot& snapshot) {
  state_ = snapshot.state;
  conditions_ = snapshot.conditions;
  internal_ = snapshot.internal;
  predictor_ = snapshot.predictor;
  predicting_ = snapshot.predicting;
  springs_ = snapshot.springs;
  multiplier_active_ = snapshot.multiplier_active;
  element_forces_ = snapshot.element_forces;
  inertia_entries_ = snapshot.inertia_entries;
  constraint_load_ = snapshot.constraint_load;
  dependent_failure_ = snapshot.dependent_failure;
}

void ConnectorSystem::set_nlgeom(bool nlgeom) {
  if (nlgeom && !context_.nlgeom) {
    // Small rotations become finite ones (NLGEOM stays on once set, keywords.md §13).
    state_.rotation.assign(plan_.dofs.nodes(), Matrix3::Identity());
    for (std::size_t node = 0; node < plan_.dofs.nodes(); ++node) {
      if (!(plan_.dofs.active(static_cast<std::int32_t>(node)) & kRotationDofs)) continue;
      Vector3 theta = Vector3::Zero();
      for (int k = 0; k < 3; ++k) {
        const int eq = plan_.dofs.equation(static_cast<std::int32_t>(node), 4 + k);
        if (eq >= 0) theta[k] = state_.x[eq];
      }
      state_.rotation[node] = rotation_exp(theta);
    }
    state_.rotation_n = state_.rotation;
  }
  context_.nlgeom = nlgeom;
  update_dependents();
  state_.rotation_n = state_.rotation;
}

void ConnectorSystem::update_dependents() {
  if (plan_.dependents.empty()) return;
  dependent_failure_.clear();
  motion_.update_values(state_.x, state_.rotation, context_.nlgeom, &dependent_failure_);
}

void ConnectorSystem::start_increment(double extrapolate_scale) {
  if (extrapolate_scale != 0) {
    // Prescribed DOFs too, so that the extrapolated state is consistent; what is left of their
    // increment (none under a steady ramp) the first correction takes.
    for (int eq = 0; eq < plan_.dofs.equations(); ++eq) {
      if (plan_.dofs.node_of(eq) < 0 || is_finite_rotation(eq)) continue;  // not a multiplier
      const double before = state_.x[eq];
      state_.x[eq] += extrapolate_scale * state_.dx_n[eq];
      if (conditions_.is_prescribed(eq)) snap_to_target(eq, before);
    }
  }
  // Prescribed values stay where they are: the first correction moves them to their targets,
  // with the free DOFs following on the tangent at the start of the increment (docs/decisions.md
  // "Prescribed increments"). Finite rotations are the exception: they jump to their targets.
  snap_prescribed_rotations();
  update_dependents();
  update_prescribed_predictor();
}

bool ConnectorSystem::is_finite_rotation(int equation) const {
  return context_.nlgeom && plan_.dofs.field(equation) == EquationField::Rotation;
}

void ConnectorSystem::snap_to_target(int equation, double before) {
  // u + (target − u) may miss the target by an ulp: a move that was the whole remaining
  // increment lands on it exactly (a partial step, s < 1 of a line search, stays well outside).
  const double target = conditions_.target(equation);
  const double scale = std::max(std::abs(target), std::abs(before));
  if (std::abs(state_.x[equation] - target) <= 1e-12 * scale) state_.x[equation] = target;
}

void ConnectorSystem::update_prescribed_predictor() {
  predicting_ = false;
  for (int eq : conditions_.prescribed()) {
    predicting_ = predicting_ || state_.x[eq] != conditions_.target(eq);
  }
  // Under vectors by rows a rank holds the prescribed DOFs of its own rows and ghosts only.
  if (halo_) predicting_ = communicator_->first(predicting_) < communicator_->size();
}

void ConnectorSystem::snap_prescribed_rotations() {
  if (!context_.nlgeom) return;
  for (int eq : conditions_.prescribed()) {
    if (is_finite_rotation(eq)) state_.x[eq] = conditions_.target(eq);
  }
  apply_prescribed_rotations();
}

void ConnectorSystem::apply_prescribed_rotations() {
  if (!context_.nlgeom) return;
  // keywords.md §9: under NLGEOM the prescribed values are components of the total rotation
  // vector φ, R = exp(φ̂). A node with some components prescribed and others free keeps its free
  // components of φ (the reaction then acts on spins; documented in docs/decisions.md).
  for (int eq : conditions_.prescribed()) {
    if (plan_.dofs.field(eq) != EquationField::Rotation) continue;
    const std::int32_t node = plan_.dofs.node_of(eq);
    Vector3 phi;
    for (int k = 0; k < 3; ++k) {
      const int e = plan_.dofs.equation(node, 4 + k);
      phi[k] = e >= 0 ? state_.x[e] : 0.0;
    }
    state_.rotation[static_cast<std::size_t>(node)] = rotation_exp(phi);
  }
}

EvalStatus ConnectorSystem::evaluate(Eigen::VectorXd& residual, SparseMatrix* tangent) {
  storage();
  internal_.setZero();
  element_forces_ = {};
  inertia_entries_ = {};
  if (predicting_) predictor_.setZero();
  if (tangent) std::fill(tangent->values.begin(), tangent->values.end(), 0.0);
  // Each rank sets the flags of its own connectors' multipliers (exchange() merges them).
  if (communicator_) std::fill(multiplier_active_.begin(), multiplier_active_.end(), 0);
  state_.request = {};
  context_.dynamic = newmark_.has_value();
  context_.dv_du = newmark_ ? newmark_->dv_du : 0.0;
  if (newmark_) {
    if (!rates_frozen_) {
      newmark_->update_rates(state_);
      update_finite_rotary_rates(plan_.inertia, newmark_->dt, state_);
    }
    inertia_force_.setZero();
  }
  const bool want_tangent = tangent != nullptr;
  LocalSystem& local = *local_;
  // The first failure ends this process's share of the elements; a distributed run still
  // exchanges it, so that every rank fails the evaluation with it (a rank that holds no part of a
  // failed map included).
  EvalStatus failed;
  if (!dependent_failure_.empty()) {
    failed = {false, dependent_failure_};
  } else if (!plan_.dependents.empty()) {
    motion_.update_gradients(state_.x, state_.rotation, context_.nlgeom);
  }
  for (std::size_t c = owned_connectors_.begin; failed.ok && c < owned_connectors_.end; ++c) {
    failed = elements_.evaluate(c, context_, state_, want_tangent, local);
    if (!failed.ok) break;
    if (!connector_finite(c, local)) {
      failed = {false, fmt::format("connector element {}: a force or output is not finite",
                                   elements_.label(c))};
      break;
    }
    const ConnectorRecord& r = plan_.connectors[c];
    for (int j = 0; j < r.multiplier_count; ++j) {
      multiplier_active_[static_cast<std::size_t>(
          r.local.equation[static_cast<std::size_t>(r.column_count + j)])] =
          local.active[static_cast<std::size_t>(j)];
    }
    scatter_element(r.local, r.expansion, pattern_->connector_at(c), local, !r.laws.symmetric,
                    tangent);
    add_force_entries(r.local, r.column_count, local);
    add_component_forces(state_.results[c]);
  }
  for (std::size_t s = owned_springs_.begin; failed.ok && s < owned_springs_.end; ++s) {
    const SpringRecord& spring = plan_.spring(s);
    SpringResult& result = springs_[s - plan_.first_spring];
    evaluate_spring(plan_, spring,
                    {state_.x, state_.x_n, context_.dt, context_.nlgeom,
                     newmark_ ? &state_.v : nullptr, newmark_ ? newmark_->dv_du : 0.0},
                    want_tangent, local, result);
    if (zero_unless_non_finite(local.r.head(spring.local.count)) + result.force * 0.0 +
            result.delta * 0.0 !=
        0.0) {
      const Element& e = model_.elements[static_cast<std::size_t>(spring.element)];
      failed = {false, fmt::format("spring element {}: a force or output is not finite",
                                   qualified_label(model_, e.instance, e.label))};
      break;
    }
    // A dashpot's dynamic tangent is unsymmetric under NLGEOM (spring_element.cpp).
    scatter_element(spring.local, spring.expansion, pattern_->spring_at(s), local, spring.dashpot,
                    tangent);
    add_force_entries(spring.local, spring.local.count, local);
  }
  if (communicator_) exchange(tangent, failed);
  if (!failed.ok) return failed;
  // Over every equation; Newton sees the solved ones (dependent_dofs.hpp).
  const DependentDofs& dependents = plan_.dependents;
  Eigen::VectorXd& full = dependents.empty() ? residual : full_residual_;
  full = internal_ - conditions_.external();
  if (newmark_) {
    const InertiaTarget target{full,
                               tangent,
                               pattern_->diagonal,
                               pattern_->symmetric,
                               predicting_ ? &predictor_ : nullptr,
                               dependents};
    add_inertia(plan_.own_inertia(), *newmark_, state_, conditions_, target, inertia_force_,
                inertia_entries_);
    if (!dependents.empty()) {
      constrained_inertia_ = mapped_inertia_blocks(plan_.own_inertia(), dependents, motion_);
      add_constrained_inertia(constrained_inertia_, *newmark_, state_, conditions_, target,
                              inertia_force_, inertia_entries_);
    }
  }
  if (stabilization_.active()) {
    stabilization_force_.setZero();
    stabilization_.add(state_.x, state_.x_n, context_.dt, conditions_,
                       {full, tangent, pattern_->diagonal, stabilization_force_});
  }
  if (predicting_ && tangent) full += predictor_;
  if (!dependents.empty()) finish_dependent_rows(full, tangent);
  for (int eq : conditions_.prescribed()) {
    // Newton's row of a prescribed DOF is Δu = target − u. A reaction that overflows takes the
    // row's place, so that Newton stops on it rather than report it (principle 8).
    full[eq] = std::isfinite(internal_[eq]) ? state_.x[eq] - conditions_.target(eq) : internal_[eq];
    // Under assembly by rows the rank that owns the row holds its diagonal.
    if (tangent && tangent->owns_row(dependents.solved(eq))) {
      tangent->values[static_cast<std::size_t>(
          pattern_->diagonal[static_cast<std::size_t>(dependents.solved(eq))])] = 1.0;
    }
  }
  if (!dependents.empty()) {
    residual.resize(size());
    for (int i = 0; i < size(); ++i) residual[i] = full[dependents.equation(i)];
  }
  return {};
}

// An overflow in a law or in the kinematics fails the evaluation, which the step driver treats as
// a failed attempt; the element's forces, outputs and trial history are checked, so that none of
// them reaches a converged row (ARCHITECTURE.md principle 8). The stiffness is left to Newton: a
// non-finite one makes the correction non-finite, which Newton reports at its DOF.
bool ConnectorSystem::connector_finite(std::size_t c, const LocalSystem& local) const {
  const ConnectorRecord& r = plan_.connectors[c];
  const ConnectorResult& out = state_.results[c];
  double sum = zero_unless_non_finite(local.r.head(r.local.count));
  for (const Vector6* v : {&out.position, &out.change, &out.constitutive, &out.elastic,
                           &out.multiplier, &out.applied, &out.total}) {
    sum += zero_unless_non_finite(*v);
  }
  for (const LawSlot& slot : r.laws) {
    const auto first = state_.history.begin() + static_cast<std::ptrdiff_t>(slot.history);
    sum = std::accumulate(first, first + static_cast<std::ptrdiff_t>(slot.law->history_size()), sum,
                          [](double s, double v) { return s + v * 0.0; });
  }
  return sum == 0.0;
}

int ConnectorSystem::force_field(int equation) const {
  return plan_.dofs.field(equation) == EquationField::Translation ? 0 : 1;
}

void ConnectorSystem::add_force_entries(const LocalEquations& l, int nodal_count,
                                        const LocalSystem& local) {
  // The nodal rows only: the multiplier rows hold constraint violations, not forces.
  for (int a = 0; a < nodal_count; ++a) {
    element_forces_.add(force_field(l.equation[static_cast<std::size_t>(a)]), std::abs(local.r[a]));
  }
}

void ConnectorSystem::add_component_forces(const ConnectorResult& result) {
  // Components 1–3 are forces, 4–6 moments (connection-types.md §1.4). CEF holds the RIGID
  // multipliers, CRF those of the constrained components, stops, locks and connector motions.
  for (const Vector6* forces :
       {&result.elastic, &result.viscous, &result.friction, &result.multiplier, &result.applied}) {
    for (int i = 0; i < 6; ++i) element_forces_.add(i < 3 ? 0 : 1, std::abs((*forces)[i]));
  }
}

void ConnectorSystem::scatter_element(const LocalEquations& l, std::int32_t expansion,
                                      std::size_t offset, const LocalSystem& local, bool symmetrize,
                                      SparseMatrix* tangent) {
  if (expansion < 0) {
    scatter({l.equation.data(), static_cast<std::size_t>(l.count)}, offset, local.r, local.k,
            symmetrize, tangent);
    return;
  }
  const ElementExpansion& e = plan_.expansions[static_cast<std::size_t>(expansion)];
  condense(e, l, plan_.dependents, motion_, local, tangent != nullptr, condensed_, internal_);
  // TᵀKT is as symmetric as K (up to round-off).
  scatter(e.equations, offset, condensed_.r, condensed_.k, symmetrize, tangent);
}

template <typename Residual, typename Tangent>
void ConnectorSystem::scatter(std::span<const int> l, std::size_t offset, const Residual& r,
                              const Tangent& local_k, bool symmetrize, SparseMatrix* tangent) {
  const auto count = static_cast<int>(l.size());
  for (int a = 0; a < count; ++a) internal_[l[static_cast<std::size_t>(a)]] += r[a];
  if (!tangent) return;
  const int* position = pattern_->positions.data() + offset;
  double* values = tangent->values.data();
  const bool symmetric = pattern_->symmetric;
  for (int b = 0; b < count; ++b) {
    const int eb = l[static_cast<std::size_t>(b)];
    const bool fixed_b = conditions_.is_prescribed(eb);
    const int last = symmetric ? b : count - 1;
    for (int a = 0; a <= last; ++a, ++position) {
      const int ea = l[static_cast<std::size_t>(a)];
      const bool fixed_a = conditions_.is_prescribed(ea);
      // Upper storage holds K(a, b) for both triangles; an unsymmetric element gives its
      // symmetric part there (keywords.md §14, UNSYMM=NO).
      const double k =
          symmetric && symmetrize ? 0.5 * (local_k(a, b) + local_k(b, a)) : local_k(a, b);
      if (!fixed_a && !fixed_b) {
        values[*position] += k;
      } else if (predicting_ && fixed_a != fixed_b) {
        // The prescribed column leaves the matrix for the right-hand side: K_fp·Δu_p. In full
        // storage only the entry in a free row does; in upper storage (a, b) stands for both.
        if (!symmetric && fixed_a) continue;
        const int free = fixed_a ? eb : ea, fixed = fixed_a ? ea : eb;
        predictor_[free] += k * (conditions_.target(fixed) - state_.x[fixed]);
      }
    }
  }
}

void ConnectorSystem::path_weights(Eigen::VectorXd& weights) const {
  weights.resize(size());
  for (int i = 0; i < size(); ++i) {
    switch (plan_.dofs.field(plan_.dependents.equation(i))) {
      case EquationField::Translation:
        weights[i] = 1.0;
        break;
      case EquationField::Rotation:
        weights[i] = plan_.length_scale * plan_.length_scale;
        break;
      default:
        weights[i] = 0.0;  // a multiplier is a force, not a motion
    }
  }
}

void ConnectorSystem::finish_dependent_rows(Eigen::VectorXd& residual, SparseMatrix* tangent) {
  const DependentDofs& dependents = plan_.dependents;
  const Eigen::VectorXd& external = conditions_.external();
  constraint_load_.setZero();
  curvature_.clear();
  for (const DependentDof& d : dependents.dofs) {
    const double load = external[d.equation];
    // HHT α: the converged force on the DOF, pulled back with the current gradients.
    const double held =
        newmark_ ? -newmark_->alpha / (1.0 + newmark_->alpha) * state_.r_n[d.equation] : 0.0;
    if (load != 0.0 || held != 0.0) {
      const std::span<const double> gradient = motion_.gradient(d);
      for (std::uint32_t e = 0; e < d.resolved_count; ++e) {
        const int eq = dependents.resolved_equation[d.first_resolved + e];
        residual[eq] += gradient[e] * (held - load);
        constraint_load_[eq] += gradient[e] * load;
      }
    }
    if (tangent && context_.nlgeom) {
      motion_.add_curvature(d, internal_[d.equation] + dependent_inertia(d.equation) + held - load,
                            state_.x, state_.rotation, curvature_);
    }
    residual[d.equation] = 0.0;
  }
  if (!tangent) return;
  for (const CurvatureEntry& entry : curvature_) add_curvature(entry, *tangent);
}

void ConnectorSystem::add_curvature(const CurvatureEntry& entry, SparseMatrix& tangent) {
  const DependentDofs& dependents = plan_.dependents;
  if (conditions_.is_prescribed(entry.row) || conditions_.is_prescribed(entry.column) ||
      dependents.is_dependent(entry.row) || dependents.is_dependent(entry.column)) {
    return;
  }
  // Upper storage: the slot of (i, j) stands for both triangles and takes the symmetric part,
  // half of each (entry_position finds the slot of either).
  const int row = dependents.solved(entry.row), column = dependents.solved(entry.column);
  // Under assembly by rows the rank that owns the row of the entry's slot adds it.
  if (!tangent.owns_row(pattern_->symmetric ? std::min(row, column) : row)) return;
  const int position = entry_position(tangent, row, column);
  const double share = pattern_->symmetric && entry.row != entry.column ? 0.5 : 1.0;
  if (position >= 0) tangent.values[static_cast<std::size_t>(position)] += share * entry.value;
}

void ConnectorSystem::apply_correction(const Eigen::VectorXd& solved_dx) {
  // A correction of the solved equations; the dependent ones follow in update_dependents.
  const DependentDofs& dependents = plan_.dependents;
  if (!dependents.empty()) {
    full_correction_.setZero(plan_.dofs.equations());
    for (int i = 0; i < size(); ++i) full_correction_[dependents.equation(i)] = solved_dx[i];
  }
  const Eigen::VectorXd& dx = dependents.empty() ? solved_dx : full_correction_;
  if (!context_.nlgeom) {
    state_.x += dx;
    update_dependents();
    finish_prescribed_correction(dx);
    return;
  }
  for (int eq = 0; eq < plan_.dofs.equations(); ++eq) {
    if (plan_.dofs.field(eq) != EquationField::Rotation) state_.x[eq] += dx[eq];
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
        previous[k] = state_.x[eqs[static_cast<std::size_t>(k)]];
      }
    }
    state_.rotation[node] = rotation_exp(spin) * state_.rotation[node];
    Vector3 phi = rotation_log(state_.rotation[node]);
    if (const int turns = rotation_vector_turns(phi, previous); turns != 0) {
      phi *= 1.0 + 2.0 * std::numbers::pi * turns / phi.norm();
    }
    for (int k = 0; k < 3; ++k) {
      if (eqs[static_cast<std::size_t>(k)] >= 0)
        state_.x[eqs[static_cast<std::size_t>(k)]] = phi[k];
    }
  }
  snap_prescribed_rotations();
  update_dependents();
  finish_prescribed_correction(dx);
}

void ConnectorSystem::finish_prescribed_correction(const Eigen::VectorXd& dx) {
  for (int eq : conditions_.prescribed()) snap_to_target(eq, state_.x[eq] - dx[eq]);
  update_prescribed_predictor();
}

void ConnectorSystem::measure(const Eigen::VectorXd& residual, const Eigen::VectorXd* correction,
                              IterationNorms& norms) const {
  // q̃ (keywords.md §16 field 1): the entries of the elements, then the applied loads.
  // Under vectors by rows each rank measures its own rows, the loads on them among the entries,
  // and join_norms joins the ranks' measures.
  ForceEntries entries = element_forces_, own_loads;
  ForceEntries& loads = halo_ ? own_loads : entries;
  ScaledNorm residual_norm, correction_norm;
  const DependentDofs& dependents = plan_.dependents;
  // The inertia forces of the rank's own nodes (under vectors by rows, joined with its loads).
  for (int f = 0; f < 2; ++f) {
    loads.sum[f] += inertia_entries_.sum[f];
    loads.count[f] += inertia_entries_.count[f];
  }
  for (const DependentDof& d : dependents.dofs) {  // loads on dependent DOFs, which have no row
    if (reports(d.equation)) {
      loads.add(force_field(d.equation), std::abs(conditions_.external()[d.equation]));
    }
  }
  const int rows = owned_size();
  for (int i = 0; i < rows; ++i) {
    const int eq = dependents.equation(i);
    const EquationField field = plan_.dofs.field(eq);
    if (field == EquationField::TranslationalMultiplier ||
        field == EquationField::RotationalMultiplier) {
      if (!multiplier_active_[static_cast<std::size_t>(eq)]) continue;
      // keywords.md §16: |g| ≤ 1e-8·L̄ (translations) or 1e-8 rad (rotations).
      const double tolerance =
          1e-8 * (field == EquationField::TranslationalMultiplier ? plan_.length_scale : 1.0);
      norms.constraint_violation =
          std::max(norms.constraint_violation, std::abs(residual[i]) / tolerance);
      continue;
    }
    const int f = field == EquationField::Translation ? 0 : 1;
    loads.add(f, std::abs(conditions_.external()[eq]));
    if (conditions_.is_prescribed(eq)) continue;
    norms.largest_residual[f] = max_keeping_nan(norms.largest_residual[f], std::abs(residual[i]));
    residual_norm.add(residual[i]);
    norms.largest_increment[f] =
        max_keeping_nan(norms.largest_increment[f], std::abs(state_.x[eq] - state_.x_n[eq]));
    if (correction) {
      const double dx = (*correction)[i];
      norms.largest_correction[f] = max_keeping_nan(norms.largest_correction[f], std::abs(dx));
      correction_norm.add(dx);
    }
  }
  if (halo_) {
    join_norms(norms, own_loads, residual_norm, correction_norm);
    for (int f = 0; f < 2; ++f) {
      entries.sum[f] += own_loads.sum[f];
      entries.count[f] += own_loads.count[f];
    }
  }
  for (int f = 0; f < 2; ++f) norms.flux[f] = entries.mean(f);
  norms.resolution[0] = 1e-12 * plan_.length_scale;
  norms.resolution[1] = 1e-12;
  const double force_scale = std::max(norms.flux[0], norms.flux[1] / plan_.length_scale);
  norms.force_resolution[0] = 1e-12 * force_scale;
  norms.force_resolution[1] = 1e-12 * force_scale * plan_.length_scale;
  norms.residual_norm = residual_norm.value();
  norms.correction_norm = correction_norm.value();
}

// Each rank of a distributed model updates the stops of its own connectors; all solve again if
// any changed.
bool ConnectorSystem::update_active_set() {
  return any_rank(update_stops(plan_, conditions_, state_));
}

void ConnectorSystem::end_increment() {
  engage_locks(plan_, state_);
  // §7.4: an element whose affected components all reached d = 1 leaves the assembly now. A
  // damage law keeps the whole plan on every rank (whole_tangent_need.cpp), so every rank sees
  // every deletion.
  for (std::size_t c = 0; c < plan_.connectors.size(); ++c) {
    const ConnectorRecord& r = plan_.connectors[c];
    if (deleted_[c] || r.laws.empty() || !is_deleted(r, state_)) continue;
    deleted_[c] = 1;
    events_.push_back(
        fmt::format("connector element {} deleted: every component its damage "
                    "affects is fully damaged (d = 1)",
                    elements_.label(c)));
  }
}

// behaviors.md §5.3: a failure criterion met on the converged state releases its components for
// good; each rule fires once.
std::vector<std::string> ConnectorSystem::release_failed_components() {
  std::vector<std::string> events;
  for (std::size_t c = 0; c < plan_.connectors.size(); ++c) {
    const ConnectorRecord& r = plan_.connectors[c];
    ConnectorActiveSet& set = state_.active_sets[c];
    for (std::size_t k = 0; k < r.failures.size(); ++k) {
      if (set.fired & (1u << k)) continue;
      const ConnectorReleaseRule& rule = r.failures[k];
      const ConnectorResult& out = state_.results[c];
      const double p = out.position[rule.component - 1];
      const double f = out.total[rule.component - 1];
      const ConnectorCriterionBounds& b = rule.bounds;
      std::string why;
      if (b.force_upper && f >= *b.force_upper) {
        why = fmt::format("component {} force {:.6g} ≥ F_U = {:.6g}", rule.component, f,
                          *b.force_upper);
      } else if (b.force_lower && f <= *b.force_lower) {
        why = fmt::format("component {} force {:.6g} ≤ F_L = {:.6g}", rule.component, f,
                          *b.force_lower);
      } else if (b.position_upper && p >= *b.position_upper) {
        why = fmt::format("component {} position {:.6g} ≥ p_U = {:.6g}", rule.component, p,
                          *b.position_upper);
      } else if (b.position_lower && p <= *b.position_lower) {
        why = fmt::format("component {} position {:.6g} ≤ p_L = {:.6g}", rule.component, p,
                          *b.position_lower);
      } else {
        continue;
      }
      set.fired |= 1u << k;
      for (int i = 0; i < 6; ++i) {
        if (has_component(rule.releases, i + 1) && !has_component(set.released, i + 1)) {
          set.release_motion[i] = out.constitutive[i];
        }
      }
      set.released |= rule.releases;
      events.push_back(fmt::format("connector element {} failed ({})", elements_.label(c), why));
    }
  }
  return lines_of_every_rank(std::move(events));
}

// What the laws' converged history adds up to over the connectors (Behavior::step_total), one
// line per quantity in the order the laws first report it. Only damage laws report totals, and
// they keep the whole plan on every rank (whole_tangent_need.cpp).
std::vector<std::string> ConnectorSystem::step_summary() const {
  struct Sum {
    StepTotal total;
    std::size_t count = 0;
  };
  std::vector<Sum> sums;
  for (const ConnectorRecord& r : plan_.connectors) {
    for (const LawSlot& slot : r.laws) {
      const std::optional<StepTotal> total =
          slot.law->step_total(slot.history_in(state_.history_n));
      if (!total) continue;
      auto sum = std::find_if(sums.begin(), sums.end(),
                              [&](const Sum& s) { return s.total.what == total->what; });
      if (sum == sums.end()) {
        sums.push_back({*total, 1});
      } else {
        sum->total.value += total->value;
        ++sum->count;
      }
    }
  }
  std::vector<std::string> lines;
  for (const Sum& sum : sums) {
    lines.push_back(fmt::format("{}: {:.6g} ({} {})", sum.total.what, sum.total.value, sum.count,
                                sum.total.holders));
  }
  if (energy_) {
    // The balance (docs/dynamics.md "Energies"): the change of ETOTAL against the largest energy
    // of the run shows how much the integration created or lost.
    const ModelEnergies e = energies();
    const double scale = std::max(energy_->largest(), initial_kinetic_);
    const std::string stabilization =
        plan_.stabilized ? fmt::format(", ALLSD {:.6g}", e.stabilization) : std::string();
    lines.push_back(fmt::format(
        "energies: ALLKE {:.6g}, ALLIE {:.6g}, ALLFD {:.6g}, ALLVD {:.6g}{}, ALLWK {:.6g}; "
        "ETOTAL {:.6g}, changed by {:.3g} of the largest energy since the start",
        e.kinetic, e.internal, e.frictional, e.viscous, stabilization, e.work, e.total(),
        scale > 0 ? std::abs(e.total() - initial_kinetic_) / scale : 0.0));
  }
  return lines;
}

// behaviors.md §7.4: a node that a deleted connector leaves without stiffness makes the system
// singular there; under load control no equilibrium exists past a softening peak, and Newton
// fails: the element whose damage grows most in the failed trial state is named.
std::string ConnectorSystem::failure_note(int failed_equation, bool riks) const {
  const std::int32_t node = failed_equation >= 0 && failed_equation < plan_.dofs.equations()
                                ? plan_.dofs.node_of(failed_equation)
                                : -1;
  const auto fully_damaged = [&](std::size_t c) {
    const LawStack& laws = plan_.connectors[c].laws;
    return std::any_of(laws.begin(), laws.end(), [&](const LawSlot& slot) {
      return slot.law->damage(slot.history_in(state_.history)) >= 1.0;
    });
  };
  const auto next_to_node = [&]() -> std::string {
    for (std::size_t c = 0; node >= 0 && c < plan_.connectors.size(); ++c) {
      const ConnectorRecord& r = plan_.connectors[c];
      if (r.nodes[0] != node && r.nodes[1] != node) continue;
      if (deleted_[c]) {
        return fmt::format("after connector element {} was deleted (damage)", elements_.label(c));
      }
      if (state_.active_sets[c].released != 0) {
        return fmt::format("after connector element {} failed (*CONNECTOR FAILURE)",
                           elements_.label(c));
      }
      if (fully_damaged(c)) {
        return fmt::format("connector element {} fully damaged (d=1)", elements_.label(c));
      }
    }
    return {};
  };
  // The first connector in element order: that of the lowest rank that has one.
  const std::vector<std::string> notes = lines_of_every_rank({next_to_node()});
  const auto first = std::find_if(notes.begin(), notes.end(),
                                  [](const std::string& note) { return !note.empty(); });
  if (first != notes.end()) return *first;
  // Softening needs a damage law, which keeps the whole plan on every rank
  // (whole_tangent_need.cpp).
  double largest = 0, growth = 0;
  std::size_t softening = plan_.connectors.size();
  for (std::size_t c = 0; c < plan_.connectors.size(); ++c) {
    for (const LawSlot& slot : plan_.connectors[c].laws) {
      const double trial = slot.law->damage(slot.history_in(state_.history));
      const double grew = trial - slot.law->damage(slot.history_in(state_.history_n));
      if (grew > growth) {
        growth = grew;
        largest = trial;
        softening = c;
      }
    }
  }
  if (softening == plan_.connectors.size()) return {};
  const bool loaded =
      (conditions_.external().size() > 0 && conditions_.external().cwiseAbs().maxCoeff() > 0) ||
      conditions_.has_connector_loads();
  if (!loaded) {
    return fmt::format("connector element {} softening (d={:.3g})", elements_.label(softening),
                       largest);
  }
  // docs/riks.md "Limits": a Riks path stalls where it turns too sharply to follow, at a limit
  // point on a kink of a softening law.
  if (riks) {
    return fmt::format(
        "connector element {} softening (d={:.3g}) at LPF {:.4g}: the path turns too sharply "
        "there to follow (a limit point on a kink of the law, docs/riks.md \"Limits\"); sample "
        "its table more finely, regularise the damage (*SECTION CONTROLS, VISCOSITY), or "
        "drive the softening connector's own motion (*BOUNDARY, *CONNECTOR MOTION) instead of "
        "the load",
        elements_.label(softening), largest, load_factor_);
  }
  // docs/riks.md: past a softening peak no larger load has an equilibrium; say where and what
  // the deck can do about it.
  return fmt::format(
      "connector element {} softening (d={:.3g}) under load control: a limit point, past "
      "which no larger load has an equilibrium, at about {:.4g} of the step's loads; to go past "
      "it, use *STATIC, RIKS, prescribe a displacement (*BOUNDARY) instead of the load, "
      "regularise the damage (*SECTION CONTROLS, VISCOSITY), or damp the step (*STATIC, "
      "STABILIZE) where a stiffer path picks the load up again",
      elements_.label(softening), largest, load_factor_);
}

NonlinearProblem::DamageChange ConnectorSystem::damage_change() const {
  DamageChange change;
  for (std::size_t c = owned_connectors_.begin; c < owned_connectors_.end; ++c) {
    for (const LawSlot& slot : plan_.connectors[c].laws) {
      const double now = slot.law->damage(slot.history_in(state_.history));
      change.damaged = change.damaged || now > 0.0;
      change.growing = change.growing || now > slot.law->damage(slot.history_in(state_.history_n));
    }
  }
  // Each rank evaluates its own connectors; the decision is taken together.
  if (communicator_) {
    std::array<std::uint8_t, 2> flags{change.damaged, change.growing};
    communicator_->max(flags);
    change = {flags[0] != 0, flags[1] != 0};
  }
  return change;
}

double ConnectorSystem::nodal_value(std::int32_t node, int dof) const {
  const int eq = plan_.dofs.equation(node, dof);
  return reports(eq) ? state_.x[eq] : 0.0;
}

double ConnectorSystem::reaction(std::int32_t node, int dof) const {
  const int eq = plan_.dofs.equation(node, dof);
  if (!reports(eq) || !conditions_.is_prescribed(eq)) return 0.0;
  return holding_force(eq) - conditions_.external()[eq];
}

double ConnectorSystem::holding_force(int eq) const {
  const double moved = constraint_load_.size() > 0 ? constraint_load_[eq] : 0.0;
  const double inertia = inertia_force_.size() > 0 ? inertia_force_[eq] : 0.0;
  return internal_[eq] + inertia - moved;
}

double ConnectorSystem::nodal_rate(std::int32_t node, int dof, int order) const {
  const int eq = plan_.dofs.equation(node, dof);
  const Eigen::VectorXd& rate = order == 1 ? state_.v : state_.a;
  return reports(eq) && eq < rate.size() ? rate[eq] : 0.0;
}

double ConnectorSystem::converged_rate(int equation, int order) const {
  const Eigen::VectorXd& rate = order == 1 ? state_.v_n : state_.a_n;
  return equation < rate.size() ? rate[equation] : 0.0;
}

double ConnectorSystem::displacement_of_rate(int equation, int order, double rate) const {
  const double u0 = state_.x_n[equation];
  // Outside an increment of a dynamic step (its start state) the DOF stays where it is.
  if (!newmark_ || newmark_->dt <= 0.0 || equation >= state_.v_n.size()) return u0;
  return newmark_->value_of_rate(u0, state_.v_n[equation], state_.a_n[equation], order, rate);
}

double ConnectorSystem::converged_component(std::size_t connector, int component, int order) const {
  const int i = component - 1;
  const std::size_t c = connector - plan_.first_connector;
  if (converged_components_.empty()) {
    const ConnectorResult& r = state_.results[c];
    return order == 0 ? r.change[i] : order == 1 ? r.velocity[i] : r.acceleration[i];
  }
  const ComponentRates& r = converged_components_[c];
  return order == 0 ? r.value[i] : order == 1 ? r.velocity[i] : r.acceleration[i];
}

double ConnectorSystem::value_of_rate(double u0, double v0, double a0, int order,
                                      double rate) const {
  if (!newmark_ || newmark_->dt <= 0.0) return u0;
  return newmark_->value_of_rate(u0, v0, a0, order, rate);
}

ModelEnergies ConnectorSystem::energies() const {
  return energy_ ? energy_->energies() : ModelEnergies{};
}

// The forces of the last evaluation for the energy balance: the loads on free DOFs, and what
// holds a prescribed DOF there (the reaction and the load on it).
EnergyForces ConnectorSystem::energy_forces() {
  external_force_ = conditions_.external();
  for (int eq : conditions_.prescribed()) external_force_[eq] = holding_force(eq);
  return {internal_, external_force_, state_.results, springs_,
          plan_.stabilized ? &stabilization_force_ : nullptr};
}

int ConnectorSystem::owned_node_equations() const {
  if (!halo_) return plan_.dofs.node_equations();
  // A rank's local equations: its nodes', then its multipliers, then the ghosts.
  int n = 0;
  while (n < halo_->owned() && plan_.dofs.node_of(n) >= 0) ++n;
  return n;
}

double ConnectorSystem::kinetic(const Eigen::VectorXd& v,
                                const std::vector<Matrix3>& rotations) const {
  double energy = kinetic_energy(plan_.own_inertia(), v, rotations);
  if (halo_) communicator_->sum({&energy, 1});
  return energy;
}

double ConnectorSystem::applied_load(std::int32_t node, int dof) const {
  const int eq = plan_.dofs.equation(node, dof);
  return reports(eq) ? conditions_.external()[eq] : 0.0;
}

ConnectorOutput ConnectorSystem::connector_output(std::size_t global) const {
  const std::size_t connector = global - plan_.first_connector;
  ConnectorOutput out;
  static_cast<ConnectorResult&>(out) = state_.results[connector];
  const ConnectorRecord& r = plan_.connectors[connector];
  out.status = state_.active_sets[connector].status;
  // output-variables.md §2: CSLST 4 on every component of a deleted element and on the
  // components a *CONNECTOR FAILURE released.
  const ComponentMask four =
      deleted_[connector] ? r.available | r.constrained : state_.active_sets[connector].released;
  for (int i = 0; i < 6; ++i) {
    if (has_component(four, i + 1)) out.status[static_cast<std::size_t>(i)] = 4;
  }
  std::size_t l = 0;
  for (const LawSlot& slot : r.laws) {
    out.laws[l++] = {slot.law->history_layout(), slot.history_in(state_.history)};
  }
  return out;
}

}  // namespace clinch
