#include "src/assembly/equation_layout.hpp"

#include <algorithm>

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
  if (plan.has_multipliers) return "connector multipliers";
  if (plan.dynamic || !plan.inertia.empty()) return "a dynamic or *FREQUENCY step";
  if (plan.stabilized) return "a STABILIZE step";
  if (plan.energies) return "the whole-model energies (*ENERGY OUTPUT)";
  return {};
}

void localize_equations(AnalysisPlan& plan, int rank, int ranks) {
  const DofMap& global = plan.dofs;
  EquationLayout& layout = plan.layout;
  layout.local = true;
  layout.global_count = global.equations();
  layout.global_node_equations = global.node_equations();
  layout.node_block = global.uniform_node_block();
  // A node belongs to the rank whose share of the rows holds its first equation, so that no node
  // is split (with a uniform node block the shares end on node boundaries already).
  const ItemRange rows = owned_rows(layout.global_count, layout.node_block, rank, ranks);
  const auto nodes = static_cast<std::int32_t>(global.nodes());
  std::vector<DofMask> active(global.nodes(), 0);
  std::vector<std::int32_t> order;  // owned nodes, then ghosts, each in node order
  std::vector<char> ghost(global.nodes(), 0);
  const auto first_equation = [&](std::int32_t node) {
    for (int dof = 1; dof <= 6; ++dof) {
      if (const int eq = global.equation(node, dof); eq >= 0) return eq;
    }
    return -1;
  };
  for (std::int32_t node = 0; node < nodes; ++node) {
    const int eq = first_equation(node);
    if (eq < 0 || static_cast<std::size_t>(eq) < rows.begin ||
        static_cast<std::size_t>(eq) >= rows.end) {
      continue;
    }
    order.push_back(node);
    active[static_cast<std::size_t>(node)] = global.active(node);
  }
  const auto touch = [&](std::int32_t node) {
    if (node >= 0 && active[static_cast<std::size_t>(node)] == 0 && global.active(node) != 0) {
      ghost[static_cast<std::size_t>(node)] = 1;
    }
  };
  for (const ConnectorRecord& r : plan.connectors) {
    for (const std::int32_t node : r.nodes) touch(node);
  }
  for (const SpringRecord& s : plan.springs) {
    for (const std::int32_t node : s.nodes) touch(node);
  }
  // The first owned equation; for a rank that owns no node, where the next rank's rows begin,
  // so that the ranks' first rows ascend and a row's owner is the last rank starting at or
  // before it.
  layout.first_owned = layout.global_count;
  for (std::int32_t node = 0; node < nodes; ++node) {
    const int eq = first_equation(node);
    if (eq >= 0 && static_cast<std::size_t>(eq) >= rows.begin) {
      layout.first_owned = eq;
      break;
    }
  }
  for (std::int32_t node = 0; node < nodes; ++node) {
    if (!ghost[static_cast<std::size_t>(node)]) continue;
    order.push_back(node);
    active[static_cast<std::size_t>(node)] = global.active(node);
  }
  DofMap local(active, order);
  layout.owned = 0;
  layout.ghost_global.clear();
  // The records' equations, global → local (a map for this pass only).
  std::vector<int> local_of_global(static_cast<std::size_t>(layout.global_count), -1);
  for (int eq = 0; eq < local.equations(); ++eq) {
    const std::int32_t node = local.node_of(eq);
    const int global_eq = global.equation(node, local.dof_of(eq));
    local_of_global[static_cast<std::size_t>(global_eq)] = eq;
    if (ghost[static_cast<std::size_t>(node)]) {
      layout.ghost_global.push_back(global_eq);
    } else {
      ++layout.owned;
    }
  }
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
