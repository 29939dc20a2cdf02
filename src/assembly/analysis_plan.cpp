#include "src/assembly/analysis_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "base/diagnostic.hpp"
#include "src/assembly/constrained_elements.hpp"
#include "src/assembly/rotary_inertia_finite.hpp"
#include "src/behavior/connector_laws.hpp"
#include "src/behavior/elastic/elastic_behavior.hpp"
#include "src/model/orientation_triad.hpp"
#include "src/parallel/communicator.hpp"

namespace clinch {
namespace {

constexpr DofMask kRotationDofs = 0b111000;

Vector3 to_vector(const Vec3& v) { return {v[0], v[1], v[2]}; }

Matrix3 to_matrix(const Triad& t) {
  Matrix3 m;
  for (int k = 0; k < 3; ++k) m.col(k) = to_vector(t[static_cast<std::size_t>(k)]);
  return m;
}

// Components a *CONNECTOR MOTION of any step (or model data) prescribes, per element; the
// targets as validation resolved them.
std::vector<ComponentMask> motion_components(const Model& model) {
  std::vector<ComponentMask> mask(model.elements.size(), 0);
  auto add = [&](const ConnectorCondition& c) {
    for (std::int32_t e : c.resolved) {
      mask[static_cast<std::size_t>(e)] |= component_bit(c.component);
    }
  };
  for (const ConnectorCondition& c : model.history.model_motions) add(c);
  for (const Step& step : model.history.steps) {
    for (const ConnectorCondition& c : step.motions) add(c);
  }
  return mask;
}

class PlanBuilder {
 public:
  PlanBuilder(const Model& model, AnalysisPlan& plan, const PlanShare* share)
      : model_(model), plan_(plan), share_(share) {}

  bool build(std::string* error) {
    plan_.dofs = DofMap(active_dofs(model_));
    plan_.two_d = model_.dimension == 2;
    plan_.connector_of_element.assign(model_.elements.size(), -1);
    plan_.spring_of_element.assign(model_.elements.size(), -1);
    motions_ = motion_components(model_);
    length_tolerance_ = geometry_tolerance(model_.nodes);
    // NLGEOM stays on once set (keywords.md §13): the steps' flags are the effective ones.
    const auto& steps = model_.history.steps;
    plan_.small_displacement =
        steps.empty() ||
        std::any_of(steps.begin(), steps.end(), [](const Step& s) { return !s.nlgeom; });
    plan_.dynamic =
        std::any_of(steps.begin(), steps.end(), [](const Step& s) { return s.dynamic; });
    // A *FREQUENCY step's mass must lie in the pattern too (constrained inertia couples).
    const bool frequency =
        std::any_of(steps.begin(), steps.end(), [](const Step& s) { return s.frequency; });
    if (plan_.dynamic || frequency) plan_.inertia = nodal_inertia(model_, plan_.dofs);
    plan_.owned_inertia = plan_.inertia.size();
    plan_.finite_rotary_inertia =
        std::any_of(plan_.inertia.begin(), plan_.inertia.end(),
                    [](const NodeInertia& n) { return has_finite_rotary_inertia(n, true); });
    plan_.stabilized = std::any_of(steps.begin(), steps.end(), [](const Step& s) {
      return s.procedure && s.procedure->stabilize && !s.dynamic;
    });
    plan_.energies =
        plan_.dynamic || plan_.stabilized ||
        std::any_of(steps.begin(), steps.end(), [](const Step& s) {
          return std::any_of(s.outputs.begin(), s.outputs.end(),
                             [](const OutputRequest& r) { return !r.energies.empty(); });
        });
    section_laws_.assign(model_.sections.connector_sections.size(), {});
    section_laws_built_.assign(model_.sections.connector_sections.size(), false);
    for (const SpringProperty& spring : model_.sections.springs) {
      plan_.spring_laws.push_back(spring.valid ? std::optional<SpringLaw>(SpringLaw(spring))
                                               : std::nullopt);
    }
    for (std::size_t s = 0; s < model_.sections.connector_sections.size(); ++s) {
      plan_.section_stops.push_back(stops_of_section(static_cast<std::int32_t>(s)));
    }
    plan_.connector_total = static_cast<std::size_t>(
        std::count_if(model_.elements.begin(), model_.elements.end(),
                      [](const Element& element) { return is_connector(element.type); }));
    plan_.spring_total = static_cast<std::size_t>(
        std::count_if(model_.elements.begin(), model_.elements.end(), [](const Element& element) {
          return element.type != ElementType::Held && !is_connector(element.type);
        }));
    own_connectors_ = {0, plan_.connector_total};
    own_springs_ = {0, plan_.spring_total};
    if (share_ && share_->ranks > 1) {
      plan_.shared = true;
      own_connectors_ = share_of(plan_.connector_total, share_->rank, share_->ranks);
      own_springs_ = share_of(plan_.spring_total, share_->rank, share_->ranks);
      plan_.share_multipliers.assign(static_cast<std::size_t>(share_->ranks), 0);
    }
    // Reserved up front: regrowing the vectors of a deck with 10⁵ connectors (a record and its
    // kinematics are about 0.7 kB) copies them and doubles the peak memory.
    plan_.connectors.reserve(own_connectors_.end - own_connectors_.begin);
    plan_.kinematics.reserve(own_connectors_.end - own_connectors_.begin);
    plan_.first_connector = own_connectors_.begin;
    plan_.first_spring = own_springs_.begin;
    plan_.springs.reserve(own_springs_.end - own_springs_.begin);
    for (std::size_t e = 0; e < model_.elements.size(); ++e) {
      const Element& element = model_.elements[e];
      // Held elements carry no formulation: only MASS and ROTARYI reach a run, as the nodal
      // inertia of dynamic steps (nodal_inertia.hpp).
      if (element.type == ElementType::Held) continue;
      const bool ok = is_connector(element.type)
                          ? add_connector(static_cast<std::int32_t>(e), error)
                          : add_spring(static_cast<std::int32_t>(e), error);
      if (!ok) return false;
    }
    return true;
  }

 private:
  // The laws of a section's behaviour, built once per section and shared by its connectors.
  const std::vector<const Behavior*>& laws_of_section(std::int32_t s) {
    const auto index = static_cast<std::size_t>(s);
    if (!section_laws_built_[index]) {
      section_laws_built_[index] = true;
      const ConnectorSection& section = model_.sections.connector_sections[index];
      if (section.behavior_index >= 0) {
        const ConnectorBehavior& b =
            model_.behaviors.behaviors[static_cast<std::size_t>(section.behavior_index)];
        DamageControls controls;
        if (section.controls_index >= 0) {
          const SectionControls& c =
              model_.sections.controls[static_cast<std::size_t>(section.controls_index)];
          controls = {c.element_deletion, c.max_degradation, c.viscosity};
        }
        for (auto& law : make_connector_laws(b, section.available, section.constrained, controls)) {
          plan_.procedure_needs.merge(law->procedure_needs());
          section_laws_[index].push_back(law.get());
          plan_.behaviors.push_back(std::move(law));
        }
      }
    }
    return section_laws_[index];
  }

  // Whether every law of a section gives a symmetric tangent (AnalysisPlan::add_law's rule).
  bool section_symmetric(std::int32_t s) {
    const std::vector<const Behavior*>& laws = laws_of_section(s);
    return std::all_of(laws.begin(), laws.end(), [](const Behavior* law) {
      return law->tangent_is_symmetric() && !law->needs_connector_forces();
    });
  }

  // The stops of a section's connectors on their available components, one table per section
  // (a table in every record took 190 bytes per connector); null when it has none.
  const ConnectorStops* stops_of_section(std::int32_t s) {
    const ConnectorSection& section =
        model_.sections.connector_sections[static_cast<std::size_t>(s)];
    if (section.behavior_index < 0) return nullptr;
    ConnectorStops stops;
    bool any = false;
    for (const ConnectorStop& stop :
         model_.behaviors.behaviors[static_cast<std::size_t>(section.behavior_index)].stops) {
      if (!has_component(section.available, stop.component)) continue;
      stops[static_cast<std::size_t>(stop.component - 1)] = {stop.lower, stop.upper};
      any = any || stop.lower || stop.upper;
    }
    if (!any) return nullptr;
    plan_.stop_tables.push_back(std::make_unique<ConnectorStops>(stops));
    return plan_.stop_tables.back().get();
  }

  // The components of connector element `e` that own a multiplier: constrained, prescribed by a
  // connector motion, RIGID, with a stop or that a lock can hold.
  ComponentMask multiplied_components(std::int32_t e, std::int32_t s,
                                      const ConnectorSection& section,
                                      const ConnectorBehavior* behavior) const {
    ComponentMask multiplied = section.constrained | motions_[static_cast<std::size_t>(e)];
    if (!behavior) return multiplied;
    multiplied |= rigid_components(*behavior, section.available);
    if (const ConnectorStops* stops = plan_.section_stops[static_cast<std::size_t>(s)]) {
      for (int i = 1; i <= 6; ++i) {
        const ConnectorStopLimits& stop = (*stops)[static_cast<std::size_t>(i - 1)];
        if (stop.lower || stop.upper) multiplied |= component_bit(i);
      }
    }
    for (const ConnectorLock& lock : behavior->locks) {
      multiplied |= locked_components(lock, section.available);
    }
    return multiplied;
  }

  static ComponentMask locked_components(const ConnectorLock& lock, ComponentMask available) {
    return lock.locked == 0 ? available : (component_bit(lock.locked) & available);
  }

  // One multiplier equation per component of `multiplied` of connector `index`, numbered in
  // element order on every rank; `r` (null for another rank's connector) records them.
  void number_multipliers(std::size_t index, ComponentMask multiplied, ConnectorRecord* r) {
    for (int i = 1; i <= 6; ++i) {
      if (!has_component(multiplied, i)) continue;
      const int eq = plan_.dofs.add_multiplier(i >= 4);
      plan_.has_multipliers = true;
      if (plan_.shared) ++plan_.share_multipliers[share_of_connector(index)];
      if (!r) continue;
      r->multiplier_components[static_cast<std::size_t>(r->multiplier_count++)] =
          static_cast<std::int8_t>(i);
      r->local.equation[static_cast<std::size_t>(r->local.count++)] = eq;
    }
  }

  bool add_connector(std::int32_t e, std::string* error) {
    const Element& element = model_.elements[static_cast<std::size_t>(e)];
    const std::int32_t s = model_.sections.section_of_element[static_cast<std::size_t>(e)];
    const ConnectorSection& section =
        model_.sections.connector_sections[static_cast<std::size_t>(s)];
    const ConnectorBehavior* behavior =
        section.behavior_index >= 0
            ? &model_.behaviors.behaviors[static_cast<std::size_t>(section.behavior_index)]
            : nullptr;
    const std::size_t index = next_connector_++;
    plan_.connector_of_element[static_cast<std::size_t>(e)] = static_cast<std::int32_t>(index);
    const std::int32_t a = element.nodes[0], b = element.nodes[1];
    const Vector3 xa = a >= 0 ? to_vector(model_.nodes[static_cast<std::size_t>(a)].x) : Vector3{};
    const Vector3 xb = b >= 0 ? to_vector(model_.nodes[static_cast<std::size_t>(b)].x) : xa;
    const Vector3 xa0 = a >= 0 ? xa : xb;  // a ground end sits at the other node (§1.2)
    // What the whole model decides, from every connector on every rank.
    plan_.length_scale = std::max(plan_.length_scale, (xb - xa0).stableNorm());
    plan_.all_laws_symmetric = plan_.all_laws_symmetric && section_symmetric(s);
    if (index < own_connectors_.begin || index >= own_connectors_.end) {
      // Another rank's connector: only its multipliers, so that every rank numbers them alike.
      number_multipliers(index, multiplied_components(e, s, section, behavior), nullptr);
      return true;
    }
    ConnectorRecord r;
    r.element = e;
    r.section = s;
    r.nodes = element.nodes;
    r.available = section.available;
    r.constrained = section.constrained;

    ConnectorSetup setup;
    setup.type_names = section.type_names;
    setup.xa0 = xa0;
    setup.xb0 = xb;
    setup.ea0 = Matrix3::Identity();
    for (int end = 0; end < 2; ++end) {
      const std::int32_t o = section.orientation_index[static_cast<std::size_t>(end)];
      if (o < 0) continue;
      const Orientation& orientation = model_.sections.orientations[static_cast<std::size_t>(o)];
      const Matrix3 triad = to_matrix(placed_triad(model_, orientation, element.instance));
      (end == 0 ? setup.ea0 : setup.eb0) = triad;
      (end == 0 ? setup.has_orientation_a : setup.has_orientation_b) = true;
    }
    if (!setup.has_orientation_b) setup.eb0 = setup.ea0;  // §1.3 default at b
    setup.rotations_a = a >= 0 && (plan_.dofs.active(a) & kRotationDofs) != 0;
    setup.two_d = section.two_d;
    setup.length_tolerance = length_tolerance_;
    setup.linearised = plan_.small_displacement;
    std::string why;
    // A rank checks the kinematics of its own connectors: the first error of the model is that
    // of the lowest rank that meets one (run_command.cpp).
    std::optional<ConnectorKinematics> kinematics = ConnectorKinematics::create(setup, &why);
    if (!kinematics) {
      *error = fmt::format("connector element {}: {}",
                           qualified_label(model_, element.instance, element.label), why);
      return false;
    }
    r.kinematics = plan_.kinematics.size();
    r.reference = kinematics->initial_position();
    plan_.kinematics.push_back(std::move(*kinematics));

    if (behavior) {
      r.rigid = rigid_components(*behavior, r.available);
      if (behavior->reference) {
        for (int i = 0; i < 6; ++i) {
          const auto& v = behavior->reference->value[static_cast<std::size_t>(i)];
          if (v && has_component(r.available, i + 1)) r.reference[i] = *v;
        }
      }
      r.stops = plan_.section_stops[static_cast<std::size_t>(s)];
      for (const ConnectorLock& lock : behavior->locks) {
        r.locks.push_back({lock.component, locked_components(lock, r.available), lock.bounds});
      }
      // §5.3: RELEASE=ALL frees every available component, never a constrained one.
      for (const ConnectorFailure& failure : behavior->failures) {
        const ComponentMask releases =
            failure.released == 0 ? r.available : (component_bit(failure.released) & r.available);
        r.failures.push_back({failure.component, releases, failure.bounds});
      }
    }
    for (int c = 0; c < 12; ++c) {
      const std::int32_t node = c < 6 ? a : b;
      const int eq = plan_.dofs.equation(node, c % 6 + 1);
      if (eq < 0) continue;
      r.columns[static_cast<std::size_t>(r.column_count++)] = static_cast<std::int8_t>(c);
      r.local.equation[static_cast<std::size_t>(r.local.count++)] = eq;
    }
    number_multipliers(index, multiplied_components(e, s, section, behavior), &r);
    plan_.connectors.push_back(std::move(r));
    for (const Behavior* law : laws_of_section(s)) plan_.add_law(plan_.connectors.size() - 1, *law);
    return true;
  }

  bool add_spring(std::int32_t e, std::string* /*error*/) {
    const std::size_t index = next_spring_++;
    plan_.spring_of_element[static_cast<std::size_t>(e)] = static_cast<std::int32_t>(index);
    if (index >= own_springs_.begin && index < own_springs_.end) {
      plan_.springs.push_back(spring_record(model_, plan_.dofs, e));
    }
    return true;
  }

  const Model& model_;
  AnalysisPlan& plan_;
  const PlanShare* share_;
  ItemRange own_connectors_, own_springs_;            // the elements whose records this plan holds
  std::size_t next_connector_ = 0, next_spring_ = 0;  // in element order
  // The rank whose share holds connector `index` (share_of, in element order).
  std::size_t share_of_connector(std::size_t index) const {
    std::size_t rank = 0;
    while (share_of(plan_.connector_total, static_cast<int>(rank), share_->ranks).end <= index) {
      ++rank;
    }
    return rank;
  }
  std::vector<ComponentMask> motions_;
  std::vector<std::vector<const Behavior*>> section_laws_;
  std::vector<bool> section_laws_built_;
  double length_tolerance_ = 1e-8;
};

}  // namespace

SpringRecord spring_record(const Model& model, const DofMap& dofs, std::int32_t e) {
  const Element& element = model.elements[static_cast<std::size_t>(e)];
  const std::int32_t p = model.sections.spring_of_element[static_cast<std::size_t>(e)];
  const SpringProperty& property = model.sections.springs[static_cast<std::size_t>(p)];
  SpringRecord r;
  r.element = e;
  r.type = spring_form(element.type);
  r.dashpot = is_dashpot(element.type);
  r.nodes = element.nodes;
  r.law = static_cast<std::size_t>(p);
  int first_dof = 1;
  if (r.type == ElementType::SpringA) {
    r.d0 = to_vector(model.nodes[static_cast<std::size_t>(r.nodes[1])].x) -
           to_vector(model.nodes[static_cast<std::size_t>(r.nodes[0])].x);
  } else {
    // keywords.md §7: DOF d means the global axis, or local axis e_d of the orientation.
    Triad triad{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    if (property.orientation_index >= 0) {
      const Orientation& o =
          model.sections.orientations[static_cast<std::size_t>(property.orientation_index)];
      triad = placed_triad(model, o, element.instance);
    }
    const int slots = r.type == ElementType::Spring1 ? 1 : 2;
    for (int k = 0; k < slots; ++k) {
      const int dof = property.dofs[static_cast<std::size_t>(k)];
      r.rotational = dof >= 4;
      r.direction[static_cast<std::size_t>(k)] =
          to_vector(triad[static_cast<std::size_t>((dof - 1) % 3)]);
    }
    first_dof = r.rotational ? 4 : 1;
  }
  for (int c = 0; c < 6; ++c) {
    const int eq = dofs.equation(r.nodes[static_cast<std::size_t>(c / 3)], first_dof + c % 3);
    if (eq < 0) continue;
    r.columns[static_cast<std::size_t>(r.column_count++)] = static_cast<std::int8_t>(c);
    r.local.equation[static_cast<std::size_t>(r.local.count++)] = eq;
  }
  return r;
}

void AnalysisPlan::add_law(std::size_t c, const Behavior& law) {
  LawStack& stack = connectors[c].laws;
  if (stack.count == LawStack::kMaxLaws) throw std::logic_error("too many laws on one connector");
  stack.slots[static_cast<std::size_t>(stack.count++)] = {&law, history_size};
  stack.needs_connector_forces = stack.needs_connector_forces || law.needs_connector_forces();
  stack.symmetric = stack.symmetric && law.tangent_is_symmetric() && !law.needs_connector_forces();
  all_laws_symmetric = all_laws_symmetric && stack.symmetric;
  history_size += law.history_size();
}

std::optional<AnalysisPlan> build_analysis_plan(const Model& model, std::string* error,
                                                const PlanShare* share) {
  AnalysisPlan plan;
  if (!PlanBuilder(model, plan, share).build(error)) return std::nullopt;
  if (!build_dependent_dofs(model, plan.dofs, plan.dependents, error)) return std::nullopt;
  expand_constrained_elements(plan);
  if (share && share->ranks > 1 && share->local_vectors) {
    localize_equations(plan, share->rank, share->ranks);
  }
  return plan;
}

}  // namespace clinch
