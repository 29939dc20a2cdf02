#include "src/assembly/equation_layout.hpp"

#include <algorithm>
#include <bit>

#include "src/assembly/analysis_plan.hpp"
#include "src/parallel/communicator.hpp"

namespace clinch {

int EquationLayout::local_of(int global_equation) const {
  if (!local) return global_equation;
  if (global_equation >= first_owned && global_equation < first_owned + owned) {
    return global_equation - first_owned;
  }
  const auto at = std::lower_bound(ghost_global.begin(), ghost_global.end(), global_equation);
  if (at == ghost_global.end() || *at != global_equation) return -1;
  return owned + static_cast<int>(at - ghost_global.begin());
}

std::string whole_vectors_need(const AnalysisPlan& plan) {
  if (!plan.dependents.empty()) {
    return "the maps of kinematic constraints read equations of any rank";
  }
  if (plan.dynamic || !plan.inertia.empty()) return "a dynamic or *FREQUENCY step";
  if (plan.stabilized) return "a STABILIZE step";
  if (plan.energies) return "the whole-model energies (*ENERGY OUTPUT)";
  return {};
}

void localize_equations(AnalysisPlan& plan, int rank, int ranks) {
  // The model's numbering: the node equations node by node, then the multipliers in element
  // order, each rank's share of the connectors one range of them.
  const DofMap& global = plan.dofs;
  EquationLayout& layout = plan.layout;
  const int nodal = global.node_equations();
  layout.local = true;
  layout.global_count = global.equations();
  layout.global_node_equations = nodal;
  layout.node_block = global.uniform_node_block();
  const auto first_equation = [&](std::int32_t node) {
    for (int dof = 1; dof <= 6; ++dof) {
      if (const int eq = global.equation(node, dof); eq >= 0) return eq;
    }
    return -1;
  };
  // A node belongs to the rank whose share of the node equations holds its first equation, so
  // that no node is split (with a uniform node block the shares end on node boundaries already).
  // Per rank: its node equations (consecutive in the model's numbering) and its multipliers.
  const auto count = static_cast<std::size_t>(ranks);
  std::vector<int> node_equations(count, 0), first_node_equation(count, nodal);
  std::vector<int> multipliers(count, 0), first_multiplier(count, nodal);
  const auto nodes = static_cast<std::int32_t>(global.nodes());
  std::vector<char> held(global.nodes(), 0);  // 1: owned here, 2: a ghost here
  std::vector<std::int32_t> owned_nodes, ghost_nodes;
  std::size_t owner = 0;
  for (std::int32_t node = 0; node < nodes; ++node) {
    const int eq = first_equation(node);
    if (eq < 0) continue;
    while (owned_rows(nodal, layout.node_block, static_cast<int>(owner), ranks).end <=
           static_cast<std::size_t>(eq)) {
      ++owner;
    }
    if (node_equations[owner] == 0) first_node_equation[owner] = eq;
    node_equations[owner] += std::popcount(static_cast<unsigned>(global.active(node)));
    if (owner == static_cast<std::size_t>(rank)) {
      owned_nodes.push_back(node);
      held[static_cast<std::size_t>(node)] = 1;
    }
  }
  for (std::size_t q = 0, next = static_cast<std::size_t>(nodal); q < count; ++q) {
    multipliers[q] = plan.share_multipliers.empty() ? 0 : plan.share_multipliers[q];
    first_multiplier[q] = static_cast<int>(next);
    next += static_cast<std::size_t>(multipliers[q]);
  }
  // The solver's numbering: rank q owns [start[q], start[q + 1]), its node equations then its
  // multipliers, each in the model's order.
  std::vector<int> start(count + 1, 0);
  for (std::size_t q = 0; q < count; ++q) {
    start[q + 1] = start[q] + node_equations[q] + multipliers[q];
  }
  const auto solver_number = [&](int eq) {
    if (eq >= nodal) {
      const std::size_t q = static_cast<std::size_t>(
          std::upper_bound(first_multiplier.begin(), first_multiplier.end(), eq) -
          first_multiplier.begin() - 1);
      return start[q] + node_equations[q] + (eq - first_multiplier[q]);
    }
    std::size_t q = 0;
    while (q + 1 < count &&
           (node_equations[q] == 0 || first_node_equation[q] + node_equations[q] <= eq)) {
      ++q;
    }
    return start[q] + (eq - first_node_equation[q]);
  };
  const auto me = static_cast<std::size_t>(rank);
  layout.first_owned = start[me];
  layout.owned = start[me + 1] - start[me];
  // The ghosts: the other ranks' nodes this rank's elements touch.
  const auto touch = [&](std::int32_t node) {
    if (node >= 0 && held[static_cast<std::size_t>(node)] == 0 && global.active(node) != 0) {
      held[static_cast<std::size_t>(node)] = 2;
    }
  };
  for (const ConnectorRecord& r : plan.connectors) {
    for (const std::int32_t node : r.nodes) touch(node);
  }
  for (const SpringRecord& s : plan.springs) {
    for (const std::int32_t node : s.nodes) touch(node);
  }
  std::vector<DofMask> active(global.nodes(), 0);
  for (std::int32_t node = 0; node < nodes; ++node) {
    if (held[static_cast<std::size_t>(node)] == 0) continue;
    active[static_cast<std::size_t>(node)] = global.active(node);
    if (held[static_cast<std::size_t>(node)] == 2) ghost_nodes.push_back(node);
  }
  // Local numbering: the owned nodes, this rank's multipliers, then the ghost nodes.
  DofMap local(std::move(active), owned_nodes);
  std::vector<int> local_of_global(static_cast<std::size_t>(layout.global_count), -1);
  for (int k = 0; k < multipliers[me]; ++k) {
    const int eq = first_multiplier[me] + k;
    local_of_global[static_cast<std::size_t>(eq)] =
        local.add_multiplier(global.field(eq) == EquationField::RotationalMultiplier);
  }
  local.add_nodes(ghost_nodes);
  layout.ghost_global.clear();
  for (int eq = 0; eq < local.equations(); ++eq) {
    const std::int32_t node = local.node_of(eq);
    if (node < 0) continue;  // a multiplier
    const int global_eq = global.equation(node, local.dof_of(eq));
    local_of_global[static_cast<std::size_t>(global_eq)] = eq;
    if (held[static_cast<std::size_t>(node)] == 2) {
      layout.ghost_global.push_back(solver_number(global_eq));
    }
  }
  // The records' equations, in the model's numbering → local.
  const auto renumber = [&](LocalEquations& l) {
    for (int k = 0; k < l.count; ++k) {
      int& eq = l.equation[static_cast<std::size_t>(k)];
      eq = local_of_global[static_cast<std::size_t>(eq)];
    }
  };
  for (ConnectorRecord& r : plan.connectors) renumber(r.local);
  for (SpringRecord& s : plan.springs) renumber(s.local);
  plan.dofs = std::move(local);
}

}  // namespace clinch
