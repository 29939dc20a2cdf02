#include "src/assembly/assembly_pattern.hpp"

#include "src/assembly/sparsity_pattern.hpp"

namespace clinch {

AssemblyPattern build_assembly_pattern(const AnalysisPlan& plan, bool symmetric) {
  AssemblyPattern p;
  p.symmetric = symmetric;
  SparsityBuilder builder(plan.dofs.equations(), symmetric);
  // An element's local entries: its upper triangle, or all of them; the vectors are sized once.
  auto entries = [&](const LocalEquations& l) {
    const auto n = static_cast<std::size_t>(l.count);
    return symmetric ? n * (n + 1) / 2 : n * n;
  };
  std::size_t local_entries = 0, local_diagonals = 0;
  auto count = [&](const LocalEquations& l) {
    local_entries += entries(l);
    local_diagonals += static_cast<std::size_t>(l.count);
  };
  for (const ConnectorRecord& r : plan.connectors) count(r.local);
  for (const SpringRecord& r : plan.springs) count(r.local);
  builder.reserve(local_entries - local_diagonals);
  auto couple = [&](const LocalEquations& l) {
    builder.couple(std::span<const int>(l.equation.data(), static_cast<std::size_t>(l.count)));
  };
  for (const ConnectorRecord& r : plan.connectors) couple(r.local);
  for (const SpringRecord& r : plan.springs) couple(r.local);
  p.matrix = builder.build();
  p.matrix.node_block = plan.dofs.uniform_node_block();
  p.positions.reserve(local_entries);
  auto place = [&](const LocalEquations& l) {
    const std::size_t offset = p.positions.size();
    for (int b = 0; b < l.count; ++b) {
      const int last = symmetric ? b : l.count - 1;
      for (int a = 0; a <= last; ++a) {
        p.positions.push_back(entry_position(p.matrix, l.equation[static_cast<std::size_t>(a)],
                                             l.equation[static_cast<std::size_t>(b)]));
      }
    }
    return offset;
  };
  p.connector_offset.reserve(plan.connectors.size());
  for (const ConnectorRecord& r : plan.connectors) p.connector_offset.push_back(place(r.local));
  p.spring_offset.reserve(plan.springs.size());
  for (const SpringRecord& r : plan.springs) p.spring_offset.push_back(place(r.local));
  p.diagonal.resize(static_cast<std::size_t>(p.matrix.n));
  for (int i = 0; i < p.matrix.n; ++i) {
    p.diagonal[static_cast<std::size_t>(i)] = entry_position(p.matrix, i, i);
  }
  return p;
}

}  // namespace clinch
