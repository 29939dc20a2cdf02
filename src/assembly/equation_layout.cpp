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
  std::vector<int> group_owner(global.nodes(), -1);  // by the group's root
  for (std::size_t node = 0; node < global.nodes(); ++node) {
    if (owner[node] < 0) continue;
    int& group =
        group_owner[static_cast<std::size_t>(groups.root(static_cast<std::int32_t>(node)))];
    if (group < 0) group = owner[node];  // the group's first node with equations
    owner[node] = group;
  }
  return owner;
}

// The number of a node's equations, and of those a kinematic constraint eliminates.
int equations_of(const DofMap& dofs, std::int32_t node) {
  return std::popcount(static_cast<unsigned>(dofs.active(node)));
}
int dependent_equations_of(const DofMap& dofs, const DependentDofs& dependents, std::int32_t node) {
  int count = 0;
  for (int dof = 1; dof <= 6; ++dof) {
    const int eq = dofs.equation(node, dof);
    count += eq >= 0 && dependents.is_dependent(eq) ? 1 : 0;
  }
  return count;
}

// The solver's numbering: rank q owns the equations [start[q], start[q + 1]), its nodes' in node
// order, then its multipliers; Newton's unknowns (solved_start) the same without the dependent
// equations. A node's equations, and its unknowns, are consecutive.
struct SolverNumbering {
  std::vector<int> start, solved_start;            // per rank, then the totals
  std::vector<int> first_global, first_solved;     // per node: its first equation and unknown
  std::vector<int> multipliers, first_multiplier;  // per rank (first: in the model's numbering)

  SolverNumbering(const AnalysisPlan& plan, const std::vector<int>& owner, int ranks)
      : start(static_cast<std::size_t>(ranks) + 1, 0),
        solved_start(start),
        first_global(plan.dofs.nodes(), -1),
        first_solved(first_global),
        multipliers(static_cast<std::size_t>(ranks), 0),
        first_multiplier(multipliers) {
    const DofMap& dofs = plan.dofs;
    const auto count = static_cast<std::size_t>(ranks);
    std::vector<int> equations(count, 0), unknowns(count, 0);
    const auto nodes = static_cast<std::int32_t>(dofs.nodes());
    // Each rank's nodes in node order, placed within its rows (counted, then shifted below).
    for (std::int32_t node = 0; node < nodes; ++node) {
      const int q = owner[static_cast<std::size_t>(node)];
      if (q < 0) continue;
      const auto n = static_cast<std::size_t>(node);
      const auto qs = static_cast<std::size_t>(q);
      first_global[n] = equations[qs];
      first_solved[n] = unknowns[qs];
      equations[qs] += equations_of(dofs, node);
      unknowns[qs] +=
          equations_of(dofs, node) - dependent_equations_of(dofs, plan.dependents, node);
    }
    for (std::size_t q = 0, next = static_cast<std::size_t>(dofs.node_equations()); q < count;
         ++q) {
      multipliers[q] = plan.share_multipliers.empty() ? 0 : plan.share_multipliers[q];
      first_multiplier[q] = static_cast<int>(next);
      next += static_cast<std::size_t>(multipliers[q]);
      start[q + 1] = start[q] + equations[q] + multipliers[q];
      solved_start[q + 1] = solved_start[q] + unknowns[q] + multipliers[q];
    }
    for (std::int32_t node = 0; node < nodes; ++node) {
      const int q = owner[static_cast<std::size_t>(node)];
      if (q < 0) continue;
      first_global[static_cast<std::size_t>(node)] += start[static_cast<std::size_t>(q)];
      first_solved[static_cast<std::size_t>(node)] += solved_start[static_cast<std::size_t>(q)];
    }
  }
};

// The nodes a rank holds: its own, in node order, and as ghosts the others its connectors and
// springs touch and those whose equations the maps of its ghost dependent DOFs read (an owned
// node's constraint is owned whole), in the solver's order.
struct HeldNodes {
  std::vector<char> held;  // per node: 1 owned, 2 a ghost, 0 not held
  std::vector<std::int32_t> owned, ghosts;

  HeldNodes(const AnalysisPlan& plan, const std::vector<int>& owner,
            const std::vector<int>& first_global, int rank)
      : held(plan.dofs.nodes(), 0) {
    const DofMap& dofs = plan.dofs;
    const DependentDofs& dependents = plan.dependents;
    for (std::size_t node = 0; node < dofs.nodes(); ++node) {
      if (owner[node] != rank) continue;
      owned.push_back(static_cast<std::int32_t>(node));
      held[node] = 1;
    }
    const auto touch = [&](std::int32_t node) {
      if (node >= 0 && held[static_cast<std::size_t>(node)] == 0 && dofs.active(node) != 0) {
        held[static_cast<std::size_t>(node)] = 2;
        ghosts.push_back(node);
      }
    };
    for (const ConnectorRecord& r : plan.connectors) {
      for (const std::int32_t node : r.nodes) touch(node);
    }
    for (const SpringRecord& s : plan.springs) {
      for (const std::int32_t node : s.nodes) touch(node);
    }
    for (std::size_t k = 0; k < ghosts.size() && !dependents.empty(); ++k) {
      for (int dof = 1; dof <= 6; ++dof) {
        const int eq = dofs.equation(ghosts[k], dof);
        if (eq < 0 || !dependents.is_dependent(eq)) continue;
        const DependentDof& d = dependents.dofs[static_cast<std::size_t>(
            dependents.of_equation[static_cast<std::size_t>(eq)])];
        for (std::uint32_t t = d.first_term; t < d.first_term + d.term_count; ++t) {
          if (const int read = dependents.term_equation[t]; read >= 0) touch(dofs.node_of(read));
        }
        touch(d.reference);
      }
    }
    std::sort(ghosts.begin(), ghosts.end(), [&](std::int32_t a, std::int32_t b) {
      return first_global[static_cast<std::size_t>(a)] < first_global[static_cast<std::size_t>(b)];
    });
  }
};

}  // namespace

void localize_equations(AnalysisPlan& plan, int rank, int ranks) {
  // The model's numbering: the node equations node by node, then the multipliers in element
  // order, each rank's share of the connectors one range of them.
  const DofMap& global = plan.dofs;
  const DependentDofs& dependents = plan.dependents;
  const int node_block = global.uniform_node_block();
  const std::vector<int> owner = node_owners(global, dependents, node_block, ranks);
  const SolverNumbering numbering(plan, owner, ranks);
  const HeldNodes nodes(plan, owner, numbering.first_global, rank);
  // Local numbering: the owned nodes, this rank's multipliers, then the ghost nodes.
  std::vector<DofMask> active(global.nodes(), 0);
  for (std::size_t node = 0; node < global.nodes(); ++node) {
    if (nodes.held[node] != 0) active[node] = global.active(static_cast<std::int32_t>(node));
  }
  DofMap local(std::move(active), nodes.owned);
  std::vector<int> local_of_global(static_cast<std::size_t>(global.equations()), -1);
  const auto me = static_cast<std::size_t>(rank);
  for (int k = 0; k < numbering.multipliers[me]; ++k) {
    const int eq = numbering.first_multiplier[me] + k;
    local_of_global[static_cast<std::size_t>(eq)] =
        local.add_multiplier(global.field(eq) == EquationField::RotationalMultiplier);
  }
  local.add_nodes(nodes.ghosts);
  const std::vector<int>& start = numbering.start;
  const std::vector<int>& solved_start = numbering.solved_start;
  const int nodal = global.node_equations(), multipliers = global.equations() - nodal;
  plan.layout = {true, start.back(), nodal, node_block, start[me], start[me + 1] - start[me], {}};
  plan.solved_layout = {true,
                        solved_start.back(),
                        solved_start.back() - multipliers,
                        dependents.solved_node_block(global),
                        solved_start[me],
                        solved_start[me + 1] - solved_start[me],
                        {}};
  // The ghosts' equations and unknowns, node by node in the solver's order.
  std::int32_t node_before = -1;
  int k = 0, j = 0;  // the place of an equation, and of an unknown, within its node's
  for (int eq = 0; eq < local.equations(); ++eq) {
    const std::int32_t node = local.node_of(eq);
    if (node < 0) continue;  // a multiplier
    if (node != node_before) k = j = 0;
    node_before = node;
    const int global_eq = global.equation(node, local.dof_of(eq));
    local_of_global[static_cast<std::size_t>(global_eq)] = eq;
    const bool is_dependent = dependents.is_dependent(global_eq);
    if (nodes.held[static_cast<std::size_t>(node)] == 2) {
      const auto n = static_cast<std::size_t>(node);
      plan.layout.ghost_global.push_back(numbering.first_global[n] + k);
      if (!is_dependent) plan.solved_layout.ghost_global.push_back(numbering.first_solved[n] + j);
    }
    ++k;
    j += is_dependent ? 0 : 1;
  }
  // The records' equations, in the model's numbering → local.
  const auto renumber = [&](std::span<int> equations) {
    for (int& eq : equations) eq = eq < 0 ? eq : local_of_global[static_cast<std::size_t>(eq)];
  };
  for (ConnectorRecord& r : plan.connectors) {
    renumber({r.local.equation.data(), static_cast<std::size_t>(r.local.count)});
  }
  for (SpringRecord& s : plan.springs) {
    renumber({s.local.equation.data(), static_cast<std::size_t>(s.local.count)});
  }
  for (ElementExpansion& e : plan.expansions) renumber(e.equations);
  // The inertia of the nodes the rank holds, its own first (AnalysisPlan::owned_inertia).
  std::vector<NodeInertia> inertia;
  for (const char kind : {char{1}, char{2}}) {
    for (NodeInertia n : plan.inertia) {
      if (nodes.held[static_cast<std::size_t>(n.node)] != kind) continue;
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
