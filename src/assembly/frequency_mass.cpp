#include "src/assembly/frequency_mass.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <map>
#include <optional>

#include "src/assembly/constrained_inertia.hpp"
#include "src/assembly/nodal_inertia.hpp"
#include "src/model/output_variables.hpp"

namespace clinch {
namespace {

// One block of the lumped mass over solved equations: a node's own block, or a constrained
// node's block condensed onto the free independent equations it moves with
// (constrained_inertia.hpp: TᵀMT).
struct SolvedBlock {
  std::vector<int> solved;
  Eigen::MatrixXd m;
};

std::optional<SolvedBlock> node_block(const std::array<int, 3>& eq, const Matrix3& m,
                                      const ConnectorSystem& system) {
  const DependentDofs& dependents = system.plan().dependents;
  SolvedBlock b;
  std::vector<int> local;
  for (int i = 0; i < 3; ++i) {
    const int e = eq[static_cast<std::size_t>(i)];
    if (e < 0 || system.is_prescribed(e) || dependents.is_dependent(e)) continue;
    b.solved.push_back(dependents.solved(e));
    local.push_back(i);
  }
  if (local.empty()) return std::nullopt;
  const auto n = static_cast<Eigen::Index>(local.size());
  b.m.resize(n, n);
  for (Eigen::Index p = 0; p < n; ++p) {
    for (Eigen::Index q = 0; q < n; ++q) {
      b.m(p, q) = m(local[static_cast<std::size_t>(p)], local[static_cast<std::size_t>(q)]);
    }
  }
  return b;
}

std::optional<SolvedBlock> mapped_block(const MappedInertiaBlock& mapped,
                                        const ConnectorSystem& system) {
  const DependentDofs& dependents = system.plan().dependents;
  SolvedBlock b;
  std::vector<Eigen::Index> kept;
  for (std::size_t p = 0; p < mapped.columns.size(); ++p) {
    if (system.is_prescribed(mapped.columns[p])) continue;
    b.solved.push_back(dependents.solved(mapped.columns[p]));
    kept.push_back(static_cast<Eigen::Index>(p));
  }
  if (kept.empty()) return std::nullopt;
  Eigen::MatrixXd t(3, static_cast<Eigen::Index>(kept.size()));
  for (std::size_t p = 0; p < kept.size(); ++p) {
    t.col(static_cast<Eigen::Index>(p)) = mapped.t.col(kept[p]);
  }
  b.m = t.transpose() * mapped.m * t;
  return b;
}

// The entries of M and its factor F (M = F Fᵀ). Blocks that share an equation are summed before
// F is taken, so that a block which is not positive by itself (the rest of a rigid body's
// element inertia on its reference node, element_mass.hpp) is factored with the blocks that
// make the whole positive. Directions below round-off of a group's largest eigenvalue carry no
// inertia.
void add_blocks(const std::vector<SolvedBlock>& blocks, int equations, LumpedMass& mass) {
  for (const SolvedBlock& b : blocks) {
    for (std::size_t p = 0; p < b.solved.size(); ++p) {
      for (std::size_t q = 0; q < b.solved.size(); ++q) {
        const double value = b.m(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(q));
        if (b.solved[p] <= b.solved[q] && value != 0.0) {
          mass.entries.push_back({b.solved[p], b.solved[q], value});
        }
      }
    }
  }
  // Groups of blocks joined by shared equations (union–find over the equations).
  std::vector<int> parent(static_cast<std::size_t>(std::max(equations, 0)));
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<int>(i);
  auto root = [&parent](int i) {
    while (parent[static_cast<std::size_t>(i)] != i) {
      i = parent[static_cast<std::size_t>(i)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
    }
    return i;
  };
  for (const SolvedBlock& b : blocks) {
    for (std::size_t p = 1; p < b.solved.size(); ++p) {
      parent[static_cast<std::size_t>(root(b.solved[p]))] = root(b.solved[0]);
    }
  }
  std::map<int, std::vector<const SolvedBlock*>> groups;
  for (const SolvedBlock& b : blocks) groups[root(b.solved[0])].push_back(&b);
  for (const auto& [group_root, members] : groups) {
    std::vector<int> solved;
    for (const SolvedBlock* b : members) solved.insert(solved.end(), b->solved.begin(), b->solved.end());
    std::sort(solved.begin(), solved.end());
    solved.erase(std::unique(solved.begin(), solved.end()), solved.end());
    const auto n = static_cast<Eigen::Index>(solved.size());
    Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(n, n);
    for (const SolvedBlock* b : members) {
      std::vector<Eigen::Index> at;
      for (const int e : b->solved) {
        at.push_back(std::lower_bound(solved.begin(), solved.end(), e) - solved.begin());
      }
      for (std::size_t p = 0; p < at.size(); ++p) {
        for (std::size_t q = 0; q < at.size(); ++q) {
          sum(at[p], at[q]) += b->m(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(q));
        }
      }
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> principal(sum);
    const double largest = principal.eigenvalues().maxCoeff();
    for (Eigen::Index k = 0; k < n; ++k) {
      const double d = principal.eigenvalues()[k];
      if (d <= 1e-12 * largest) continue;
      std::vector<std::pair<int, double>> column;
      for (Eigen::Index p = 0; p < n; ++p) {
        const double f = std::sqrt(d) * principal.eigenvectors()(p, k);
        if (f != 0.0) column.emplace_back(solved[static_cast<std::size_t>(p)], f);
      }
      mass.factor.push_back(std::move(column));
    }
  }
}

}  // namespace

FrequencyModel frequency_model(const Model& model, const ConnectorSystem& system) {
  const AnalysisPlan& plan = system.plan();
  FrequencyModel out;
  const int n = system.size();
  out.dof_names.resize(static_cast<std::size_t>(n));
  for (int s = 0; s < n; ++s) {
    const int eq = system.equation_of_solved(s);
    if (eq >= plan.dofs.node_equations()) continue;  // a multiplier
    const Node& node = model.nodes[static_cast<std::size_t>(plan.dofs.node_of(eq))];
    out.dof_names[static_cast<std::size_t>(s)] =
        output_column_label("U", plan.dofs.dof_of(eq)) + "@" +
        qualified_label(model, node.instance, node.label);
  }
  const std::vector<NodeInertia> inertia = nodal_inertia(model, plan.dofs);
  std::vector<SolvedBlock> blocks;
  auto keep = [&blocks](std::optional<SolvedBlock> b) {
    if (b) blocks.push_back(std::move(*b));
  };
  for (const NodeInertia& node : inertia) {
    if (!has_dependent_dof(node.translation, plan.dependents)) {
      keep(node_block(node.translation, Matrix3(node.mass.asDiagonal()), system));
    }
    if (!has_dependent_dof(node.rotation, plan.dependents)) {
      keep(node_block(node.rotation, node.rotary, system));
    }
  }
  const DependentMotion motion = system.dependent_motion();
  for (const MappedInertiaBlock& b : mapped_inertia_blocks(inertia, plan.dependents, motion)) {
    keep(mapped_block(b, system));
  }
  add_blocks(blocks, n, out.mass);
  return out;
}

}  // namespace clinch
