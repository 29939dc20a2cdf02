#include "src/assembly/dynamic_terms.hpp"

#include <cmath>

#include "src/assembly/constrained_inertia.hpp"
#include "src/assembly/rotary_inertia_finite.hpp"
#include "src/assembly/sparsity_pattern.hpp"

namespace clinch {
namespace {

// The equations of a node's inertia: u1–u3 with their masses, then ur1–ur3 with the tensor.
struct InertiaBlock {
  std::array<int, 3> eq;
  Matrix3 m;
};

std::array<InertiaBlock, 2> blocks_of(const NodeInertia& n) {
  return {InertiaBlock{n.translation, Matrix3(n.mass.asDiagonal())},
          InertiaBlock{n.rotation, n.rotary}};
}

}  // namespace

NewmarkIncrement NewmarkIncrement::of(const DynamicProcedure& procedure, double dt) {
  NewmarkIncrement n;
  n.dt = dt;
  n.backward_euler = procedure.backward_euler;
  n.alpha = procedure.backward_euler ? 0.0 : procedure.alpha;
  n.beta = procedure.beta;
  n.gamma = procedure.gamma;
  n.da_du = n.backward_euler ? 1.0 / (dt * dt) : 1.0 / (n.beta * dt * dt);
  n.dv_du = n.backward_euler ? 1.0 / dt : n.gamma / (n.beta * dt);
  return n;
}

void NewmarkIncrement::update_rates(AnalysisState& s) const {
  const auto n = s.v.size();
  const auto du = s.x.head(n) - s.x_n.head(n);
  if (backward_euler) {
    s.v = du / dt;
    s.a = (s.v - s.v_n) / dt;
    return;
  }
  // Newmark: u₁ = u₀ + Δt v₀ + Δt²[(1/2 − β) a₀ + β a₁], v₁ = v₀ + Δt[(1 − γ) a₀ + γ a₁].
  s.a = da_du * (du - dt * s.v_n) - (0.5 / beta - 1.0) * s.a_n;
  s.v = s.v_n + dt * ((1.0 - gamma) * s.a_n + gamma * s.a);
}

double NewmarkIncrement::value_of_rate(double u0, double v0, double a0, int order,
                                       double rate) const {
  if (backward_euler) {
    const double v1 = order == 1 ? rate : v0 + dt * rate;
    return u0 + dt * v1;
  }
  const double a1 = order == 2 ? rate : (rate - v0 - dt * (1.0 - gamma) * a0) / (gamma * dt);
  return u0 + dt * v0 + dt * dt * ((0.5 - beta) * a0 + beta * a1);
}

void NewmarkIncrement::set_half_increment_state(AnalysisState& s, const DofMap& dofs) const {
  const auto n = s.v.size();
  const Eigen::VectorXd mean = 0.5 * (s.x + s.x_n);
  s.x = mean;
  s.a = 0.5 * (s.a + s.a_n);
  if (backward_euler) {
    s.v = 0.5 * (s.v + s.v_n);
    return;
  }
  const double h = 0.5 * dt;
  s.x.head(n) = s.x_n.head(n) + h * s.v_n + h * h * ((0.5 - beta) * s.a_n + beta * s.a);
  s.v = s.v_n + h * ((1.0 - gamma) * s.a_n + gamma * s.a);
  // A multiplier among the rates' equations (a rank's local numbering) keeps the mean.
  for (Eigen::Index eq = 0; eq < n; ++eq) {
    if (dofs.node_of(static_cast<int>(eq)) < 0) s.x[eq] = mean[eq];
  }
}

void add_inertia(std::span<const NodeInertia> inertia, const NewmarkIncrement& increment,
                 const AnalysisState& state, const IncrementConditions& conditions,
                 InertiaTarget target, Eigen::VectorXd& inertia_force, ForceEntries& entries) {
  const double scale = 1.0 / (1.0 + increment.alpha);
  const double stiffness = increment.da_du * scale;
  // The HHT α term of the converged state, on every free nodal row; the rotation rows of a node
  // with finite rotary inertia hold their own balance (rotary_inertia_finite.hpp).
  const bool nlgeom = !state.rotation.empty();
  if (increment.alpha != 0.0) {
    Eigen::VectorXd alpha_term = increment.alpha * scale * state.r_n;
    for (const NodeInertia& node : inertia) {
      if (!has_finite_rotary_inertia(node, nlgeom)) continue;
      for (int eq : node.rotation) alpha_term[eq] = 0.0;
    }
    for (Eigen::Index eq = 0; eq < state.r_n.size(); ++eq) {
      if (!conditions.is_prescribed(static_cast<int>(eq))) target.residual[eq] -= alpha_term[eq];
    }
  }
  add_finite_rotary_inertia(inertia, increment.dt, state, conditions, target, inertia_force,
                            entries);
  for (const NodeInertia& node : inertia) {
    const std::array<InertiaBlock, 2> blocks = blocks_of(node);
    const int fields = has_finite_rotary_inertia(node, nlgeom) ? 1 : 2;
    for (int field = 0; field < fields; ++field) {  // forces, then moments
      const InertiaBlock& block = blocks[static_cast<std::size_t>(field)];
      if (has_dependent_dof(block.eq, target.dependents)) continue;
      for (int i = 0; i < 3; ++i) {
        const int row = block.eq[static_cast<std::size_t>(i)];
        if (row < 0) continue;
        double force = 0.0;
        for (int j = 0; j < 3; ++j) {
          const int column = block.eq[static_cast<std::size_t>(j)];
          if (column >= 0) force += block.m(i, j) * state.a[column];
        }
        inertia_force[row] = force;
        entries.add(field, std::abs(force));
        if (conditions.is_prescribed(row)) continue;
        target.residual[row] += scale * force;
        if (!target.tangent) continue;
        for (int j = 0; j < 3; ++j) {
          const int column = block.eq[static_cast<std::size_t>(j)];
          if (column < 0 || block.m(i, j) == 0.0) continue;
          const double k = stiffness * block.m(i, j);
          if (conditions.is_prescribed(column)) {
            // The prescribed column goes to the right-hand side, as an element's does.
            if (target.predictor) {
              (*target.predictor)[row] += k * (conditions.target(column) - state.x[column]);
            }
            continue;
          }
          const int solved_row = target.dependents.solved(row);
          const int solved_column = target.dependents.solved(column);
          // The upper triangle holds both; under assembly by rows the rank that owns the row
          // adds the entry.
          if (target.symmetric && solved_column < solved_row) continue;
          if (!target.tangent->owns_row(solved_row)) continue;
          const int position = row == column
                                   ? target.diagonal[static_cast<std::size_t>(solved_row)]
                                   : entry_position(*target.tangent, solved_row, solved_column);
          target.tangent->values[static_cast<std::size_t>(position)] += k;
        }
      }
    }
  }
}

void initial_accelerations(std::span<const NodeInertia> inertia,
                           const IncrementConditions& conditions, const Eigen::VectorXd& r,
                           Eigen::VectorXd& a) {
  a.setZero();
  for (const NodeInertia& node : inertia) {
    for (const InertiaBlock& block : blocks_of(node)) {
      // The free DOFs of the block that carry inertia: solve their part of M a = −r.
      std::array<int, 3> local{};
      int count = 0;
      for (int i = 0; i < 3; ++i) {
        const int eq = block.eq[static_cast<std::size_t>(i)];
        if (eq >= 0 && !conditions.is_prescribed(eq) && block.m(i, i) > 0.0) local[count++] = i;
      }
      if (count == 0) continue;
      Eigen::MatrixXd m(count, count);
      Eigen::VectorXd f(count);
      for (int p = 0; p < count; ++p) {
        f[p] = -r[block.eq[static_cast<std::size_t>(local[p])]];
        for (int q = 0; q < count; ++q) m(p, q) = block.m(local[p], local[q]);
      }
      const Eigen::VectorXd solved = m.ldlt().solve(f);
      for (int p = 0; p < count; ++p) a[block.eq[static_cast<std::size_t>(local[p])]] = solved[p];
    }
  }
}

double kinetic_energy(std::span<const NodeInertia> inertia, const Eigen::VectorXd& v,
                      const std::vector<Matrix3>& rotations) {
  double energy = 0.0;
  for (const NodeInertia& node : inertia) {
    const bool finite = has_finite_rotary_inertia(node, !rotations.empty());
    if (finite) {
      const Vector3 omega(v[node.rotation[0]], v[node.rotation[1]], v[node.rotation[2]]);
      energy +=
          finite_rotary_kinetic_energy(node, rotations[static_cast<std::size_t>(node.node)], omega);
    }
    const std::array<InertiaBlock, 2> blocks = blocks_of(node);
    for (int field = 0; field < (finite ? 1 : 2); ++field) {  // translations, then rotations
      const InertiaBlock& block = blocks[static_cast<std::size_t>(field)];
      Vector3 velocity = Vector3::Zero();
      for (int i = 0; i < 3; ++i) {
        const int eq = block.eq[static_cast<std::size_t>(i)];
        if (eq >= 0) velocity[i] = v[eq];
      }
      energy += 0.5 * velocity.dot(block.m * velocity);
    }
  }
  return energy;
}

}  // namespace clinch
