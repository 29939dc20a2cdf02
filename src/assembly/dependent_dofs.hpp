// The DOFs that kinematic constraints eliminate (docs/constraints.md "Elimination"): rigid body
// and coupling nodes that follow a reference node, MPCs, *EQUATION, MPC LINK. A dependent DOF
// keeps its equation, so that elements, outputs and the state read it like any other; its value
// is computed from the DOFs it depends on (dependent_motion.hpp), its row of the tangent is the
// identity, and what elements and loads put on it moves to those DOFs.
//
// The list is in dependency order: a DOF comes after every dependent DOF it depends on, so that
// values are computed, and chains of linear maps substituted, in one pass.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "base/small_types.hpp"
#include "src/assembly/dof_map.hpp"

namespace clinch {

struct Model;

struct DependentDof {
  // How the value follows from its first-level terms:
  //   RigidTranslation  u = u_ref,k + ((R_ref − I)·arm)_k   (small displacements: (θ_ref × arm)_k;
  //                     a body anchored at another node reads u_k there: constraint_model.hpp)
  //   Rotation          θ = θ_ref,k                          (NLGEOM: R = R_ref)
  //   Linear            u = Σ c_t u_t                          (*EQUATION)
  //   LinkTranslation   x_k = x_other,k + s·√(L² − Σ_{j≠k} d_j²), d = x − x_other (MPC LINK)
  enum class Map : std::uint8_t { RigidTranslation, Rotation, Linear, LinkTranslation };
  Map map = Map::Linear;
  int equation = -1;
  std::int32_t node = -1;
  std::int32_t reference = -1;  // the followed node (its rotation), or a link's other node
  int axis = 0;                 // 0…2: the component k
  // RigidTranslation: X − X of the node whose u_k it reads; Link: X − X_other initially.
  Vector3 arm = Vector3::Zero();
  // First-level terms: the equations the map reads, in the order dependent_motion.cpp writes
  // their coefficients (Linear: the coefficients, constant).
  std::uint32_t first_term = 0, term_count = 0;
  // The gradient substituted down to independent equations (chains of linear maps).
  std::uint32_t first_resolved = 0, resolved_count = 0;
  std::int32_t source = -1;  // into ConstraintModel::sources
  // Whether the map has second derivatives (NLGEOM): a rigid arm or a link.
  bool curved() const {
    return (map == Map::RigidTranslation && arm != Vector3::Zero()) || map == Map::LinkTranslation;
  }
};

struct DependentDofs {
  std::vector<DependentDof> dofs;         // in dependency order
  std::vector<std::int32_t> of_equation;  // equation → index into dofs, −1 when independent
  std::vector<int> term_equation;         // first-level terms
  std::vector<double> term_coefficient;   // Linear maps only (the others are computed)
  std::vector<int> resolved_equation;     // independent equations of the gradients
  // For each resolved entry, the first-level term it came through and, when that term is a
  // dependent DOF, the position in that DOF's resolved list (else −1): how dependent_motion.cpp
  // substitutes chains without searching.
  std::vector<std::uint32_t> resolved_via_term;
  std::vector<std::int32_t> resolved_via_entry;
  // Nodes whose rotation is the rotation of another (NLGEOM: R_node = R_reference).
  std::vector<std::pair<std::int32_t, std::int32_t>> rotation_followers;
  // The equations Newton solves: every equation but the dependent ones, in their order. Both
  // empty when no DOF is dependent: then the solved numbering is the equation numbering.
  std::vector<int> solved_of_equation;  // −1 for a dependent equation
  std::vector<int> equation_of_solved;

  bool empty() const { return dofs.empty(); }
  bool is_dependent(int equation) const {
    return !of_equation.empty() && of_equation[static_cast<std::size_t>(equation)] >= 0;
  }
  int solved(int equation) const {
    return solved_of_equation.empty() ? equation
                                      : solved_of_equation[static_cast<std::size_t>(equation)];
  }
  int equation(int solved) const {
    return equation_of_solved.empty() ? solved
                                      : equation_of_solved[static_cast<std::size_t>(solved)];
  }
  int solved_count(const DofMap& map) const {
    return map.equations() - static_cast<int>(dofs.size());
  }
  // SparseMatrix::node_block of the solved system: DofMap::uniform_node_block without the
  // dependent DOFs (1 when the nodes keep different numbers of solved DOFs).
  int solved_node_block(const DofMap& map) const;
};

// The dependent DOFs of the model's resolved constraints over the DOF map. Returns false with
// `error` when a chain of maps cannot be ordered (a cycle).
bool build_dependent_dofs(const Model& model, const DofMap& dofs, DependentDofs& out,
                          std::string* error);

// The dependent DOFs a rank holds (equation_layout.hpp), over its local equations `local`:
// `local_of` takes the model's equations to local ones (−1 where the rank holds none). The
// rank's equations close over the maps: a DOF it holds finds every equation its map reads.
DependentDofs local_dependents(const DependentDofs& whole, std::span<const int> local_of,
                               const DofMap& local);

}  // namespace clinch
