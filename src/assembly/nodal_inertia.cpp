#include "src/assembly/nodal_inertia.hpp"

#include <array>
#include <map>

#include "base/fold_name.hpp"
#include "src/model/inertia_elements.hpp"

namespace clinch {
namespace {

// The value of field `i` of the section's first data line (0 when blank or absent).
double row_value(const ElementSection& section, std::size_t i) {
  if (section.rows.empty() || i >= section.rows[0].values.size()) return 0.0;
  return section.rows[0].values[i];
}

bool anisotropic(const ElementSection& section) {
  for (const KeptParameter& p : section.parameters) {
    if (p.name == "TYPE") return fold_name(p.value) == "ANISOTROPIC";
  }
  return false;
}

// *MASS: m in each direction, or m1, m2, m3 with TYPE=ANISOTROPIC (keywords.md).
Vector3 section_mass(const ElementSection& section) {
  return anisotropic(section)
             ? Vector3(row_value(section, 0), row_value(section, 1), row_value(section, 2))
             : Vector3::Constant(row_value(section, 0));
}

// I11, I22, I33, I12, I13, I23 (the order of *ROTARY INERTIA) as a symmetric tensor.
Matrix3 inertia_tensor(const std::array<double, 6>& i) {
  Matrix3 j;
  j << i[0], i[3], i[4], i[3], i[1], i[5], i[4], i[5], i[2];
  return j;
}

}  // namespace

std::vector<PointMass> point_masses(const Model& model) {
  const std::vector<std::int32_t> node_of = inertia_element_nodes(model);
  std::vector<PointMass> masses;
  for (const ElementSection& section : model.structure.sections) {
    if (section.kind != ElementSection::Kind::Mass) continue;
    for (std::int32_t e : section.elements) {
      const std::int32_t node = node_of[static_cast<std::size_t>(e)];
      if (node >= 0) masses.push_back({e, node, section_mass(section)});
    }
  }
  for (const ElementMassPoint& p : model.constraints.element_masses) {
    masses.push_back({p.element, p.node, Vector3::Constant(p.mass)});
  }
  return masses;
}

std::vector<NodeInertia> nodal_inertia(const Model& model, const DofMap& dofs) {
  const std::vector<std::int32_t> node_of = inertia_element_nodes(model);
  std::map<std::int32_t, NodeInertia> by_node;
  for (const ElementSection& section : model.structure.sections) {
    const bool mass = section.kind == ElementSection::Kind::Mass;
    if (!mass && section.kind != ElementSection::Kind::RotaryInertia) continue;
    // keywords.md: *MASS gives m (or m1, m2, m3 with TYPE=ANISOTROPIC); *ROTARY INERTIA gives
    // I11, I22, I33, I12, I13, I23.
    Vector3 m = Vector3::Zero();
    Matrix3 j = Matrix3::Zero();
    if (mass) {
      m = section_mass(section);
    } else {
      j = inertia_tensor({row_value(section, 0), row_value(section, 1), row_value(section, 2),
                          row_value(section, 3), row_value(section, 4), row_value(section, 5)});
    }
    for (std::int32_t e : section.elements) {
      const std::int32_t node = node_of[static_cast<std::size_t>(e)];
      if (node < 0 || dofs.active(node) == 0) continue;
      NodeInertia& n = by_node[node];
      n.node = node;
      n.mass += m;
      n.rotary += j;
    }
  }
  // The mass of rigid bodies' elements from their density: at the node added at each one's centre,
  // its inertia about that centre on the body's reference node (ElementMassPoint).
  for (const ElementMassPoint& p : model.constraints.element_masses) {
    if (dofs.active(p.node) != 0) {
      by_node[p.node].node = p.node;
      by_node[p.node].mass += Vector3::Constant(p.mass);
    }
    if (dofs.active(p.reference) != 0) {
      by_node[p.reference].node = p.reference;
      by_node[p.reference].rotary += inertia_tensor(p.rotary);
    }
  }
  std::vector<NodeInertia> inertia;
  inertia.reserve(by_node.size());
  for (auto& [node, n] : by_node) {
    for (int k = 0; k < 3; ++k) {
      n.translation[static_cast<std::size_t>(k)] = dofs.equation(node, 1 + k);
      n.rotation[static_cast<std::size_t>(k)] = dofs.equation(node, 4 + k);
    }
    inertia.push_back(n);
  }
  return inertia;
}

}  // namespace clinch
