// check_behaviors: the rules of behaviors.md that need a whole *CONNECTOR BEHAVIOR block
// (§2 attachment and per-component rules, §6 plasticity/elasticity interplay, §7 damage
// prerequisites), the unused-behaviour warning, and — through check_behavior_sections — the
// checks that need the connection types of the sections using the behaviour. Runs after
// resolve_sections (which sets ConnectorBehavior::used and the sections' available masks).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "base/diagnostic.hpp"
#include "src/check/check.hpp"
#include "src/check/check_behavior_sections.hpp"
#include "src/model/elasticity_queries.hpp"
#include "src/model/model.hpp"

namespace clinch {
namespace {

constexpr std::uint8_t kAllComponents = 0x3f;

std::uint8_t bit(int component) {
  return component >= 1 && component <= 6 ? static_cast<std::uint8_t>(1u << (component - 1)) : 0;
}

// Components an elasticity covers (§2: coupled linear elasticity counts for every component; an
// all-component RIGID too).
std::uint8_t covered(const ConnectorElasticity& e) {
  switch (e.kind) {
    case ConnectorElasticity::Kind::Coupled:
      return kAllComponents;
    case ConnectorElasticity::Kind::Rigid:
      return e.rigid_all ? kAllComponents : e.rigid_components;
    case ConnectorElasticity::Kind::Linear:
    case ConnectorElasticity::Kind::Nonlinear:
      return bit(e.component);
  }
  return 0;
}

SourceLoc elasticity_loc(const ConnectorElasticity& e) {
  return e.component_loc.valid() ? e.component_loc : e.loc;
}

class BehaviorChecker {
 public:
  // `available`: the components every section using the behaviour makes available (all six
  // when none uses it). Rules about other components would only repeat the availability errors
  // (component-not-available, potential-unavailable-component) reported for them.
  BehaviorChecker(const ConnectorBehavior& b, std::uint8_t available, DiagnosticSink& sink)
      : b_(b), available_(available), sink_(sink) {}

  void run() {
    elasticities();
    stops();
    plasticities();
    damage();
  }

 private:
  // §2: several elasticities on a component add; RIGID with any other elasticity on the same
  // component is an error.
  void elasticities() {
    for (std::size_t k = 0; k < b_.elasticities.size(); ++k) {
      const ConnectorElasticity& e = b_.elasticities[k];
      if (!e.valid) {
        // An option we could not read: its components are unknown, so stay silent about them.
        invalid_elasticity_ |= e.component > 0 ? bit(e.component) : kAllComponents;
        continue;
      }
      const bool rigid = e.kind == ConnectorElasticity::Kind::Rigid;
      const std::uint8_t mask = covered(e);
      for (int c = 1; c <= 6; ++c) {
        if (!(mask & bit(c))) continue;
        ComponentElasticity& on = elastic_[static_cast<std::size_t>(c - 1)];
        const int clash = rigid ? on.first : on.rigid;
        if (clash >= 0) {
          Diagnostic& d = sink_.report(
              DiagCode::elasticity_duplicate, elasticity_loc(e),
              fmt::format("component {} of connector behavior '{}' has a RIGID elasticity and "
                          "another elasticity; RIGID cannot be combined with another "
                          "elasticity on the same component",
                          c, b_.name.display));
          d.notes.push_back({b_.elasticities[static_cast<std::size_t>(clash)].loc,
                             "the other elasticity is here"});
          break;  // one report per option
        }
        if (on.first < 0) on.first = static_cast<int>(k);
        switch (e.kind) {
          case ConnectorElasticity::Kind::Rigid:
            on.rigid = static_cast<int>(k);
            break;
          case ConnectorElasticity::Kind::Nonlinear:
            if (on.nonlinear < 0) on.nonlinear = static_cast<int>(k);
            break;
          case ConnectorElasticity::Kind::Linear:
            on.linear = true;
            on.stiffness += e.stiffness;
            break;
          case ConnectorElasticity::Kind::Coupled:
            on.linear = true;
            on.stiffness += e.coupled[c - 1][c - 1];
            break;
        }
      }
    }
  }

  // §2: at most one stop per component.
  void stops() {
    std::array<int, 6> stop_of;
    stop_of.fill(-1);
    for (std::size_t k = 0; k < b_.stops.size(); ++k) {
      const ConnectorStop& s = b_.stops[k];
      if (s.component < 1 || s.component > 6) continue;
      int& slot = stop_of[static_cast<std::size_t>(s.component - 1)];
      if (slot < 0) {
        slot = static_cast<int>(k);
        continue;
      }
      Diagnostic& d = sink_.report(
          DiagCode::stop_duplicate, s.component_loc.valid() ? s.component_loc : s.loc,
          fmt::format("component {} already has a *CONNECTOR STOP in connector behavior '{}'",
                      s.component, b_.name.display));
      d.notes.push_back({b_.stops[static_cast<std::size_t>(slot)].loc, "previous stop is here"});
    }
  }

  // The linear elastic stiffness on `component`, every definition added (0: none known), for
  // the softening limit of §6.1; a rigid-plastic component has its stiff spring (§4.4).
  double stiffness_of(int component) const {
    if (component < 1 || component > 6) return 0;
    const ComponentElasticity& on = elastic_[static_cast<std::size_t>(component - 1)];
    if (on.rigid >= 0) return rigid_plastic_stiffness(b_, available_, component);
    return on.linear ? on.stiffness : 0.0;
  }

  void plasticities() {
    std::array<int, 6> uncoupled_of;
    uncoupled_of.fill(-1);
    int coupled = -1;
    int uncoupled_count = 0;
    for (std::size_t k = 0; k < b_.plasticities.size(); ++k) {
      const ConnectorPlasticity& p = b_.plasticities[k];
      if (!p.isotropic && !p.kinematic) {
        sink_.report(DiagCode::plasticity_no_hardening, p.loc,
                     "*CONNECTOR PLASTICITY needs a *CONNECTOR HARDENING (ISOTROPIC, KINEMATIC "
                     "or both)");
      }
      if (!p.valid) continue;
      if (p.coupled()) {
        if (coupled >= 0) {
          // §2: v1 allows one coupled plasticity per behaviour.
          Diagnostic& d = sink_.report(DiagCode::unsupported_option, p.loc,
                                       "a second coupled *CONNECTOR PLASTICITY in one connector "
                                       "behavior is not supported by clinch");
          d.notes.push_back({b_.plasticities[static_cast<std::size_t>(coupled)].loc,
                             "first coupled plasticity is here"});
          continue;
        }
        coupled = static_cast<int>(k);
        coupled_components_ =
            potential_components(b_, PotentialOwner::Kind::Plasticity, k) & available_;
        needs_linear_elasticity_coupled(p);
      } else {
        int& slot = uncoupled_of[static_cast<std::size_t>(p.component - 1)];
        if (slot >= 0) {
          Diagnostic& d = sink_.report(
              DiagCode::plasticity_overlap, p.component_loc,
              fmt::format("component {} already has a *CONNECTOR PLASTICITY", p.component));
          d.notes.push_back(
              {b_.plasticities[static_cast<std::size_t>(slot)].loc, "previous plasticity is here"});
          continue;
        }
        slot = static_cast<int>(k);
        ++uncoupled_count;
        needs_linear_elasticity_uncoupled(p);
        if (uncoupled_count == 2 && coupled_offdiagonal()) {
          // §6.3: several uncoupled plastic components with a non-diagonal coupled D.
          sink_.report(DiagCode::unsupported_option, p.loc,
                       "several uncoupled plasticities combined with a coupled (non-diagonal) "
                       "elasticity are not supported by clinch");
        }
      }
      hardening(p);
    }
    if (coupled >= 0 && uncoupled_count > 0 && coupled_offdiagonal()) {
      // §6.3–§6.4: with a non-diagonal D the two returns would move each other's forces.
      for (int slot : uncoupled_of) {
        if (slot < 0) continue;
        Diagnostic& d = sink_.report(
            DiagCode::unsupported_option, b_.plasticities[static_cast<std::size_t>(slot)].loc,
            "an uncoupled plasticity together with a coupled plasticity and a coupled "
            "(non-diagonal) elasticity is not supported by clinch");
        d.notes.push_back(
            {b_.plasticities[static_cast<std::size_t>(coupled)].loc, "coupled plasticity is here"});
        break;
      }
    }
    // §2: no component in both an uncoupled and the coupled plasticity.
    if (coupled < 0 || !coupled_components_) return;
    for (int c = 1; c <= 6; ++c) {
      const int u = uncoupled_of[static_cast<std::size_t>(c - 1)];
      if (u < 0 || !(coupled_components_ & bit(c))) continue;
      const ConnectorPlasticity& p = b_.plasticities[static_cast<std::size_t>(u)];
      Diagnostic& d = sink_.report(
          DiagCode::plasticity_overlap, p.component_loc,
          fmt::format("component {} has an uncoupled *CONNECTOR PLASTICITY and is also in the "
                      "potential of the coupled plasticity",
                      c));
      d.notes.push_back(
          {b_.plasticities[static_cast<std::size_t>(coupled)].loc, "coupled plasticity is here"});
    }
  }

  bool coupled_offdiagonal() const {
    for (const ConnectorElasticity& e : b_.elasticities) {
      if (e.kind != ConnectorElasticity::Kind::Coupled || !e.valid) continue;
      for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 6; ++j) {
          if (i != j && e.coupled[i][j] != 0) return true;
        }
      }
    }
    return false;
  }

  // §2, §4.4, §6: a plastic component needs linear (uncoupled or coupled) elasticity, or RIGID
  // elasticity (rigid-plastic), and no NONLINEAR elasticity. `where` locates the report.
  // Returns false when the component broke the rule (reported).
  bool plastic_component_elasticity(int c, SourceLoc where, const char* what) {
    if (invalid_elasticity_ & bit(c)) return true;
    const ComponentElasticity& on = elastic_[static_cast<std::size_t>(c - 1)];
    if (on.nonlinear >= 0) {
      Diagnostic& d = sink_.report(
          DiagCode::plasticity_needs_linear_elasticity, where,
          fmt::format("{} on component {} needs linear elasticity, but that component has a "
                      "NONLINEAR elasticity",
                      what, c));
      d.notes.push_back(
          {b_.elasticities[static_cast<std::size_t>(on.nonlinear)].loc, "elasticity defined here"});
      return false;
    }
    if (on.rigid >= 0) {
      // §4.4: the rigid part becomes a stiff spring, named so that a comparison can pin it.
      sink_.report(DiagCode::rigid_plastic_stiffness, where,
                   fmt::format("component {} is RIGID and plastic (rigid-plastic): its rigid part "
                               "is a stiff spring of {:g}",
                               c, rigid_plastic_stiffness(b_, available_, c)));
      return true;
    }
    if (on.linear) return true;
    sink_.report(DiagCode::plasticity_needs_linear_elasticity, where,
                 fmt::format("{} on component {} needs a linear *CONNECTOR ELASTICITY on that "
                             "component (it has none)",
                             what, c));
    return false;
  }

  void needs_linear_elasticity_uncoupled(const ConnectorPlasticity& p) {
    const int c = p.component;
    if (!(available_ & bit(c))) return;
    plastic_component_elasticity(c, p.component_loc, "plasticity");
  }

  void needs_linear_elasticity_coupled(const ConnectorPlasticity& p) {
    // The components a coupled plasticity involves come from its potential
    // (derived-components-and-potentials.md §2.8); each needs linear elasticity.
    for (int c = 1; c <= 6; ++c) {
      if (!(coupled_components_ & bit(c))) continue;
      if (!plastic_component_elasticity(c, p.loc, "coupled plasticity")) return;
    }
    if (coupled_components_ || invalid_elasticity_) return;
    for (const ConnectorElasticity& e : b_.elasticities) {
      if (e.kind == ConnectorElasticity::Kind::Linear ||
          e.kind == ConnectorElasticity::Kind::Coupled) {
        return;
      }
    }
    sink_.report(DiagCode::plasticity_needs_linear_elasticity, p.loc,
                 fmt::format("coupled plasticity needs linear elasticity, but connector behavior "
                             "'{}' has no linear *CONNECTOR ELASTICITY",
                             b_.name.display));
  }

  // §6.1: softening limit, kinematic F_0 and the yield size of a kinematic-only plasticity.
  void hardening(const ConnectorPlasticity& p) {
    double k_min = 0;
    if (!p.coupled()) {
      k_min = stiffness_of(p.component);
    } else {
      k_min = std::numeric_limits<double>::infinity();
      for (int c = 1; c <= 6; ++c) {
        const double k = stiffness_of(c);
        if (k > 0) k_min = std::min(k_min, k);
      }
      if (!std::isfinite(k_min)) k_min = 0;
    }
    if (p.isotropic && p.isotropic->valid && k_min > 0) {
      const IsotropicHardening& h = *p.isotropic;
      if (h.definition == IsotropicHardening::Definition::Tabular) {
        for (std::size_t j = 0; j + 1 < h.table.size(); ++j) {
          const TablePoint& a = h.table[j];
          const TablePoint& c = h.table[j + 1];
          const double slope = (c.value - a.value) / (c.at - a.at);
          if (slope <= -k_min) {
            sink_.report(DiagCode::softening_too_steep, c.loc,
                         fmt::format("hardening slope {:.6g} is too steep: softening must stay "
                                     "above -{:.6g} (minus the elastic stiffness)",
                                     slope, k_min));
            break;
          }
        }
      } else if (h.q_inf * h.b <= -k_min) {
        sink_.report(DiagCode::softening_too_steep, h.data_loc,
                     fmt::format("initial hardening slope Q_inf*b = {:.6g} is too steep: "
                                 "softening must stay above -{:.6g} (minus the elastic stiffness)",
                                 h.q_inf * h.b, k_min));
      }
    }
    if (!p.kinematic || !p.kinematic->valid) return;
    const KinematicHardening& k = *p.kinematic;
    if (!p.isotropic) {
      if (k.f0 <= 0) {
        sink_.report(DiagCode::yield_not_positive, k.f0_loc.valid() ? k.f0_loc : k.loc,
                     fmt::format("yield force F_0 must be positive, got {}", k.f0));
      }
      return;
    }
    if (!p.isotropic->valid) return;
    const IsotropicHardening& h = *p.isotropic;
    double fy0 = 0;
    if (h.definition == IsotropicHardening::Definition::Tabular) {
      if (h.table.empty()) return;
      fy0 = h.table.front().value;
    } else {
      fy0 = h.f0;
    }
    if (std::fabs(k.f0 - fy0) > 1e-6 * std::fabs(fy0)) {
      sink_.report(DiagCode::kinematic_f0_ignored, k.f0_loc.valid() ? k.f0_loc : k.loc,
                   fmt::format("kinematic F_0 = {} differs from the isotropic yield force {} at "
                               "zero plastic motion; clinch uses {}",
                               k.f0, fy0, fy0));
    }
  }

  void damage() {
    for (const DamageInitiation& d : b_.damage_initiations) {
      if (!d.valid || d.criterion != DamageInitiation::Criterion::PlasticMotion) continue;
      // §7.1: PLASTIC MOTION needs plasticity on the component, or a coupled plasticity.
      bool found = false;
      for (const ConnectorPlasticity& p : b_.plasticities) {
        if (d.coupled() ? p.coupled() : p.component == d.component) found = true;
      }
      if (found) continue;
      sink_.report(DiagCode::damage_needs_plasticity, d.criterion_loc,
                   d.coupled()
                       ? std::string("CRITERION=PLASTIC MOTION without COMPONENT needs a coupled "
                                     "*CONNECTOR PLASTICITY in the same behavior")
                       : fmt::format("CRITERION=PLASTIC MOTION on component {} needs a "
                                     "*CONNECTOR PLASTICITY on that component",
                                     d.component));
    }
    for (std::size_t k = 0; k < b_.damage_evolutions.size(); ++k) {
      const DamageEvolution& e = b_.damage_evolutions[k];
      if (!e.valid || e.initiation < 0) continue;
      const DamageInitiation& d = b_.damage_initiations[static_cast<std::size_t>(e.initiation)];
      if (!d.coupled() || d.criterion == DamageInitiation::Criterion::PlasticMotion) continue;
      if (has_potential(PotentialOwner::Kind::DamageEvolution, k)) continue;
      // §7.2: without an evolution potential δ is the Euclidean norm of the affected motions
      // (not confirmed), which mixes units when translations and rotations are both affected.
      // Without AFFECTED COMPONENTS they are the components of the initiation potential.
      const std::uint8_t affected =
          e.affected ? e.affected
                     : potential_components(b_, PotentialOwner::Kind::DamageInitiation,
                                            static_cast<std::size_t>(e.initiation));
      if ((affected & 0x07) && (affected & 0x38)) {
        sink_.report(DiagCode::damage_mixed_units, e.affected ? e.affected_loc : e.loc,
                     "the damage evolution motion (the norm of the affected components) mixes "
                     "translations and rotations; define an evolution *CONNECTOR POTENTIAL to "
                     "scale them");
      }
    }
  }

  bool has_potential(PotentialOwner::Kind kind, std::size_t index) const {
    for (const PotentialOwner& o : b_.potential_owners) {
      if (o.kind == kind && o.index == static_cast<std::int32_t>(index)) return o.potential >= 0;
    }
    return false;
  }

  const ConnectorBehavior& b_;
  std::uint8_t available_;
  DiagnosticSink& sink_;
  // What the elasticities of the block put on each component (§2).
  struct ComponentElasticity {
    int first = -1;        // the first definition on it
    int rigid = -1;        // a RIGID definition
    int nonlinear = -1;    // the first NONLINEAR definition
    bool linear = false;   // some linear (uncoupled or coupled) definition
    double stiffness = 0;  // their diagonal stiffness, added
  };
  std::array<ComponentElasticity, 6> elastic_{};
  std::uint8_t invalid_elasticity_ = 0;
  std::uint8_t coupled_components_ = 0;  // components of the coupled plasticity's potential
};

}  // namespace

void check_behaviors(const Model& model, DiagnosticSink& sink) {
  const auto& behaviors = model.behaviors.behaviors;
  for (std::size_t i = 0; i < behaviors.size(); ++i) {
    const ConnectorBehavior& b = behaviors[i];
    std::uint8_t available = kAllComponents;
    for (const ConnectorSection& s : model.sections.connector_sections) {
      if (s.valid && s.behavior_index == static_cast<std::int32_t>(i)) available &= s.available;
    }
    BehaviorChecker(b, available, sink).run();
    if (b.referable && !b.used) {
      sink.report(DiagCode::defined_but_unused, b.loc,
                  fmt::format("connector behavior '{}' is not used by any *CONNECTOR SECTION",
                              b.name.display));
    }
    check_behavior_against_sections(model, i, sink);
  }
}

BehaviorFeatures behavior_features(const ConnectorBehavior& behavior) {
  BehaviorFeatures f;
  f.elasticity = !behavior.elasticities.empty();
  f.plasticity = !behavior.plasticities.empty();
  for (const ConnectorPlasticity& p : behavior.plasticities) {
    if (p.kinematic) f.kinematic_hardening = true;
  }
  f.damage = !behavior.damage_initiations.empty();
  for (const DamageInitiation& d : behavior.damage_initiations) {
    switch (d.criterion) {
      case DamageInitiation::Criterion::Force:
        f.force_criterion = true;
        break;
      case DamageInitiation::Criterion::Motion:
        f.motion_criterion = true;
        break;
      case DamageInitiation::Criterion::PlasticMotion:
        f.plastic_motion_criterion = true;
        break;
    }
  }
  // CSLST also reports released components (status 4, output-variables.md §2).
  f.stops_or_locks =
      !behavior.stops.empty() || !behavior.locks.empty() || !behavior.failures.empty();
  f.friction = !behavior.frictions.empty();
  return f;
}

}  // namespace clinch
