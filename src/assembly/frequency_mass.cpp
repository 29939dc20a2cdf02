#include "src/assembly/frequency_mass.hpp"

#include <Eigen/Eigenvalues>

#include "src/assembly/constrained_inertia.hpp"
#include "src/assembly/nodal_inertia.hpp"
#include "src/model/output_variables.hpp"

namespace clinch {
namespace {

// Adds one node's block: the free solved equations of `eq` and their part of `m`.
void add_block(const std::array<int, 3>& eq, const Matrix3& m, const ConnectorSystem& system,
               LumpedMass& mass) {
  const DependentDofs& dependents = system.plan().dependents;
  std::array<int, 3> solved{};
  std::array<int, 3> local{};
  int count = 0;
  for (int i = 0; i < 3; ++i) {
    const int e = eq[static_cast<std::size_t>(i)];
    if (e < 0 || system.is_prescribed(e) || dependents.is_dependent(e)) continue;
    if (m(i, i) <= 0.0) continue;  // no inertia in this direction (a positive block has m_ii > 0)
    solved[static_cast<std::size_t>(count)] = dependents.solved(e);
    local[static_cast<std::size_t>(count++)] = i;
  }
  if (count == 0) return;
  Eigen::MatrixXd block(count, count);
  for (int p = 0; p < count; ++p) {
    for (int q = 0; q < count; ++q) {
      block(p, q) = m(local[static_cast<std::size_t>(p)], local[static_cast<std::size_t>(q)]);
    }
  }
  for (int p = 0; p < count; ++p) {
    for (int q = 0; q < count; ++q) {
      const int row = solved[static_cast<std::size_t>(p)];
      const int column = solved[static_cast<std::size_t>(q)];
      if (row <= column && block(p, q) != 0.0) mass.entries.push_back({row, column, block(p, q)});
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> principal(block);
  const double largest = principal.eigenvalues().maxCoeff();
  for (int k = 0; k < count; ++k) {
    const double d = principal.eigenvalues()[k];
    // Below round-off of the largest: a direction without inertia (a singular tensor).
    if (d <= 1e-12 * largest) continue;
    std::vector<std::pair<int, double>> column;
    for (int p = 0; p < count; ++p) {
      const double f = std::sqrt(d) * principal.eigenvectors()(p, k);
      if (f != 0.0) column.emplace_back(solved[static_cast<std::size_t>(p)], f);
    }
    mass.factor.push_back(std::move(column));
  }
}

// A block with a dependent DOF, condensed onto the free independent equations it moves with
// (constrained_inertia.hpp): the entries of TᵀMT and the columns Tᵀ(√d q).
void add_mapped_block(const MappedInertiaBlock& b, const ConnectorSystem& system,
                      LumpedMass& mass) {
  const DependentDofs& dependents = system.plan().dependents;
  std::vector<int> solved;
  std::vector<Eigen::Index> kept;
  for (std::size_t p = 0; p < b.columns.size(); ++p) {
    if (system.is_prescribed(b.columns[p])) continue;
    solved.push_back(dependents.solved(b.columns[p]));
    kept.push_back(static_cast<Eigen::Index>(p));
  }
  if (kept.empty()) return;
  Eigen::MatrixXd t(3, static_cast<Eigen::Index>(kept.size()));
  for (std::size_t p = 0; p < kept.size(); ++p) t.col(static_cast<Eigen::Index>(p)) = b.t.col(kept[p]);
  const Eigen::MatrixXd condensed = t.transpose() * b.m * t;
  for (std::size_t p = 0; p < solved.size(); ++p) {
    for (std::size_t q = 0; q < solved.size(); ++q) {
      const double value = condensed(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(q));
      if (solved[p] <= solved[q] && value != 0.0) mass.entries.push_back({solved[p], solved[q], value});
    }
  }
  const Eigen::SelfAdjointEigenSolver<Matrix3> principal(b.m);
  const double largest = principal.eigenvalues().maxCoeff();
  for (int k = 0; k < 3; ++k) {
    const double d = principal.eigenvalues()[k];
    if (d <= 1e-12 * largest) continue;
    const Eigen::VectorXd f = t.transpose() * (std::sqrt(d) * principal.eigenvectors().col(k));
    std::vector<std::pair<int, double>> column;
    for (std::size_t p = 0; p < solved.size(); ++p) {
      if (f[static_cast<Eigen::Index>(p)] != 0.0) column.emplace_back(solved[p], f[static_cast<Eigen::Index>(p)]);
    }
    if (!column.empty()) mass.factor.push_back(std::move(column));
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
  for (const NodeInertia& node : inertia) {
    if (!has_dependent_dof(node.translation, plan.dependents)) {
      add_block(node.translation, Matrix3(node.mass.asDiagonal()), system, out.mass);
    }
    if (!has_dependent_dof(node.rotation, plan.dependents)) {
      add_block(node.rotation, node.rotary, system, out.mass);
    }
  }
  const DependentMotion motion = system.dependent_motion();
  for (const MappedInertiaBlock& b : mapped_inertia_blocks(inertia, plan.dependents, motion)) {
    add_mapped_block(b, system, out.mass);
  }
  return out;
}

}  // namespace clinch
