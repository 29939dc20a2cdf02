#include "src/assembly/constrained_inertia.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "src/assembly/sparsity_pattern.hpp"

namespace clinch {
namespace {

const DependentDof& dependent_of(const DependentDofs& dofs, int eq) {
  return dofs.dofs[static_cast<std::size_t>(dofs.of_equation[static_cast<std::size_t>(eq)])];
}

// The independent equations a DOF moves with: itself, or the resolved terms of its map.
template <typename Visit>
void for_each_column(const DependentDofs& dofs, int eq, Visit visit) {
  if (!dofs.is_dependent(eq)) {
    visit(eq, 0u);
    return;
  }
  const DependentDof& d = dependent_of(dofs, eq);
  for (std::uint32_t e = 0; e < d.resolved_count; ++e) {
    visit(dofs.resolved_equation[d.first_resolved + e], e);
  }
}

std::vector<int> block_columns(const std::array<int, 3>& eq, const DependentDofs& dofs) {
  std::vector<int> columns;
  for (const int e : eq) {
    if (e < 0) continue;
    for_each_column(dofs, e, [&columns](int column, std::uint32_t) {
      if (std::find(columns.begin(), columns.end(), column) == columns.end()) {
        columns.push_back(column);
      }
    });
  }
  return columns;
}

// The two blocks of a node: translations with their masses, rotations with the tensor.
template <typename Visit>
void for_each_block(const NodeInertia& node, Visit visit) {
  visit(node.translation, Matrix3(node.mass.asDiagonal()), 0);
  visit(node.rotation, node.rotary, 1);
}

bool carries_inertia(const Matrix3& m) { return m.diagonal().maxCoeff() > 0.0; }

}  // namespace

bool has_dependent_dof(const std::array<int, 3>& eq, const DependentDofs& dofs) {
  return std::any_of(eq.begin(), eq.end(), [&](int e) { return e >= 0 && dofs.is_dependent(e); });
}

std::vector<MappedInertiaBlock> mapped_inertia_blocks(std::span<const NodeInertia> inertia,
                                                      const DependentDofs& dofs,
                                                      const DependentMotion& motion) {
  std::vector<MappedInertiaBlock> blocks;
  if (dofs.empty()) return blocks;
  for (const NodeInertia& node : inertia) {
    for_each_block(node, [&](const std::array<int, 3>& eq, const Matrix3& m, int field) {
      if (!carries_inertia(m) || !has_dependent_dof(eq, dofs)) return;
      MappedInertiaBlock b;
      b.eq = eq;
      b.field = field;
      b.m = m;
      b.columns = block_columns(eq, dofs);
      b.t.setZero(3, static_cast<Eigen::Index>(b.columns.size()));
      for (int i = 0; i < 3; ++i) {
        const int e = eq[static_cast<std::size_t>(i)];
        if (e < 0) continue;
        const bool dependent = dofs.is_dependent(e);
        const std::span<const double> gradient =
            dependent ? motion.gradient(dependent_of(dofs, e)) : std::span<const double>{};
        for_each_column(dofs, e, [&](int column, std::uint32_t k) {
          const auto place =
              std::find(b.columns.begin(), b.columns.end(), column) - b.columns.begin();
          b.t(i, place) += dependent ? gradient[k] : 1.0;
        });
      }
      blocks.push_back(std::move(b));
    });
  }
  return blocks;
}

std::vector<std::vector<int>> constrained_inertia_couplings(std::span<const NodeInertia> inertia,
                                                            const DependentDofs& dofs) {
  std::vector<std::vector<int>> couplings;
  if (dofs.empty()) return couplings;
  for (const NodeInertia& node : inertia) {
    for_each_block(node, [&](const std::array<int, 3>& eq, const Matrix3& m, int) {
      if (carries_inertia(m) && has_dependent_dof(eq, dofs)) {
        couplings.push_back(block_columns(eq, dofs));
      }
    });
  }
  return couplings;
}

void add_constrained_inertia(const std::vector<MappedInertiaBlock>& blocks,
                             const NewmarkIncrement& increment, const AnalysisState& state,
                             const IncrementConditions& conditions, InertiaTarget target,
                             Eigen::VectorXd& inertia_force, ForceEntries& entries) {
  const double scale = 1.0 / (1.0 + increment.alpha);
  const DependentDofs& dofs = target.dependents;
  for (const MappedInertiaBlock& b : blocks) {
    Vector3 acceleration = Vector3::Zero();
    for (int i = 0; i < 3; ++i) {
      const int e = b.eq[static_cast<std::size_t>(i)];
      if (e >= 0) acceleration[i] = state.a[e];
    }
    const Vector3 force = b.m * acceleration;
    for (int i = 0; i < 3; ++i) {
      const int e = b.eq[static_cast<std::size_t>(i)];
      if (e < 0) continue;
      if (dofs.is_dependent(e)) inertia_force[e] = force[i];
      entries.add(b.field, std::abs(force[i]));
    }
    const Eigen::VectorXd pulled = b.t.transpose() * force;
    const auto n = static_cast<Eigen::Index>(b.columns.size());
    for (Eigen::Index p = 0; p < n; ++p) {
      const int row = b.columns[static_cast<std::size_t>(p)];
      inertia_force[row] += pulled[p];  // what a prescribed row's reaction includes
      if (!conditions.is_prescribed(row)) target.residual[row] += scale * pulled[p];
    }
    if (!target.tangent) continue;
    const Eigen::MatrixXd k = (increment.da_du * scale) * (b.t.transpose() * b.m * b.t);
    for (Eigen::Index p = 0; p < n; ++p) {
      const int row = b.columns[static_cast<std::size_t>(p)];
      if (conditions.is_prescribed(row)) continue;
      for (Eigen::Index q = 0; q < n; ++q) {
        const int column = b.columns[static_cast<std::size_t>(q)];
        if (k(p, q) == 0.0) continue;
        if (conditions.is_prescribed(column)) {
          // The prescribed column goes to the right-hand side, as an element's does.
          if (target.predictor) {
            (*target.predictor)[row] += k(p, q) * (conditions.target(column) - state.x[column]);
          }
          continue;
        }
        const int solved_row = dofs.solved(row), solved_column = dofs.solved(column);
        if (target.symmetric && solved_column < solved_row) continue;  // upper storage
        // Under assembly by rows the rank that owns the row adds the entry.
        if (!target.tangent->owns_row(solved_row)) continue;
        const int position = entry_position(*target.tangent, solved_row, solved_column);
        target.tangent->values[static_cast<std::size_t>(position)] += k(p, q);
      }
    }
  }
}

void dependent_inertia_forces(const std::vector<MappedInertiaBlock>& blocks,
                              const DependentDofs& dofs, const Eigen::VectorXd& a,
                              Eigen::VectorXd& out) {
  for (const MappedInertiaBlock& b : blocks) {
    Vector3 acceleration = Vector3::Zero();
    for (int i = 0; i < 3; ++i) {
      const int e = b.eq[static_cast<std::size_t>(i)];
      if (e >= 0) acceleration[i] = a[e];
    }
    const Vector3 force = b.m * acceleration;
    for (int i = 0; i < 3; ++i) {
      const int e = b.eq[static_cast<std::size_t>(i)];
      if (e >= 0 && dofs.is_dependent(e)) out[e] = force[i];
    }
  }
}

void follow_constraint_rates(const DependentDofs& dofs, const DependentMotion& motion,
                             const Eigen::VectorXd& x, const std::vector<Matrix3>& rotation,
                             bool nlgeom, Eigen::VectorXd& v, Eigen::VectorXd* a) {
  std::vector<CurvatureEntry> curvature;
  for (const DependentDof& d : dofs.dofs) {
    const std::span<const double> gradient = motion.gradient(d);
    double velocity = 0.0, acceleration = 0.0;
    for (std::uint32_t e = 0; e < d.resolved_count; ++e) {
      const int eq = dofs.resolved_equation[d.first_resolved + e];
      velocity += gradient[e] * v[eq];
      if (a) acceleration += gradient[e] * (*a)[eq];
    }
    v[d.equation] = velocity;
    if (!a) continue;
    if (nlgeom && !rotation.empty()) {
      curvature.clear();
      motion.add_curvature(d, 1.0, x, rotation, curvature);
      for (const CurvatureEntry& c : curvature) acceleration += c.value * v[c.row] * v[c.column];
    }
    (*a)[d.equation] = acceleration;
  }
}

void constrained_initial_accelerations(std::span<const NodeInertia> inertia,
                                       const std::vector<MappedInertiaBlock>& blocks,
                                       const IncrementConditions& conditions,
                                       const Eigen::VectorXd& r, Eigen::VectorXd& a) {
  if (blocks.empty()) return;
  // The free equations of the condensed system, numbered in the order they are met.
  std::unordered_map<int, Eigen::Index> place;
  std::vector<int> equations;
  auto include = [&](int eq) {
    if (eq < 0 || conditions.is_prescribed(eq) || place.contains(eq)) return;
    place.emplace(eq, static_cast<Eigen::Index>(equations.size()));
    equations.push_back(eq);
  };
  for (const MappedInertiaBlock& b : blocks) {
    for (const int column : b.columns) include(column);
  }
  // A free block (no dependent DOF) on one of those equations is solved with them.
  std::vector<std::pair<std::array<int, 3>, Matrix3>> shared;
  for (const NodeInertia& node : inertia) {
    for_each_block(node, [&](const std::array<int, 3>& eq, const Matrix3& m, int) {
      if (!carries_inertia(m)) return;
      const bool dependent = std::any_of(blocks.begin(), blocks.end(),
                                         [&](const MappedInertiaBlock& b) { return b.eq == eq; });
      const bool touches =
          std::any_of(eq.begin(), eq.end(), [&](int e) { return place.contains(e); });
      if (dependent || !touches) return;
      shared.emplace_back(eq, m);
    });
  }
  for (const auto& [eq, m] : shared) {
    for (const int e : eq) include(e);
  }
  const auto n = static_cast<Eigen::Index>(equations.size());
  Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd rhs(n);
  for (Eigen::Index i = 0; i < n; ++i) rhs[i] = -r[equations[static_cast<std::size_t>(i)]];
  for (const auto& [eq, m] : shared) {
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        const auto pi = place.find(eq[static_cast<std::size_t>(i)]);
        const auto pj = place.find(eq[static_cast<std::size_t>(j)]);
        if (pi != place.end() && pj != place.end()) mass(pi->second, pj->second) += m(i, j);
      }
    }
  }
  for (const MappedInertiaBlock& b : blocks) {
    // The velocity-product terms the caller left in `a` at the block's dependent DOFs.
    Vector3 c = Vector3::Zero();
    for (int i = 0; i < 3; ++i) {
      const int e = b.eq[static_cast<std::size_t>(i)];
      if (e >= 0 && std::find(b.columns.begin(), b.columns.end(), e) == b.columns.end()) {
        c[i] = a[e];
      }
    }
    const Eigen::MatrixXd mt = b.m * b.t;
    const Eigen::VectorXd mc = b.t.transpose() * (b.m * c);
    for (std::size_t p = 0; p < b.columns.size(); ++p) {
      const auto pp = place.find(b.columns[p]);
      if (pp == place.end()) continue;
      rhs[pp->second] -= mc[static_cast<Eigen::Index>(p)];
      for (std::size_t q = 0; q < b.columns.size(); ++q) {
        const auto pq = place.find(b.columns[q]);
        if (pq == place.end()) continue;
        mass(pp->second, pq->second) +=
            b.t.col(static_cast<Eigen::Index>(p)).dot(mt.col(static_cast<Eigen::Index>(q)));
      }
    }
  }
  // An equation without inertia in the condensed system (a massless direction) keeps a = 0.
  const double largest = n > 0 ? mass.diagonal().maxCoeff() : 0.0;
  std::vector<Eigen::Index> kept;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (mass(i, i) > 1e-12 * largest) kept.push_back(i);
  }
  const auto k = static_cast<Eigen::Index>(kept.size());
  Eigen::MatrixXd reduced(k, k);
  Eigen::VectorXd f(k);
  for (Eigen::Index p = 0; p < k; ++p) {
    f[p] = rhs[kept[static_cast<std::size_t>(p)]];
    for (Eigen::Index q = 0; q < k; ++q) {
      reduced(p, q) = mass(kept[static_cast<std::size_t>(p)], kept[static_cast<std::size_t>(q)]);
    }
  }
  const Eigen::VectorXd solved = reduced.ldlt().solve(f);
  for (const int eq : equations) a[eq] = 0.0;
  for (Eigen::Index p = 0; p < k; ++p) {
    a[equations[static_cast<std::size_t>(kept[static_cast<std::size_t>(p)])]] = solved[p];
  }
}

}  // namespace clinch
