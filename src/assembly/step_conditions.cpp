#include "src/assembly/step_conditions.hpp"

#include <ranges>

namespace clinch {
namespace {

using Query = ConnectorSystem::ComponentQuery;

std::int64_t component_key(std::int32_t connector, int component) {
  return static_cast<std::int64_t>(connector) * 8 + component;
}

// The values of the keyed connector components on every rank (a distributed model holds each
// connector on one rank only: ConnectorSystem::component_values); `quantity(k)` says which value
// of the k-th key.
template <class Keys, class Quantity>
std::vector<double> component_values(const ConnectorSystem& system, const Keys& keys,
                                     const Quantity& quantity) {
  std::vector<ConnectorSystem::ComponentQuery> queries;
  for (const std::int64_t key : keys) {
    queries.push_back(
        {static_cast<std::size_t>(key / 8), static_cast<int>(key % 8), quantity(queries.size())});
  }
  return system.component_values(queries);
}

}  // namespace

StepConditions::StepConditions(const Model& model, const AnalysisPlan& plan)
    : model_(model), plan_(plan) {
  for (const Amplitude& a : model_.history.amplitudes) {
    if (a.valid)
      amplitudes_.emplace_back(AmplitudeFunction(a));
    else
      amplitudes_.emplace_back(std::nullopt);
  }
  const auto& steps = model_.history.steps;
  if (std::any_of(steps.begin(), steps.end(), [](const Step& s) { return !s.gravity.empty(); })) {
    point_masses_ = point_masses(model_);
    point_mass_of_element_.assign(model_.elements.size(), -1);
    for (std::size_t i = 0; i < point_masses_.size(); ++i) {
      point_mass_of_element_[static_cast<std::size_t>(point_masses_[i].element)] =
          static_cast<std::int32_t>(i);
    }
  }
}

double StepConditions::Condition::value(
    double tau, double step_time, double total_time,
    const std::vector<std::optional<AmplitudeFunction>>& amplitudes) const {
  switch (mode) {
    case Mode::Ramp:
      return start + (magnitude - start) * tau;
    case Mode::Jump:
      return magnitude;
    case Mode::Amplitude:
      return magnitude *
             amplitudes[static_cast<std::size_t>(amplitude)]->value(step_time, total_time);
    case Mode::AmplitudeAbsolute:
      return amplitudes[static_cast<std::size_t>(amplitude)]->value(step_time, total_time);
    case Mode::Fixed:
      return start;
    case Mode::Hold:
      return magnitude;
  }
  return magnitude;
}

// keywords.md §13, "within the step where a condition is defined".
StepConditions::Condition StepConditions::define(const ConditionBlock& block, const Step& step,
                                                 double magnitude, double start,
                                                 bool prescribed_kind) const {
  Condition c;
  c.start = start;
  c.magnitude = magnitude;
  c.rate_order = block.rate_order;
  // A Riks step scales its values by the load proportionality factor, P₀ + λ(P_ref − P₀), the
  // ramp at τ = λ; amplitudes are ignored (docs/riks.md).
  const bool riks = step.procedure && step.procedure->riks;
  if (block.fixed) {
    c.mode = Mode::Fixed;
  } else if (riks) {
    c.mode = Mode::Ramp;
  } else if (block.amplitude_index >= 0 &&
             amplitudes_[static_cast<std::size_t>(block.amplitude_index)]) {
    c.amplitude = block.amplitude_index;
    c.mode = model_.history.amplitudes[static_cast<std::size_t>(block.amplitude_index)].absolute
                 ? Mode::AmplitudeAbsolute
                 : Mode::Amplitude;
  } else if (step.amplitude == StepAmplitude::Step && !(prescribed_kind && block.explicit_type)) {
    c.mode = Mode::Jump;
  } else {
    c.mode = Mode::Ramp;
  }
  return c;
}

// v₀ of a load: its value at the end of the previous step, 0 when new (keywords.md §13).
double StepConditions::load_start(const Table& table, std::int64_t key) {
  const auto it = table.find(key);
  if (it == table.end()) return 0.0;
  return it->second.mode == Mode::Hold ? it->second.magnitude : it->second.start;
}

// keywords.md §13, "across steps": OP=NEW removes every earlier condition of the kind; a removed
// load ramps to zero (or drops at once under AMPLITUDE=STEP); a removed prescribed condition
// becomes the load `removed` that replaces its last reaction and decays the same way.
void StepConditions::carry_over(Table& table, bool replaced, bool load_kind, const Step& step,
                                Table& removed) {
  if (!replaced) return;
  if (load_kind) {
    for (auto& [key, c] : table) {
      c = Condition{Mode::Ramp, c.magnitude, 0.0, -1};
      if (step.amplitude == StepAmplitude::Step) c.start = 0.0;
    }
    return;
  }
  for (auto& [key, c] : removed) {
    if (step.amplitude == StepAmplitude::Step) c.start = 0.0;
  }
  table.clear();
}

void StepConditions::begin_step(std::size_t s, ConnectorSystem& system) {
  const Step& step = model_.history.steps[s];
  period_ = step.procedure ? step.procedure->period : 1.0;
  released_loads_.clear();
  released_connector_loads_.clear();
  base_.reset();

  if (s == 0) {
    // Model-data conditions hold zero from time 0 (keywords.md §9, §11).
    for (const BoundaryCondition& bc : model_.history.model_boundaries) {
      for (std::int32_t node : bc.resolved) {
        for (int dof = 1; dof <= 6; ++dof) {
          const int eq = (bc.dofs >> (dof - 1)) & 1u ? plan_.dofs.equation(node, dof) : -1;
          if (eq >= 0) boundaries_[eq] = Condition{Mode::Hold, 0.0, 0.0, -1};
        }
      }
    }
    for (const ConnectorCondition& m : model_.history.model_motions) {
      for (std::int32_t e : m.resolved) {
        const std::int32_t c = plan_.connector_of_element[static_cast<std::size_t>(e)];
        if (c >= 0) motions_[component_key(c, m.component)] = Condition{Mode::Hold, 0.0, 0.0, -1};
      }
    }
  }

  if (step.is_perturbation()) {
    begin_perturbation(step, system);
    return;
  }

  if (step.replaces(ConditionKind::Boundary)) {
    for (const auto& [eq, c] : boundaries_) {
      const std::int32_t node = plan_.dofs.node_of(static_cast<int>(eq));
      const double r = system.reaction(node, plan_.dofs.dof_of(static_cast<int>(eq)));
      // The support force the node felt becomes an applied load: F_ext + r keeps it in place.
      released_loads_[eq] = Condition{Mode::Ramp, r, 0.0, -1};
    }
  }
  if (step.replaces(ConditionKind::Motion)) {
    const std::vector<double> reactions = component_values(
        system, std::views::keys(motions_), [](std::size_t) { return Query::Reaction; });
    std::size_t k = 0;
    for (const auto& [key, c] : motions_) {
      // The constraint force λ enters CTF as +λ; a connector load enters as −CCF.
      released_connector_loads_[key] = Condition{Mode::Ramp, -reactions[k++], 0.0, -1};
    }
  }
  carry_over(boundaries_, step.replaces(ConditionKind::Boundary), false, step, released_loads_);
  carry_over(motions_, step.replaces(ConditionKind::Motion), false, step,
             released_connector_loads_);
  carry_over(loads_, step.replaces(ConditionKind::Load), true, step, released_loads_);
  carry_over(connector_loads_, step.replaces(ConditionKind::ConnectorLoad), true, step,
             released_connector_loads_);
  carry_over(gravity_, step.replaces(ConditionKind::Gravity), true, step, released_loads_);

  for (const BoundaryCondition& bc : step.boundaries) {
    const ConditionBlock& block = step.blocks[static_cast<std::size_t>(bc.block)];
    for (std::int32_t node : bc.resolved) {
      for (int dof = 1; dof <= 6; ++dof) {
        if (!((bc.dofs >> (dof - 1)) & 1u)) continue;
        const int eq = plan_.dofs.equation(node, dof);
        if (eq < 0) continue;  // inactive DOF: W0803 at check time
        // A prescribed rate starts from the rate the DOF has (docs/dynamics.md).
        const double start = block.rate_order > 0 ? system.converged_rate(eq, block.rate_order)
                                                  : system.converged_value(eq);
        boundaries_[eq] = define(block, step, bc.magnitude, start, true);
        released_loads_.erase(eq);
      }
    }
  }
  for (const ConcentratedLoad& load : step.loads) {
    const ConditionBlock& block = step.blocks[static_cast<std::size_t>(load.block)];
    for (std::int32_t node : load.resolved) {
      const int eq = plan_.dofs.equation(node, load.dof);
      if (eq < 0) continue;
      loads_[eq] = define(block, step, load.magnitude, load_start(loads_, eq), false);
    }
  }
  auto connector_conditions = [&](const std::vector<ConnectorCondition>& list, Table& table,
                                  bool motion) {
    // A motion starts from the component's converged value, a prescribed rate from the rate it
    // has (docs/dynamics.md): asked for all of the step's motions at once.
    std::vector<std::int64_t> keys;
    std::vector<Query::Quantity> quantities;
    for (const ConnectorCondition& cc : list) {
      const ConditionBlock& block = step.blocks[static_cast<std::size_t>(cc.block)];
      for (std::int32_t e : cc.resolved) {
        const std::int32_t c = plan_.connector_of_element[static_cast<std::size_t>(e)];
        if (c < 0 || !motion) continue;
        keys.push_back(component_key(c, cc.component));
        quantities.push_back(static_cast<Query::Quantity>(block.rate_order));
      }
    }
    const std::vector<double> starts =
        component_values(system, keys, [&](std::size_t k) { return quantities[k]; });
    std::size_t k = 0;
    for (const ConnectorCondition& cc : list) {
      const ConditionBlock& block = step.blocks[static_cast<std::size_t>(cc.block)];
      for (std::int32_t e : cc.resolved) {
        const std::int32_t c = plan_.connector_of_element[static_cast<std::size_t>(e)];
        if (c < 0) continue;
        const std::int64_t key = component_key(c, cc.component);
        double start = 0.0;
        if (motion) {
          start = starts[k++];
          released_connector_loads_.erase(key);
        } else {
          start = load_start(table, key);
        }
        table[key] = define(block, step, cc.magnitude, start, motion);
      }
    }
  };
  connector_conditions(step.motions, motions_, true);
  connector_conditions(step.connector_loads, connector_loads_, false);
  // A later GRAV line on the same element replaces its acceleration, like a load on a DOF.
  for (const GravityLoad& g : step.gravity) {
    const ConditionBlock& block = step.blocks[static_cast<std::size_t>(g.block)];
    for (std::int32_t e : g.resolved) {
      const std::int32_t p = point_mass_of_element_[static_cast<std::size_t>(e)];
      if (p < 0) continue;
      for (int d = 0; d < 3; ++d) {
        const std::int64_t key = static_cast<std::int64_t>(p) * 8 + d;
        gravity_[key] = define(block, step, g.magnitude * g.direction[static_cast<std::size_t>(d)],
                               load_start(gravity_, key), false);
      }
    }
  }
}

// docs/perturbation.md: every condition of the base state holds its value; the step's own
// conditions add their magnitudes to the base values, v(τ) = v_base + τ·Δ, so that τ scales the
// perturbation alone. OP=NEW on *BOUNDARY (*CONNECTOR MOTION) frees the DOFs (components) the base
// state held for this step: their last reactions become loads that keep the base state in
// equilibrium. OP=NEW on a load leaves the base loads as they are: they are not perturbations.
void StepConditions::begin_perturbation(const Step& step, ConnectorSystem& system) {
  base_ = Tables{boundaries_,
                 loads_,
                 motions_,
                 connector_loads_,
                 gravity_,
                 released_loads_,
                 released_connector_loads_};
  period_ = 1.0;
  auto perturbed = [](double base, double delta) {
    return Condition{Mode::Ramp, base, base + delta, -1};
  };
  if (step.replaces(ConditionKind::Boundary)) {
    for (const auto& [eq, c] : boundaries_) {
      const std::int32_t node = plan_.dofs.node_of(static_cast<int>(eq));
      released_loads_[eq] = Condition{
          Mode::Hold, 0.0, system.reaction(node, plan_.dofs.dof_of(static_cast<int>(eq))), -1};
    }
    boundaries_.clear();
  }
  if (step.replaces(ConditionKind::Motion)) {
    const std::vector<double> reactions = component_values(
        system, std::views::keys(motions_), [](std::size_t) { return Query::Reaction; });
    std::size_t k = 0;
    for (const auto& [key, c] : motions_) {
      released_connector_loads_[key] = Condition{Mode::Hold, 0.0, -reactions[k++], -1};
    }
    motions_.clear();
  }
  for (const BoundaryCondition& bc : step.boundaries) {
    const ConditionBlock& block = step.blocks[static_cast<std::size_t>(bc.block)];
    for (std::int32_t node : bc.resolved) {
      for (int dof = 1; dof <= 6; ++dof) {
        const int eq = (bc.dofs >> (dof - 1)) & 1u ? plan_.dofs.equation(node, dof) : -1;
        if (eq < 0) continue;
        boundaries_[eq] = perturbed(system.converged_value(eq), block.fixed ? 0.0 : bc.magnitude);
        released_loads_.erase(eq);
      }
    }
  }
  for (const ConcentratedLoad& load : step.loads) {
    for (std::int32_t node : load.resolved) {
      const int eq = plan_.dofs.equation(node, load.dof);
      if (eq >= 0) loads_[eq] = perturbed(load_start(base_->loads, eq), load.magnitude);
    }
  }
  for (const ConnectorCondition& m : step.motions) {
    const ConditionBlock& block = step.blocks[static_cast<std::size_t>(m.block)];
    for (std::int32_t e : m.resolved) {
      const std::int32_t c = plan_.connector_of_element[static_cast<std::size_t>(e)];
      if (c < 0) continue;
      const std::int64_t key = component_key(c, m.component);
      // A perturbation step keeps the whole plan on every rank (whole_tangent_need.cpp).
      const double base =
          system.connector_output(static_cast<std::size_t>(c)).change[m.component - 1];
      motions_[key] = perturbed(base, block.fixed ? 0.0 : m.magnitude);
      released_connector_loads_.erase(key);
    }
  }
  for (const ConnectorCondition& cl : step.connector_loads) {
    for (std::int32_t e : cl.resolved) {
      const std::int32_t c = plan_.connector_of_element[static_cast<std::size_t>(e)];
      if (c < 0) continue;
      const std::int64_t key = component_key(c, cl.component);
      connector_loads_[key] = perturbed(load_start(base_->connector_loads, key), cl.magnitude);
    }
  }
  for (const GravityLoad& g : step.gravity) {
    for (std::int32_t e : g.resolved) {
      const std::int32_t p = point_mass_of_element_[static_cast<std::size_t>(e)];
      if (p < 0) continue;
      for (int d = 0; d < 3; ++d) {
        const std::int64_t key = static_cast<std::int64_t>(p) * 8 + d;
        gravity_[key] = perturbed(load_start(base_->gravity, key),
                                  g.magnitude * g.direction[static_cast<std::size_t>(d)]);
      }
    }
  }
}

void StepConditions::end_perturbation() {
  if (!base_) return;
  boundaries_ = std::move(base_->boundaries);
  loads_ = std::move(base_->loads);
  motions_ = std::move(base_->motions);
  connector_loads_ = std::move(base_->connector_loads);
  gravity_ = std::move(base_->gravity);
  released_loads_ = std::move(base_->released_loads);
  released_connector_loads_ = std::move(base_->released_connector_loads);
  base_.reset();
}

void StepConditions::apply(ConnectorSystem& system, double step_time, double total_time) const {
  push(system, [&](const Condition& c) { return value_at(c, {step_time, total_time}); });
}

double StepConditions::value_at(const Condition& c, Time time) const {
  return c.value(period_ > 0 ? time.first / period_ : 1.0, time.first, time.second, amplitudes_);
}

void StepConditions::apply_blended(ConnectorSystem& system, Time from, Time to,
                                   double fraction) const {
  push(system, [&](const Condition& c) {
    const double start = value_at(c, from);
    return start + fraction * (value_at(c, to) - start);
  });
}

bool StepConditions::loads_change(Time from, Time to) const {
  for (const Table* table :
       {&loads_, &released_loads_, &gravity_, &connector_loads_, &released_connector_loads_}) {
    for (const auto& [key, c] : *table) {
      if (value_at(c, from) != value_at(c, to)) return true;
    }
  }
  return false;
}

template <class Value>
void StepConditions::push(ConnectorSystem& system, const Value& value) const {
  IncrementConditions& conditions = system.conditions();
  conditions.clear();
  for (const auto& [eq, c] : boundaries_) {
    const int equation = static_cast<int>(eq);
    conditions.prescribe(equation, c.rate_order == 0 ? value(c)
                                                     : system.displacement_of_rate(
                                                           equation, c.rate_order, value(c)));
  }
  for (const auto& [eq, c] : loads_) conditions.add_load(static_cast<int>(eq), value(c));
  for (const auto& [eq, c] : released_loads_) conditions.add_load(static_cast<int>(eq), value(c));
  for (const auto& [key, c] : gravity_) {
    const PointMass& p = point_masses_[static_cast<std::size_t>(key / 8)];
    const int d = static_cast<int>(key % 8);
    const int eq = plan_.dofs.equation(p.node, d + 1);
    if (eq >= 0) conditions.add_load(eq, p.mass[d] * value(c));
  }
  // A prescribed rate (a *DYNAMIC step's TYPE=VELOCITY or ACCELERATION) moves the component
  // from its converged CU, CV and CA, asked for all of them at once.
  std::vector<std::int64_t> rate_keys;
  for (const auto& [key, c] : motions_) {
    if (c.rate_order != 0) rate_keys.insert(rate_keys.end(), {key, key, key});
  }
  const std::vector<double> converged =
      rate_keys.empty() ? std::vector<double>()
                        : component_values(system, rate_keys, [](std::size_t k) {
                            return static_cast<Query::Quantity>(k % 3);
                          });
  std::size_t k = 0;
  for (const auto& [key, c] : motions_) {
    double target = value(c);
    if (c.rate_order != 0) {
      target = system.value_of_rate(converged[k], converged[k + 1], converged[k + 2], c.rate_order,
                                    target);
      k += 3;
    }
    conditions.prescribe_motion(static_cast<int>(key / 8), static_cast<int>(key % 8), target);
  }
  for (const Table* table : {&connector_loads_, &released_connector_loads_}) {
    for (const auto& [key, c] : *table) {
      conditions.add_connector_load(static_cast<int>(key / 8), static_cast<int>(key % 8), value(c));
    }
  }
}

void StepConditions::end_step(double period, double total_time, double tau) {
  for (Table* table : {&boundaries_, &loads_, &motions_, &connector_loads_, &gravity_}) {
    for (auto& [key, c] : *table) {
      if (c.mode == Mode::Hold) continue;
      const bool follows_total_time =
          c.amplitude >= 0 &&
          model_.history.amplitudes[static_cast<std::size_t>(c.amplitude)].total_time;
      if (follows_total_time) continue;
      c = Condition{Mode::Hold, 0.0, c.value(tau, period, total_time, amplitudes_), -1,
                    c.rate_order};
    }
  }
  released_loads_.clear();
  released_connector_loads_.clear();
}

}  // namespace clinch
