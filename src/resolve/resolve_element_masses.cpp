// The mass of a rigid body's elements from their density and volume
// (docs/dynamics.md "Inertia on constrained nodes"): each element's mass goes to a node of its
// own at its centre of mass, pinned to the body's reference node like a PIN NSET node, and its
// inertia about that centre to the reference node (ElementMassPoint). The added node is the one
// point of the body where a point mass is exact (mass, first and second moments), so that the
// inertia, the gravity and the time integration treat it as a MASS element on a body's node.
#include <algorithm>
#include <map>

#include "src/model/element_mass.hpp"
#include "src/model/model.hpp"
#include "src/resolve/resolve.hpp"

namespace clinch {

void resolve_rigid_body_element_masses(Model& model) {
  const std::vector<ElementMass> masses = rigid_body_element_masses(model);
  if (masses.empty()) return;
  ConstraintModel& constraints = model.constraints;
  // Labels past every label of the deck: nothing in it names the added nodes.
  std::int32_t label = 0;
  for (const Node& node : model.nodes) label = std::max(label, node.label);
  const DofMask translations = model.dimension == 2 ? DofMask{0x03} : DofMask{0x07};
  std::map<std::int32_t, std::int32_t> source_of_body;
  for (const ElementMass& m : masses) {
    auto [found, added] =
        source_of_body.try_emplace(m.body, static_cast<std::int32_t>(constraints.sources.size()));
    if (added) {
      constraints.sources.push_back(
          {"*RIGID BODY", constraints.rigid_bodies[static_cast<std::size_t>(m.body)].keyword_loc});
    }
    const std::int32_t source = found->second;
    Node node;
    node.label = ++label;
    node.instance = model.nodes[static_cast<std::size_t>(m.reference)].instance;  // for messages
    node.x = {m.centre[0], m.centre[1], m.centre[2]};
    const auto index = static_cast<std::int32_t>(model.nodes.size());
    model.nodes.push_back(node);
    constraints.followers.push_back({index, m.reference, translations, true, source});
    ElementMassPoint point;
    point.element = m.element;
    point.node = index;
    point.reference = m.reference;
    point.mass = m.mass;
    point.rotary = {m.rotary(0, 0), m.rotary(1, 1), m.rotary(2, 2),
                    m.rotary(0, 1), m.rotary(0, 2), m.rotary(1, 2)};
    constraints.element_masses.push_back(point);
  }
}

}  // namespace clinch
