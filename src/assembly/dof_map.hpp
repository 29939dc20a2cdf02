// Equation numbers of the analysis (ARCHITECTURE.md principle 9): only the DOFs some element uses
// get an equation (a translational-only model has 3 per node, a CONN2D2 model u1, u2, ur3), node
// by node; Lagrange multipliers of connector constraints follow the nodal equations.
#pragma once

#include <bit>
#include <cstdint>
#include <vector>

#include "src/model/active_dofs.hpp"

namespace clinch {

enum class EquationField : std::uint8_t {
  Translation,
  Rotation,
  TranslationalMultiplier,
  RotationalMultiplier
};

class DofMap {
 public:
  DofMap() = default;
  explicit DofMap(std::vector<DofMask> active);
  // The equations of the nodes in `order` only, numbered in that order (a rank's local equations,
  // equation_layout.hpp); every other node has none until add_nodes numbers it.
  DofMap(std::vector<DofMask> active, const std::vector<std::int32_t>& order);
  // Numbers the nodes of `order` next, after any multiplier (a rank's ghost nodes).
  void add_nodes(const std::vector<std::int32_t>& order);

  // Equation of DOF `dof` (1…6) of global node `node`, or −1 when the DOF is not active.
  int equation(std::int32_t node, int dof) const {
    if (node < 0) return -1;
    const DofMask mask = active_[static_cast<std::size_t>(node)];
    const DofMask bit = static_cast<DofMask>(1u << (dof - 1));
    if (!(mask & bit)) return -1;
    return first_[static_cast<std::size_t>(node)] +
           std::popcount(static_cast<unsigned>(mask & (bit - 1)));
  }
  DofMask active(std::int32_t node) const { return active_[static_cast<std::size_t>(node)]; }
  // How many equations are nodal: the first ones, but in a rank's local numbering, whose ghost
  // nodes follow its multipliers (equation_layout.hpp).
  int node_equations() const { return node_equations_; }
  int equations() const { return static_cast<int>(field_.size()); }
  // Appends a multiplier equation and returns its number.
  int add_multiplier(bool rotational);
  EquationField field(int equation) const { return field_[static_cast<std::size_t>(equation)]; }
  // Node and DOF of a nodal equation (for messages: the singular pivot names them).
  std::int32_t node_of(int equation) const { return node_of_[static_cast<std::size_t>(equation)]; }
  int dof_of(int equation) const;
  std::size_t nodes() const { return active_.size(); }
  // The number of equations of each node when every node that has equations has the same DOFs
  // and there are no multipliers, else 1 (SparseMatrix::node_block).
  int uniform_node_block() const;

 private:
  void number(std::int32_t node);  // the next equations are the active DOFs of `node`
  std::vector<DofMask> active_;
  std::vector<int> first_;
  std::vector<std::int32_t> node_of_;
  std::vector<EquationField> field_;
  int node_equations_ = 0;
};

}  // namespace clinch
