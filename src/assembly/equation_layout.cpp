#include "src/assembly/equation_layout.hpp"

#include <algorithm>
#include <bit>
#include <numeric>
#include <span>

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

namespace {

// The nodes a kinematic constraint ties together: each dependent DOF's node, the nodes of the
// equations its map reads and its reference node, joined (union-find over nodes).
class ConstraintGroups {
 public:
  ConstraintGroups(const DofMap& dofs, const DependentDofs& dependents) : parent_(dofs.nodes()) {
    std::iota(parent_.begin(), parent_.end(), 0);
    for (const DependentDof& d : dependents.dofs) {
      for (std::uint32_t t = d.first_term; t < d.first_term + d.term_count; ++t) {
        if (const int eq = dependents.term_equation[t]; eq >= 0) join(d.node, dofs.node_of(eq));
      }
      if (d.reference >= 0) join(d.node, d.reference);
    }
  }
  std::int32_t root(std::int32_t node) {
    while (parent_[static_cast<std::size_t>(node)] != node) {
      std::int32_t& up = parent_[static_cast<std::size_t>(node)];
      up = parent_[static_cast<std::size_t>(up)];
      node = up;
    }
    return node;
  }

 private:
  void join(std::int32_t a, std::int32_t b) {
    a = root(a);
    b = root(b);
    if (a != b) parent_[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  }
  std::vector<std::int32_t> parent_;
};

// The rank that owns each node (−1 for a node without equations): the rank whose share of the
// node equations holds its first equation, so that no node is split (with a uniform node block
// the shares end on node boundaries already); the nodes a kinematic constraint ties together
// all go to the owner of the first of them, so that each rigid body, coupling or chain of MPCs
// and equations lies on one rank with its reference node (docs/parallel.md).
std::vector<int> node_owners(const DofMap& global, const DependentDofs& dependents, int node_block,
                             int ranks) {
  const int nodal = global.node_equations();
  std::vector<int> owner(global.nodes(), -1);
  int rank = 0;
  for (std::size_t node = 0; node < global.nodes(); ++node) {
    const auto n = static_cast<std::int32_t>(node);
    if (global.active(n) == 0) continue;
    const int first = global.equation(n, std::countr_zero(global.active(n)) + 1);
    while (owned_rows(nodal, node_block, rank, ranks).end <= static_cast<std::size_t>(first)) {
      ++rank;
    }
    owner[node] = rank;
  }
  if (dependents.empty()) return owner;
  ConstraintGroups groups(global, dependents);
  // A root is the group's first node: its owner is set before any other member is visited.
  for (std::size_t node = 0; node < global.nodes(); ++node) {
    const auto root = static_cast<std::size_t>(groups.root(static_cast<std::int32_t>(node)));
    if (root != node && owner[node] >= 0) {
      if (owner[root] < 0) owner[root] = owner[node];
      owner[node] = owner[root];
    }
  }
  return owner;
}

}  // namespace

void localize_equations(AnalysisPlan& plan, int rank, int ranks) {
  // The model's numbering: the node equations node by node, then the multipliers in element
  // order, each rank's share of the connectors one range of them.
  const DofMap& global = plan.dofs;
  const DependentDofs& dependents = plan.dependents;
  EquationLayout& layout = plan.layout;
  EquationLayout& solved = plan.solved_layout;
  const int nodal = global.node_equations();
  const int node_block = global.uniform_node_block();
  const std::vector<int> owner = node_owners(global, dependents, node_block, ranks);
  const auto count = static_cast<std::size_t>(ranks);
  const auto me = static_cast<std::size_t>(rank);
  // Per rank: its node equations, how many of them are dependent, its multipliers.
  std::vector<int> node_equations(count, 0), dependent(count, 0), multipliers(count, 0);
  const auto nodes = static_cast<std::int32_t>(global.nodes());
  const auto dependent_dofs_of = [&](std::int32_t node) {
    int k = 0;
    for (int dof = 1; dof <= 6; ++dof) {
      const int eq = global.equation(node, dof);
      k += eq >= 0 && dependents.is_dependent(eq) ? 1 : 0;
    }
    return k;
  };
  for (std::int32_t node = 0; node < nodes; ++node) {
    const int q = owner[static_cast<std::size_t>(node)];
    if (q < 0) continue;
    node_equations[static_cast<std::size_t>(q)] +=
        std::popcount(static_cast<unsigned>(global.active(node)));
    dependent[static_cast<std::size_t>(q)] += dependent_dofs_of(node);
  }
  std::vector<int> first_multiplier(count, nodal);
  for (std::size_t q = 0, next = static_cast<std::size_t>(nodal); q < count; ++q) {
    multipliers[q] = plan.share_multipliers.empty() ? 0 : plan.share_multipliers[q];
    first_multiplier[q] = static_cast<int>(next);
    next += static_cast<std::size_t>(multipliers[q]);
  }
  // The solver's numbering: rank q owns [start[q], start[q + 1]), its nodes' equations in node
  // order, then its multipliers; Newton's unknowns (`solved`) the same without the dependent
  // equations.
  std::vector<int> start(count + 1, 0), solved_start(count + 1, 0);
  for (std::size_t q = 0; q < count; ++q) {
    start[q + 1] = start[q] + node_equations[q] + multipliers[q];
    solved_start[q + 1] = solved_start[q] + node_equations[q] - dependent[q] + multipliers[q];
  }
  // Each node's first equation and first unknown in that numbering.
  std::vector<int> first_global(global.nodes(), -1), first_solved(global.nodes(), -1);
  {
    std::vector<int> placed(count, 0), solved_placed(count, 0);
    for (std::int32_t node = 0; node < nodes; ++node) {
      const int q = owner[static_cast<std::size_t>(node)];
      if (q < 0) continue;
      const auto qs = static_cast<std::size_t>(q);
      first_global[static_cast<std::size_t>(node)] = start[qs] + placed[qs];
      first_solved[static_cast<std::size_t>(node)] = solved_start[qs] + solved_placed[qs];
      const int equations = std::popcount(static_cast<unsigned>(global.active(node)));
      placed[qs] += equations;
      solved_placed[qs] += equations - dependent_dofs_of(node);
    }
  }
  // The nodes this rank holds: its own, then as ghosts the others its elements touch and those
  // whose equations the maps of the dependent DOFs it holds read.
  std::vector<char> held(global.nodes(), 0);  // 1: owned here, 2: a ghost here
  std::vector<std::int32_t> owned_nodes, ghost_nodes;
  for (std::int32_t node = 0; node < nodes; ++node) {
    if (owner[static_cast<std::size_t>(node)] != rank) continue;
    owned_nodes.push_back(node);
    held[static_cast<std::size_t>(node)] = 1;
  }
  const auto touch = [&](std::int32_t node) {
    if (node >= 0 && held[static_cast<std::size_t>(node)] == 0 && global.active(node) != 0) {
      held[static_cast<std::size_t>(node)] = 2;
      ghost_nodes.push_back(node);
    }
  };
  for (const ConnectorRecord& r : plan.connectors) {
    for (const std::int32_t node : r.nodes) touch(node);
  }
  for (const SpringRecord& s : plan.springs) {
    for (const std::int32_t node : s.nodes) touch(node);
  }
  // An owned node's constraint group is owned here whole; a ghost's is closed over here.
  for (std::size_t k = 0; k < ghost_nodes.size() && !dependents.empty(); ++k) {
    const std::int32_t node = ghost_nodes[k];
    for (int dof = 1; dof <= 6; ++dof) {
      const int eq = global.equation(node, dof);
      if (eq < 0 || !dependents.is_dependent(eq)) continue;
      const DependentDof& d =
          dependents
              .dofs[static_cast<std::size_t>(dependents.of_equation[static_cast<std::size_t>(eq)])];
      for (std::uint32_t t = d.first_term; t < d.first_term + d.term_count; ++t) {
        if (const int read = dependents.term_equation[t]; read >= 0) touch(global.node_of(read));
      }
      touch(d.reference);
    }
  }
  std::sort(ghost_nodes.begin(), ghost_nodes.end(), [&](std::int32_t a, std::int32_t b) {
    return first_global[static_cast<std::size_t>(a)] < first_global[static_cast<std::size_t>(b)];
  });
  std::vector<DofMask> active(global.nodes(), 0);
  for (std::int32_t node = 0; node < nodes; ++node) {
    if (held[static_cast<std::size_t>(node)] != 0) {
      active[static_cast<std::size_t>(node)] = global.active(node);
    }
  }
  // Local numbering: the owned nodes, this rank's multipliers, then the ghost nodes.
  DofMap local(std::move(active), owned_nodes);
  std::vector<int> local_of_global(static_cast<std::size_t>(global.equations()), -1);
  for (int k = 0; k < multipliers[me]; ++k) {
    const int eq = first_multiplier[me] + k;
    local_of_global[static_cast<std::size_t>(eq)] =
        local.add_multiplier(global.field(eq) == EquationField::RotationalMultiplier);
  }
  local.add_nodes(ghost_nodes);
  layout = {true, start[count], nodal, node_block, start[me], start[me + 1] - start[me], {}};
  const int solved_nodal = solved_start[count] - (start[count] - nodal);
  solved = {true,
            solved_start[count],
            solved_nodal,
            dependents.solved_node_block(global),
            solved_start[me],
            solved_start[me + 1] - solved_start[me],
            {}};
  // Node by node, a node's k-th equation and its j-th unknown are consecutive in the solver's.
  std::int32_t node_before = -1;
  int k = 0, j = 0;
  for (int eq = 0; eq < local.equations(); ++eq) {
    const std::int32_t node = local.node_of(eq);
    if (node < 0) continue;  // a multiplier
    if (node != node_before) k = j = 0;
    node_before = node;
    const int global_eq = global.equation(node, local.dof_of(eq));
    local_of_global[static_cast<std::size_t>(global_eq)] = eq;
    const bool is_dependent = dependents.is_dependent(global_eq);
    if (held[static_cast<std::size_t>(node)] == 2) {
      layout.ghost_global.push_back(first_global[static_cast<std::size_t>(node)] + k);
      if (!is_dependent)
        solved.ghost_global.push_back(first_solved[static_cast<std::size_t>(node)] + j);
    }
    ++k;
    j += is_dependent ? 0 : 1;
  }
  // The records' equations, in the model's numbering → local.
  const auto renumber = [&](std::span<int> equations) {
    for (int& eq : equations) eq = eq < 0 ? eq : local_of_global[static_cast<std::size_t>(eq)];
  };
  for (ConnectorRecord& r : plan.connectors)
    renumber({r.local.equation.data(), static_cast<std::size_t>(r.local.count)});
  for (SpringRecord& s : plan.springs)
    renumber({s.local.equation.data(), static_cast<std::size_t>(s.local.count)});
  for (ElementExpansion& e : plan.expansions) renumber(e.equations);
  // The inertia of the nodes the rank holds, its own first (AnalysisPlan::owned_inertia).
  std::vector<NodeInertia> inertia;
  for (const char kind : {1, 2}) {
    for (NodeInertia n : plan.inertia) {
      if (held[static_cast<std::size_t>(n.node)] != kind) continue;
      renumber(n.translation);
      renumber(n.rotation);
      inertia.push_back(n);
    }
    if (kind == 1) plan.owned_inertia = inertia.size();
  }
  plan.inertia = std::move(inertia);
  plan.dependents = local_dependents(dependents, local_of_global, local);
  plan.dofs = std::move(local);
}

}  // namespace clinch
