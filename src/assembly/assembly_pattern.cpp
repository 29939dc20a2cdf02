#include "src/assembly/assembly_pattern.hpp"

#include <algorithm>
#include <stdexcept>

#include "src/assembly/constrained_elements.hpp"
#include "src/assembly/constrained_inertia.hpp"
#include "src/assembly/sparsity_pattern.hpp"

namespace clinch {

AssemblyPattern build_assembly_pattern(const AnalysisPlan& plan, bool symmetric,
                                       const RowAssemblyShare* share) {
  AssemblyPattern p;
  p.symmetric = symmetric;
  // The pattern is over the solved equations: the dependent ones have no row
  // (dependent_dofs.hpp).
  const DependentDofs& dependents = plan.dependents;
  const int n = dependents.solved_count(plan.dofs);
  const int node_block = dependents.solved_node_block(plan.dofs);
  if (!share && plan.shared) {
    throw std::logic_error("build_assembly_pattern: the whole pattern of a rank's plan");
  }
  // Over a rank's local unknowns its owned rows come first (equation_layout.hpp).
  const EquationLayout& layout = plan.solved_layout;
  const ItemRange rows = layout.local ? ItemRange{0, static_cast<std::size_t>(layout.owned)}
                         : share      ? owned_rows(n, node_block, share->rank, share->ranks)
                                      : ItemRange{0, static_cast<std::size_t>(n)};
  const ItemRange connectors = share ? share->connectors : ItemRange{0, plan.connectors.size()};
  const ItemRange springs =
      share ? share->springs
            : ItemRange{plan.first_spring, plan.first_spring + plan.springs.size()};
  const std::span<const ConnectorRecord> own_connectors(plan.connectors.data() + connectors.begin,
                                                        connectors.end - connectors.begin);
  const std::span<const SpringRecord> own_springs(
      plan.springs.data() + (springs.begin - plan.first_spring), springs.end - springs.begin);
  SparsityBuilder builder(n, symmetric, static_cast<int>(rows.begin), static_cast<int>(rows.end));
  // An element's equations: its own, or those of its condensed system (constrained_elements.hpp),
  // in the solved numbering.
  std::vector<int> solved;
  auto in_solved_numbering = [&](std::span<const int> l) -> std::span<const int> {
    if (dependents.empty()) return l;
    solved.clear();
    for (int eq : l) solved.push_back(eq < 0 ? eq : dependents.solved(eq));
    return solved;
  };
  auto equations = [&](const auto& r) {
    return in_solved_numbering(scatter_equations(plan, r.local, r.expansion));
  };
  // An element's local entries: its upper triangle, or all of them; the vectors are sized once.
  auto entries = [&](std::span<const int> l) {
    const auto n = l.size();
    return symmetric ? n * (n + 1) / 2 : n * n;
  };
  std::size_t local_entries = 0, local_diagonals = 0;
  auto count = [&](std::span<const int> l) {
    local_entries += entries(l);
    local_diagonals += l.size();
  };
  for (const ConnectorRecord& r : own_connectors) count(equations(r));
  for (const SpringRecord& r : own_springs) count(equations(r));
  builder.reserve(local_entries - (share ? 0 : local_diagonals));
  for (const ConnectorRecord& r : own_connectors) builder.couple(equations(r));
  for (const SpringRecord& r : own_springs) builder.couple(equations(r));
  // A rotary inertia tensor couples the rotations of its node (in a rank's part, of a node with
  // a row it owns: the rank that owns an entry's row adds it); inertia on a dependent DOF couples
  // the independent equations its block moves with (constrained_inertia.hpp).
  const auto owns_some = [&](std::span<const int> equations) {
    return !share || std::any_of(equations.begin(), equations.end(), [&](int eq) {
      return eq >= 0 && static_cast<std::size_t>(eq) >= rows.begin &&
             static_cast<std::size_t>(eq) < rows.end;
    });
  };
  for (const NodeInertia& n : plan.inertia) {
    if (has_dependent_dof(n.rotation, dependents)) continue;
    const std::span<const int> solved_rotation = in_solved_numbering(n.rotation);
    if (owns_some(solved_rotation)) builder.couple(solved_rotation);
  }
  for (const std::vector<int>& columns : constrained_inertia_couplings(plan.inertia, dependents)) {
    const std::span<const int> solved_columns = in_solved_numbering(columns);
    if (owns_some(solved_columns)) builder.couple(solved_columns);
  }
  // The curvature of rigid arms and links under NLGEOM couples the equations they read.
  for (const DependentDof& d : dependents.dofs) {
    if (!d.curved()) continue;
    std::vector<int> read(dependents.term_equation.begin() + d.first_term,
                          dependents.term_equation.begin() + d.first_term + d.term_count);
    for (int i = 0; i < 3; ++i) read.push_back(plan.dofs.equation(d.reference, 4 + i));
    std::erase_if(read, [&dependents](int eq) { return eq < 0 || dependents.is_dependent(eq); });
    const std::span<const int> solved_read = in_solved_numbering(read);
    if (owns_some(solved_read)) builder.couple(solved_read);
  }
  p.matrix = builder.build();
  p.matrix.node_block = layout.local ? layout.node_block : node_block;
  if (share) {
    p.matrix.first_owned_row = static_cast<int>(rows.begin);
    p.matrix.owned_rows = static_cast<int>(rows.end - rows.begin);
  }
  if (layout.local) {
    p.matrix.global_equation.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
      p.matrix.global_equation[static_cast<std::size_t>(i)] = layout.global_of(i);
    p.matrix.global_n = layout.global_count;
    p.matrix.global_first_row = layout.first_owned;
  }
  p.positions.reserve(local_entries);
  auto place = [&](std::span<const int> l) {
    const std::size_t offset = p.positions.size();
    const auto n = static_cast<int>(l.size());
    for (int b = 0; b < n; ++b) {
      const int last = symmetric ? b : n - 1;
      for (int a = 0; a <= last; ++a) {
        p.positions.push_back(entry_position(p.matrix, l[static_cast<std::size_t>(a)],
                                             l[static_cast<std::size_t>(b)]));
      }
    }
    return offset;
  };
  p.first_connector = connectors.begin;
  p.connector_offset.reserve(own_connectors.size());
  for (const ConnectorRecord& r : own_connectors) p.connector_offset.push_back(place(equations(r)));
  p.first_spring = springs.begin;
  p.spring_offset.reserve(own_springs.size());
  for (const SpringRecord& r : own_springs) p.spring_offset.push_back(place(equations(r)));
  p.diagonal.resize(static_cast<std::size_t>(p.matrix.n));
  for (int i = 0; i < p.matrix.n; ++i) {
    p.diagonal[static_cast<std::size_t>(i)] = entry_position(p.matrix, i, i);
  }
  return p;
}

}  // namespace clinch
