#include "src/model/active_dofs.hpp"

#include <algorithm>
#include <array>

#include "src/model/connection_types.hpp"
#include "src/model/inertia_elements.hpp"
#include "src/model/model.hpp"

namespace clinch {
namespace {

constexpr DofMask kAll3D = 0b111111;
constexpr DofMask kTranslations3D = 0b000111;
constexpr DofMask kAll2D = 0b100011;  // u1, u2, ur3
constexpr DofMask kTranslations2D = 0b000011;

DofMask dof_bit(int dof) {
  return dof >= 1 && dof <= 6 ? static_cast<DofMask>(1u << (dof - 1)) : 0;
}

// connection-types.md §1.1: a connector activates the rotations of a node when one of its types
// allows an orientation at that end (table §2.1, ori a / ori b) or uses the node's rotation,
// except AXIAL, LINK and JOIN, which never do (JOIN only *uses* rotations that something else
// activated). So CARTESIAN, SLOT, SLIDE-PLANE and RADIAL-THRUST (orientation ignored at b)
// activate the rotations of node a only. Elements without a valid section are taken to use every
// DOF, so that the errors about the section are not followed by warnings about DOFs.
DofMask section_dofs(const ConnectorSection& section, int slot) {
  if (!section.valid || section.type_names.empty()) return kAll3D;
  for (const std::string& type : section.type_names) {
    if (type == "AXIAL" || type == "LINK" || type == "JOIN") continue;
    const ConnectionTypeInfo* info = find_connection_type(type);
    if (!info) return kAll3D;
    const OrientationUse use = slot == 0 ? info->orientation_a : info->orientation_b;
    if (use != OrientationUse::Ignored || info->kind != ConnectionKind::Translational) {
      return kAll3D;
    }
  }
  return kTranslations3D;
}

// The DOFs of every connector section at each end, looked up once per section: a deck has few
// sections and many elements.
class ConnectorDofs {
 public:
  explicit ConnectorDofs(const Model& model) {
    for (const ConnectorSection& section : model.sections.connector_sections) {
      by_section_.push_back({section_dofs(section, 0), section_dofs(section, 1)});
    }
  }
  DofMask operator()(const Model& model, std::int32_t element, int slot) const {
    const auto& sections = model.sections;
    if (element < 0 || static_cast<std::size_t>(element) >= sections.section_of_element.size()) {
      return kAll3D;
    }
    const std::int32_t s = sections.section_of_element[static_cast<std::size_t>(element)];
    if (s < 0 || static_cast<std::size_t>(s) >= by_section_.size()) return kAll3D;
    return by_section_[static_cast<std::size_t>(s)][static_cast<std::size_t>(slot)];
  }

 private:
  std::vector<std::array<DofMask, 2>> by_section_;
};

// keywords.md §7: SPRING1/SPRING2 (and DASHPOT1/DASHPOT2) use the DOFs of their DOF line (1–6
// while the data are unknown or invalid).
DofMask spring_dofs(const Model& model, std::int32_t element, int slot, bool two_d) {
  const auto& sections = model.sections;
  const DofMask fallback = two_d ? kAll2D : kAll3D;
  if (element < 0 || static_cast<std::size_t>(element) >= sections.spring_of_element.size()) {
    return fallback;
  }
  const std::int32_t s = sections.spring_of_element[static_cast<std::size_t>(element)];
  if (s < 0 || static_cast<std::size_t>(s) >= sections.springs.size()) return fallback;
  const SpringProperty& spring = sections.springs[static_cast<std::size_t>(s)];
  if (!spring.valid) return fallback;
  const int dof = spring.dofs[slot == 0 ? 0 : 1];
  const DofMask mask = dof_bit(dof);
  return mask ? mask : fallback;
}

// DOFs element `element` (global index) uses at its node in `slot` (0 or 1).
DofMask element_dofs(const Model& model, const ConnectorDofs& connector_dofs,
                     std::int32_t element, int slot) {
  if (element < 0 || static_cast<std::size_t>(element) >= model.elements.size()) return 0;
  const Element& e = model.elements[static_cast<std::size_t>(element)];
  const bool two_d = model.dimension == 2;
  switch (spring_form(e.type)) {
    case ElementType::Conn3D2:
      return two_d ? (connector_dofs(model, element, slot) == kAll3D ? kAll2D : kTranslations2D)
                   : connector_dofs(model, element, slot);
    case ElementType::Conn2D2:
      return connector_dofs(model, element, slot) == kAll3D ? kAll2D : kTranslations2D;
    case ElementType::SpringA:
      return two_d ? kTranslations2D : kTranslations3D;
    case ElementType::Spring1:
      return slot == 0 ? spring_dofs(model, element, 0, two_d) : 0;
    case ElementType::Spring2:
      return spring_dofs(model, element, slot, two_d);
    default: return 0;  // spring_form gives no dashpot type
  }
  return 0;
}

// DOFs that *CLOAD and *BOUNDARY lines name at each node (a load or a condition on a rigid
// body's node acts on the body), every DOF of the nodes that nodal output names (a rigid
// body's node reports how it moves), and the translations of a MASS's node and the rotations of a
// ROTARYI's (inertia on a rigid body's node is the body's inertia).
std::vector<DofMask> named_dofs(const Model& model) {
  std::vector<DofMask> named(model.nodes.size(), 0);
  auto name = [&named](const std::vector<std::int32_t>& nodes, DofMask mask) {
    for (std::int32_t node : nodes) {
      if (node >= 0 && static_cast<std::size_t>(node) < named.size()) {
        named[static_cast<std::size_t>(node)] |= mask;
      }
    }
  };
  const bool two_d = model.dimension == 2;
  const std::vector<std::int32_t> inertia_node = inertia_element_nodes(model);
  for (const ElementSection& section : model.structure.sections) {
    const bool mass = section.kind == ElementSection::Kind::Mass;
    if (!mass && section.kind != ElementSection::Kind::RotaryInertia) continue;
    const DofMask mask = mass ? (two_d ? kTranslations2D : kTranslations3D)
                              : (two_d ? kAll2D & ~kTranslations2D : kAll3D & ~kTranslations3D);
    for (const std::int32_t e : section.elements) {
      const std::int32_t node = inertia_node[static_cast<std::size_t>(e)];
      if (node >= 0) named[static_cast<std::size_t>(node)] |= mask;
    }
  }
  // The mass of rigid bodies' elements from their density: the translations of the node at each
  // one's centre, the rotations of the reference node that carries its inertia (ElementMassPoint).
  for (const ElementMassPoint& p : model.constraints.element_masses) {
    named[static_cast<std::size_t>(p.node)] |= two_d ? kTranslations2D : kTranslations3D;
    named[static_cast<std::size_t>(p.reference)] |=
        two_d ? kAll2D & ~kTranslations2D : kAll3D & ~kTranslations3D;
  }
  for (const BoundaryCondition& bc : model.history.model_boundaries) name(bc.resolved, bc.dofs);
  for (const Step& step : model.history.steps) {
    for (const BoundaryCondition& bc : step.boundaries) name(bc.resolved, bc.dofs);
    for (const ConcentratedLoad& load : step.loads) name(load.resolved, dof_bit(load.dof));
    for (const OutputRequest& output : step.outputs) {
      for (const NodeOutputRequest& request : output.nodes) name(request.resolved, kAll3D);
    }
    for (const PrintRequest& print : step.prints) {
      if (print.node) name(print.resolved, kAll3D);
    }
  }
  return named;
}

bool set_dofs(std::vector<DofMask>& active, std::int32_t node, DofMask mask) {
  if (node < 0 || static_cast<std::size_t>(node) >= active.size()) return false;
  DofMask& m = active[static_cast<std::size_t>(node)];
  if ((m | mask) == m) return false;
  m |= mask;
  return true;
}

// docs/constraints.md "Which DOFs take part": a node that follows another eliminates the DOFs
// that elements, loads and nodal output use there, and the node it follows then needs the DOFs those depend
// on (its rotations too, for a rigid arm); an equation or a link takes part as soon as one of
// its DOFs does. Repeated until nothing changes, for chains of constraints.
void add_constraint_dofs(const Model& model, std::vector<DofMask>& active) {
  const ConstraintModel& c = model.constraints;
  if (c.followers.empty() && c.equations.empty() && c.links.empty()) return;
  const bool two_d = model.dimension == 2;
  const DofMask translations = two_d ? kTranslations2D : kTranslations3D;
  const DofMask rotations = two_d ? kAll2D & ~kTranslations2D : kAll3D & ~kTranslations3D;
  const std::vector<DofMask> named = named_dofs(model);
  for (bool changed = true; changed;) {
    changed = false;
    for (const NodeFollower& f : c.followers) {
      const auto node = static_cast<std::size_t>(f.node);
      const DofMask dependent = (active[node] | named[node]) & f.dofs;
      if (!dependent) continue;
      changed |= set_dofs(active, f.node, dependent);
      const std::int32_t source = f.translation_source();
      changed |= set_dofs(active, source, dependent);
      const Vec3& x = model.nodes[node].x;
      const Vec3& x_source = model.nodes[static_cast<std::size_t>(source)].x;
      if (f.rigid_arm && (dependent & translations) && x != x_source) {
        changed |= set_dofs(active, f.reference, rotations);
      }
    }
    for (const LinearConstraint& equation : c.equations) {
      const bool takes_part = std::any_of(
          equation.terms.begin(), equation.terms.end(), [&](const LinearTerm& t) {
            return active[static_cast<std::size_t>(t.node)] & dof_bit(t.dof);
          });
      if (!takes_part) continue;
      for (const LinearTerm& t : equation.terms) changed |= set_dofs(active, t.node, dof_bit(t.dof));
    }
    for (const DistanceLink& link : c.links) {
      if (!((active[static_cast<std::size_t>(link.node)] |
             active[static_cast<std::size_t>(link.other)]) &
            translations)) {
        continue;
      }
      changed |= set_dofs(active, link.node, translations);
      changed |= set_dofs(active, link.other, translations);
    }
  }
}

}  // namespace

std::vector<DofMask> following_dofs(const Model& model) {
  std::vector<DofMask> following(model.nodes.size(), 0);
  for (const NodeFollower& f : model.constraints.followers) {
    following[static_cast<std::size_t>(f.node)] |= f.dofs;
  }
  return following;
}

std::vector<DofMask> active_dofs(const Model& model) {
  const ConnectorDofs connector_dofs(model);
  std::vector<DofMask> active(model.nodes.size(), 0);
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const Element& element = model.elements[e];
    for (int slot = 0; slot < 2; ++slot) {
      const std::int32_t node = element.nodes[static_cast<std::size_t>(slot)];
      if (node < 0 || static_cast<std::size_t>(node) >= active.size()) continue;  // ground
      active[static_cast<std::size_t>(node)] |=
          element_dofs(model, connector_dofs, static_cast<std::int32_t>(e), slot);
    }
  }
  add_constraint_dofs(model, active);
  return active;
}

}  // namespace clinch
