// The inertia of MASS and ROTARYI elements, gathered per node (docs/dynamics.md): a point mass per
// translational direction (*MASS, isotropic or ANISOTROPIC in the global axes) and a rotary
// inertia tensor (*ROTARY INERTIA: I11, I22, I33, I12, I13, I23 in the global axes). Elements on
// the same node add up. The mass matrix is lumped: block diagonal, node by node.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "src/assembly/dof_map.hpp"
#include "base/small_types.hpp"
#include "src/model/model.hpp"

namespace clinch {

struct NodeInertia {
  std::int32_t node = 0;
  std::array<int, 3> translation{-1, -1, -1};  // equations of u1–u3 (−1: not active)
  std::array<int, 3> rotation{-1, -1, -1};     // equations of ur1–ur3
  Vector3 mass = Vector3::Zero();              // per translational direction
  Matrix3 rotary = Matrix3::Zero();            // symmetric
};

// A MASS element with a node: its mass per translational direction (gravity loads it).
struct PointMass {
  std::int32_t element = 0, node = 0;
  Vector3 mass = Vector3::Zero();
};
std::vector<PointMass> point_masses(const Model& model);

// The nodes that carry inertia and have active DOFs, in node order. A MASS or ROTARYI element
// whose node has no active DOF carries no equation of motion and is left out.
std::vector<NodeInertia> nodal_inertia(const Model& model, const DofMap& dofs);

}  // namespace clinch
