// resolve_history: the rules of keywords.md §8–§18 that need the whole model. Amplitude
// references (E0507, W0501), procedures of unclosed steps (E0605), boundary conditions and loads
// against the DOFs the elements use (W0502, W0803, E0801), repeated conditions (W0802), loads on
// prescribed DOFs or components (W0801), connector motions and loads against the connection type
// (E0512, E0709, E0702), UNSYMM=NO with an unsymmetric behaviour (W0806), and the output requests
// (resolve_output_requests.cpp).
#include <cmath>

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <array>
#include <bit>
#include <memory>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "base/diagnostic.hpp"
#include "base/suggest.hpp"
#include "src/model/active_dofs.hpp"
#include "src/model/connection_types.hpp"
#include "src/model/model.hpp"
#include "src/resolve/reference_lookup.hpp"
#include "src/resolve/resolve.hpp"
#include "src/resolve/resolve_output_requests.hpp"

namespace clinch {
namespace {

// "DOF 4", "DOFs 2, 3" for messages.
std::string dof_list(DofMask mask) {
  std::string list;
  int count = 0;
  for (int d = 1; d <= 6; ++d) {
    if (!(mask & (1u << (d - 1)))) continue;
    list += (count++ ? ", " : "") + std::to_string(d);
  }
  return (count == 1 ? "DOF " : "DOFs ") + list;
}

std::string node_name(const Model& model, std::int32_t node) {
  const Node& n = model.nodes[static_cast<std::size_t>(node)];
  return qualified_label(model, n.instance, n.label);
}

std::string element_name(const Model& model, std::int32_t element) {
  const Element& e = model.elements[static_cast<std::size_t>(element)];
  return qualified_label(model, e.instance, e.label);
}

// The conditions that are in force (BCs by node and DOF, motions by element and component),
// carried from model data through the steps (keywords.md §13).
// Per-(node or element, DOF or component) flags with the location of the line that first set
// each entry: one byte of flags and one location per index, in pages of 4096 indices allocated
// when first touched, so that a deck with a million constrained nodes costs a few bytes per node
// and one that holds a handful of the million costs a few pages (ARCHITECTURE.md, performance by
// design).
class DofTable {
 public:
  DofTable() = default;
  DofTable(DofTable&&) = default;
  DofTable& operator=(DofTable&&) = default;
  // A copy of the touched pages (the conditions in force before a perturbation step).
  DofTable(const DofTable& other) {
    pages_.resize(other.pages_.size());
    for (std::size_t p = 0; p < pages_.size(); ++p) {
      if (other.pages_[p]) pages_[p] = std::make_unique<Page>(*other.pages_[p]);
    }
  }
  // Sets (index, dof). Returns true when it was not set; otherwise *previous is the location of
  // the line that set the index first.
  bool insert(std::int32_t index, int dof, SourceLoc loc, SourceLoc* previous = nullptr) {
    const auto i = static_cast<std::size_t>(index);
    if (i / kPage >= pages_.size()) pages_.resize(i / kPage + 1);
    std::unique_ptr<Page>& page = pages_[i / kPage];
    if (!page) page = std::make_unique<Page>();
    std::uint8_t& mask = page->mask[i % kPage];
    const auto bit = static_cast<std::uint8_t>(1u << (dof - 1));
    if (mask == 0) page->first[i % kPage] = loc;
    if (mask & bit) {
      if (previous) *previous = page->first[i % kPage];
      return false;
    }
    mask |= bit;
    return true;
  }
  bool contains(std::int32_t index, int dof) const {
    const auto i = static_cast<std::size_t>(index);
    if (i / kPage >= pages_.size() || !pages_[i / kPage]) return false;
    return (pages_[i / kPage]->mask[i % kPage] >> (dof - 1)) & 1u;
  }
  void clear() { pages_.clear(); }

 private:
  static constexpr std::size_t kPage = 4096;
  struct Page {
    std::array<std::uint8_t, kPage> mask{};
    std::array<SourceLoc, kPage> first{};
  };
  std::vector<std::unique_ptr<Page>> pages_;
};

struct InForce {
  DofTable boundaries;
  DofTable motions;
};

class HistoryValidator {
 public:
  HistoryValidator(Model& model, DiagnosticSink& sink) : model_(model), sink_(sink) {}

  void run() {
    HistoryModel& history = model_.history;
    // The nodes of every *BOUNDARY first: a condition on a rigid body's node anchors the body
    // there, which changes the followers that the active DOFs read.
    for (BoundaryCondition& bc : history.model_boundaries) resolve(bc.target, false, bc.resolved);
    for (Step& step : history.steps) {
      for (BoundaryCondition& bc : step.boundaries) resolve(bc.target, false, bc.resolved);
    }
    anchor_rigid_bodies(model_);
    active_ = active_dofs(model_);
    following_ = following_dofs(model_);
    resolve_amplitudes(history.model_blocks);
    for (Step& step : history.steps) resolve_amplitudes(step.blocks);
    report_unused_amplitudes();

    // Model data: zero BCs and motions, in force from time 0.
    InForce in_force;
    {
      DofTable seen;
      for (BoundaryCondition& bc : history.model_boundaries) {
        check_boundary(bc, "model data", seen, in_force.boundaries);
      }
      seen.clear();
      for (ConnectorCondition& motion : history.model_motions) {
        check_connector(motion, ConditionKind::Motion, "model data", &seen, in_force);
      }
    }

    for (InitialVelocity& velocity : history.initial_velocities) check_initial_velocity(velocity);
    for (const RotatingVelocity& rotating : history.rotating_velocities) {
      expand_rotating_velocity(rotating);
    }

    for (Step& step : history.steps) {
      check_step_structure(step);
      const std::string where = fmt::format("step '{}'", step.name.display);
      // A perturbation step's conditions hold in that step only (docs/perturbation.md).
      std::optional<InForce> base =
          step.is_perturbation() ? std::optional<InForce>(in_force) : std::nullopt;
      if (step.replaces(ConditionKind::Boundary)) in_force.boundaries.clear();
      if (step.replaces(ConditionKind::Motion)) in_force.motions.clear();
      DofTable seen;
      for (BoundaryCondition& bc : step.boundaries) {
        check_boundary(bc, where, seen, in_force.boundaries);
      }
      seen.clear();
      for (ConnectorCondition& motion : step.motions) {
        check_connector(motion, ConditionKind::Motion, where, &seen, in_force);
      }
      for (ConcentratedLoad& load : step.loads) check_load(load, in_force);
      for (GravityLoad& load : step.gravity) check_gravity(load);
      for (ConnectorCondition& load : step.connector_loads) {
        check_connector(load, ConditionKind::ConnectorLoad, where, nullptr, in_force);
      }
      if (base) in_force = std::move(*base);
    }
    resolve_output_requests(model_, active_, sink_);
  }

 private:
  // ---- Amplitudes (keywords.md §8) ----------------------------------------------------------

  void resolve_amplitudes(std::vector<ConditionBlock>& blocks) {
    HistoryModel& history = model_.history;
    for (ConditionBlock& block : blocks) {
      if (block.amplitude.empty()) continue;
      auto it = history.amplitude_by_key.find(block.amplitude.key);
      if (it != history.amplitude_by_key.end() && it->second < 0) continue;  // refused: reported
      if (it != history.amplitude_by_key.end()) {
        block.amplitude_index = it->second;
        history.amplitudes[static_cast<std::size_t>(it->second)].used = true;
        continue;
      }
      Diagnostic& d =
          sink_.report(DiagCode::undefined_amplitude, block.amplitude.loc,
                       fmt::format("undefined amplitude '{}'", block.amplitude.display));
      std::vector<std::string> names;
      for (const Amplitude& a : history.amplitudes) names.push_back(a.name.display);
      if (auto guess = closest_match(block.amplitude.display, names)) {
        d.notes.push_back({block.amplitude.loc, fmt::format("did you mean '{}'?", *guess)});
      }
    }
  }

  void report_unused_amplitudes() {
    for (const Amplitude& a : model_.history.amplitudes) {
      if (a.used) continue;
      sink_.report(DiagCode::defined_but_unused, a.name.loc.valid() ? a.name.loc : a.loc,
                   fmt::format("amplitude '{}' is not used by any load or boundary condition",
                               a.name.display));
    }
  }

  // ---- Steps --------------------------------------------------------------------------------

  void check_step_structure(Step& step) {
    // A closed step without a procedure was reported at its *END STEP; an unclosed one (E0603)
    // is reported here (input-syntax.md §8).
    if (!step.closed && !step.has_procedure()) {
      sink_.report(DiagCode::step_procedure, step.loc,
                   fmt::format("step '{}' has no procedure (expected *STATIC, *DYNAMIC or "
                               "*FREQUENCY)",
                               step.name.display));
    }
    if (step.procedure && step.procedure->riks) check_riks(step);
    // keywords.md §14: UNSYMM=NO with a behaviour whose tangent is unsymmetric (friction).
    if (step.unsymmetric == Unsymmetric::No && uses_friction()) {
      sink_.report(DiagCode::symmetrized_tangent, step.unsymmetric_loc,
                   "UNSYMM=NO with connector friction: the tangent is symmetrised and "
                   "convergence may slow");
    }
  }

  // docs/riks.md: the monitored node is one node; the loads the LPF scales are the step's own,
  // as ramps (amplitudes are ignored, as the manual says of the Riks method).
  void check_riks(Step& step) {
    RiksSettings& riks = *step.procedure->riks;
    if (riks.node) {
      std::vector<std::int32_t> nodes;
      if (resolve(*riks.node, false, nodes)) {
        if (nodes.size() != 1) {
          sink_.report(DiagCode::invalid_value, riks.node->loc,
                       fmt::format("the monitored node must be one node; {} has {}",
                                   describe(*riks.node, false), nodes.size()));
        } else {
          riks.resolved_node = nodes.front();
        }
      }
    }
    if (step.loads.empty() && step.connector_loads.empty() && step.gravity.empty()) {
      sink_.report(DiagCode::step_procedure, step.procedure->loc,
                   fmt::format("step '{}' is a Riks step without loads: the load proportionality "
                               "factor scales the *CLOAD and *CONNECTOR LOAD values the step "
                               "defines",
                               step.name.display));
    }
    // The bordered system takes the LPF's effect on the loads; a prescribed value that moved with
    // it would also move the free DOFs through the predictor of prescribed increments, which
    // the arc length does not measure (docs/riks.md).
    auto moving = [&](const SourceLoc& at, std::string_view what) {
      sink_.report(DiagCode::unsupported_option, at,
                   fmt::format("a non-zero {} in a Riks step is not supported: the load "
                               "proportionality factor scales loads; prescribe the value in a "
                               "*STATIC step before, and load the Riks step with *CLOAD or "
                               "*CONNECTOR LOAD",
                               what));
    };
    for (const BoundaryCondition& bc : step.boundaries) {
      if (bc.magnitude != 0.0) moving(bc.magnitude_loc.valid() ? bc.magnitude_loc : bc.loc,
                                      "*BOUNDARY value");
    }
    for (const ConnectorCondition& motion : step.motions) {
      if (motion.magnitude != 0.0) moving(motion.magnitude_loc.valid() ? motion.magnitude_loc
                                                                       : motion.loc,
                                          "*CONNECTOR MOTION value");
    }
    std::set<std::int32_t> warned;
    for (const ConditionBlock& block : step.blocks) {
      if (block.amplitude.key.empty() || !warned.insert(block.loc.line).second) continue;
      sink_.report(DiagCode::parameter_ignored, block.loc,
                   "AMPLITUDE is ignored in a Riks step: the load proportionality factor "
                   "scales the step's values");
    }
  }

  bool uses_friction() {
    if (friction_known_) return friction_;
    friction_known_ = true;
    for (const ConnectorSection& section : model_.sections.connector_sections) {
      const std::int32_t b = section.behavior_index;
      if (b < 0 || static_cast<std::size_t>(b) >= model_.behaviors.behaviors.size()) continue;
      if (section.elements.empty()) continue;
      if (behavior_features(model_.behaviors.behaviors[static_cast<std::size_t>(b)]).friction) {
        friction_ = true;
      }
    }
    return friction_;
  }

  // ---- *BOUNDARY (keywords.md §9) -----------------------------------------------------------

  // Resolves a condition's target into the list the run reads (`out`); an empty set is E0515.
  bool resolve(const TargetRef& target, bool element, std::vector<std::int32_t>& out) {
    out.clear();
    const bool ok = element ? resolve_elements(model_, target, out, sink_)
                            : resolve_nodes(model_, target, out, sink_);
    if (!ok) return false;
    if (out.empty()) {
      sink_.report(DiagCode::empty_set, target.loc,
                   fmt::format("{} is empty", describe(target, element)));
      return false;
    }
    return true;
  }

  void check_boundary(BoundaryCondition& bc, const std::string& where, DofTable& seen,
                      DofTable& in_force) {
    if (bc.resolved.empty()) return;  // not resolved (reported), or moved to other lines
    DofMask dofs = bc.dofs;
    // In 2-D only the members 1, 2 and 6 of a named type apply (§9).
    if (!bc.named_type.empty() && model_.dimension == 2) dofs &= 0b100011;

    std::int32_t lonely_node = -1;
    std::size_t lonely = 0;
    DofMask inactive = 0;
    std::size_t inactive_nodes = 0;
    std::int32_t inactive_node = -1;
    bool duplicate_reported = false;
    for (std::int32_t node : bc.resolved) {
      const DofMask active = active_[static_cast<std::size_t>(node)];
      if (active == 0) {
        if (!on_held_element(node) && lonely++ == 0) lonely_node = node;
        continue;
      }
      if (dofs & ~active) {
        inactive |= static_cast<DofMask>(dofs & ~active);
        if (inactive_nodes++ == 0) inactive_node = node;
      }
      for (int d = 1; d <= 6; ++d) {
        if (!(dofs & active & (1u << (d - 1)))) continue;
        in_force.insert(node, d, bc.loc);
        SourceLoc previous;
        if (seen.insert(node, d, bc.loc, &previous) || duplicate_reported || previous == bc.loc) {
          continue;
        }
        duplicate_reported = true;
        sink_
            .report(DiagCode::condition_redefined, bc.loc,
                    fmt::format("node {} DOF {} prescribed twice in {}; the later value is used",
                                node_name(model_, node), d, where))
            .notes.push_back({previous, "previously prescribed here"});
      }
    }
    if (lonely == 1) {
      sink_.report(DiagCode::node_without_element, bc.loc,
                   fmt::format("node {} belongs to no element; *BOUNDARY ignored",
                               node_name(model_, lonely_node)));
    } else if (lonely > 1) {
      sink_.report(DiagCode::node_without_element, bc.loc,
                   fmt::format("{} nodes of {} belong to no element; *BOUNDARY ignored for them",
                               lonely, describe(bc.target, false)));
    }
    if (inactive_nodes == 1) {
      sink_.report(DiagCode::inactive_dof, bc.loc,
                   fmt::format("{} {} not active at node {}; boundary condition ignored",
                               dof_list(inactive), std::has_single_bit(inactive) ? "is" : "are",
                               node_name(model_, inactive_node)));
    } else if (inactive_nodes > 1) {
      sink_.report(DiagCode::inactive_dof, bc.loc,
                   fmt::format("{} {} not active at {} nodes of {}; boundary condition ignored "
                               "there",
                               dof_list(inactive), std::has_single_bit(inactive) ? "is" : "are",
                               inactive_nodes, describe(bc.target, false)));
    }
  }

  // ---- *CLOAD (keywords.md §10) -------------------------------------------------------------

  // *INITIAL CONDITIONS, TYPE=VELOCITY: a velocity on a DOF that no element uses would be lost.
  void check_initial_velocity(InitialVelocity& velocity) {
    if (!resolve(velocity.target, false, velocity.resolved)) return;
    const DofMask bit = static_cast<DofMask>(1u << (velocity.dof - 1));
    for (std::int32_t node : velocity.resolved) {
      if ((active_[static_cast<std::size_t>(node)] & bit) || on_held_element(node)) continue;
      sink_.report(DiagCode::invalid_dof, velocity.dof_loc,
                   fmt::format("initial velocity on DOF {} of node {}, which no element uses",
                               velocity.dof, node_name(model_, node)));
      return;
    }
  }

  // *INITIAL CONDITIONS, TYPE=ROTATING VELOCITY: the velocities that the rigid rotation gives each
  // node, as the DOF-wise velocities of TYPE=VELOCITY (which the run reads), on the DOFs the node
  // has; a node with no translational DOF would lose its velocity, which is an error.
  void expand_rotating_velocity(const RotatingVelocity& rotating) {
    std::vector<std::int32_t> nodes;
    if (!resolve(rotating.target, false, nodes)) return;
    const Vec3 axis{rotating.b[0] - rotating.a[0], rotating.b[1] - rotating.a[1],
                    rotating.b[2] - rotating.a[2]};
    const double length = length_of(axis);
    const Vec3 w{rotating.omega * axis[0] / length, rotating.omega * axis[1] / length,
                 rotating.omega * axis[2] / length};
    for (std::int32_t node : nodes) {
      const Vec3& x = model_.nodes[static_cast<std::size_t>(node)].x;
      const Vec3 r{x[0] - rotating.a[0], x[1] - rotating.a[1], x[2] - rotating.a[2]};
      const std::array<double, 6> rates{
          rotating.translation[0] + w[1] * r[2] - w[2] * r[1],
          rotating.translation[1] + w[2] * r[0] - w[0] * r[2],
          rotating.translation[2] + w[0] * r[1] - w[1] * r[0], w[0], w[1], w[2]};
      const DofMask active = active_[static_cast<std::size_t>(node)];
      const bool held = on_held_element(node);
      // A translational velocity on a DOF no element uses would be lost, as for TYPE=VELOCITY; a
      // node without rotational DOFs (a point mass) has no angular velocity to take.
      const double speed = length_of({rates[0], rates[1], rates[2]});
      for (int dof = 1; dof <= 3 && !held; ++dof) {
        if ((active & (1u << (dof - 1))) ||
            std::abs(rates[static_cast<std::size_t>(dof - 1)]) <= 1e-12 * speed) {
          continue;
        }
        sink_.report(DiagCode::invalid_dof, rotating.target.loc,
                     fmt::format("the rotating velocity gives DOF {} of node {} the velocity {}, "
                                 "but no element uses that DOF",
                                 dof, node_name(model_, node),
                                 rates[static_cast<std::size_t>(dof - 1)]));
        return;
      }
      for (int dof = 1; dof <= 6; ++dof) {
        if (!held && !(active & (1u << (dof - 1)))) continue;
        InitialVelocity velocity;
        velocity.target = rotating.target;
        velocity.resolved = {node};
        velocity.dof = dof;
        velocity.value = rates[static_cast<std::size_t>(dof - 1)];
        velocity.loc = velocity.dof_loc = rotating.loc;
        model_.history.initial_velocities.push_back(std::move(velocity));
      }
    }
  }

  // docs/dynamics.md "Gravity": the MASS elements of the line's set (of the model when it names
  // none), and the rigid bodies' elements whose mass comes from their density (ElementMassPoint);
  // a set without one would load nothing, which the analyst should hear of.
  void check_gravity(GravityLoad& load) {
    std::vector<std::int32_t> named;
    if (load.target && !resolve(*load.target, true, named)) return;
    std::vector<bool> wanted(model_.elements.size(), !load.target);
    for (std::int32_t e : named) wanted[static_cast<std::size_t>(e)] = true;
    load.resolved.clear();
    for (const ElementSection& section : model_.structure.sections) {
      if (section.kind != ElementSection::Kind::Mass) continue;
      for (std::int32_t e : section.elements) {
        if (wanted[static_cast<std::size_t>(e)]) load.resolved.push_back(e);
      }
    }
    for (const ElementMassPoint& p : model_.constraints.element_masses) {
      if (wanted[static_cast<std::size_t>(p.element)]) load.resolved.push_back(p.element);
    }
    if (load.resolved.empty()) {
      sink_.report(DiagCode::inactive_dof, load.target ? load.target->loc : load.loc,
                   fmt::format("*DLOAD, GRAV acts on MASS elements, and {} has none: connectors "
                               "and springs have no mass",
                               load.target ? describe(*load.target, true) : "the model"));
    }
  }

  void check_load(ConcentratedLoad& load, const InForce& in_force) {
    if (!resolve(load.target, false, load.resolved)) return;
    const DofMask bit = static_cast<DofMask>(1u << (load.dof - 1));
    std::size_t lost = 0;
    std::int32_t lost_node = -1;
    bool prescribed_reported = false;
    for (std::int32_t node : load.resolved) {
      const auto n = static_cast<std::size_t>(node);
      if (!((active_[n] | following_[n]) & bit)) {
        if (!on_held_element(node) && lost++ == 0) lost_node = node;
        continue;
      }
      if (!prescribed_reported && in_force.boundaries.contains(node, load.dof)) {
        prescribed_reported = true;
        sink_.report(DiagCode::load_on_prescribed_dof, load.loc,
                     fmt::format("*CLOAD on node {} DOF {}, which also has a boundary condition; "
                                 "the load goes into the reaction",
                                 node_name(model_, node), load.dof));
      }
    }
    if (lost > 0) {
      std::string more = lost > 1 ? fmt::format(" (and {} more nodes of {})", lost - 1,
                                                describe(load.target, false))
                                  : "";
      sink_.report(DiagCode::invalid_dof, load.dof_loc,
                   fmt::format("*CLOAD on DOF {} of node {}, which no element uses{}", load.dof,
                               node_name(model_, lost_node), more));
    }
  }

  // ---- *CONNECTOR MOTION, *CONNECTOR LOAD (keywords.md §11, §12) ----------------------------

  void check_connector(ConnectorCondition& condition, ConditionKind kind, const std::string& where,
                       DofTable* seen, InForce& in_force) {
    if (!resolve(condition.target, true, condition.resolved)) return;
    const char* keyword = condition_keyword(kind);
    const int c = condition.component;
    bool kind_reported = false, dimension_reported = false, duplicate_reported = false;
    bool prescribed_reported = false;
    std::vector<std::int32_t> reported_sections;
    const auto& sections = model_.sections;
    for (std::int32_t e : condition.resolved) {
      const Element& element = model_.elements[static_cast<std::size_t>(e)];
      if (!is_connector(element.type)) {
        if (!kind_reported) {
          kind_reported = true;
          const std::string what =
              condition.target.is_label
                  ? fmt::format("element {} is of type {}", element_name(model_, e),
                                element_type_name(model_, e))
                  : fmt::format("{} contains element {} of type {}",
                                describe(condition.target, true), element_name(model_, e),
                                element_type_name(model_, e));
          sink_.report(DiagCode::wrong_element_kind, condition.target.loc,
                       fmt::format("{}; {} needs connector elements", what, keyword));
        }
        continue;
      }
      if (element.type == ElementType::Conn2D2 && c >= 3 && c <= 5) {
        if (!dimension_reported) {
          dimension_reported = true;
          sink_.report(
              DiagCode::component_not_in_2d, condition.component_loc,
              fmt::format("component {} does not exist for CONN2D2 (components 1, 2, 6)", c));
        }
        continue;
      }
      const std::int32_t s = static_cast<std::size_t>(e) < sections.section_of_element.size()
                                 ? sections.section_of_element[static_cast<std::size_t>(e)]
                                 : -1;
      if (s >= 0 && static_cast<std::size_t>(s) < sections.connector_sections.size()) {
        const ConnectorSection& section = sections.connector_sections[static_cast<std::size_t>(s)];
        if (section.valid && !has_component(section.available, c)) {
          if (std::find(reported_sections.begin(), reported_sections.end(), s) ==
              reported_sections.end()) {
            reported_sections.push_back(s);
            sink_
                .report(
                    DiagCode::component_not_available, condition.component_loc,
                    fmt::format("component {} is not available for connection type {} "
                                "(available: {})",
                                c, connection_display(section), component_list(section.available)))
                .notes.push_back({section.keyword_loc, "section defined here"});
          }
          continue;
        }
      }
      if (kind == ConditionKind::Motion) {
        in_force.motions.insert(e, c, condition.loc);
        if (!seen) continue;
        SourceLoc previous;
        if (seen->insert(e, c, condition.loc, &previous) || duplicate_reported ||
            previous == condition.loc) {
          continue;
        }
        duplicate_reported = true;
        sink_
            .report(DiagCode::condition_redefined, condition.loc,
                    fmt::format("element {} component {} prescribed twice in {}; the later "
                                "value is used",
                                element_name(model_, e), c, where))
            .notes.push_back({previous, "previously prescribed here"});
      } else if (!prescribed_reported && in_force.motions.contains(e, c)) {
        prescribed_reported = true;
        sink_.report(DiagCode::load_on_prescribed_dof, condition.loc,
                     fmt::format("*CONNECTOR LOAD on element {} component {}, which also has a "
                                 "*CONNECTOR MOTION; the load goes into the reaction",
                                 element_name(model_, e), c));
      }
    }
  }

  Model& model_;
  DiagnosticSink& sink_;
  std::vector<DofMask> active_;
  std::vector<DofMask> following_;  // a load on a node that follows another acts on it

  // A node of a held element that is refused while deformable (check_held_elements): a
  // condition on it is not reported a second time.
  bool on_held_element(std::int32_t node) const {
    const auto& held = model_.structure.node_on_held_element;
    return static_cast<std::size_t>(node) < held.size() && held[static_cast<std::size_t>(node)];
  }
  bool friction_known_ = false, friction_ = false;
};

}  // namespace

void resolve_history(Model& model, DiagnosticSink& sink) { HistoryValidator(model, sink).run(); }

}  // namespace clinch
