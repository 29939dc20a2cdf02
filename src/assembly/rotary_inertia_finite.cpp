#include "src/assembly/rotary_inertia_finite.hpp"

#include <cmath>

#include "src/assembly/sparsity_pattern.hpp"
#include "src/kinematics/rotation_math.hpp"

namespace clinch {
namespace {

Vector3 rotation_values(const Eigen::VectorXd& values, const std::array<int, 3>& eq) {
  return {values[eq[0]], values[eq[1]], values[eq[2]]};
}

// T(Θ)⁻¹ = I − Θ̂/2 + (1/θ² − (1 + cos θ)/(2θ sin θ)) Θ̂²; the series near θ = 0.
Matrix3 inverse_left_jacobian(const Vector3& theta) {
  const double t = theta.norm();
  const Matrix3 w = skew(theta);
  const double c = t < 1e-4 ? 1.0 / 12.0 + t * t / 720.0
                            : 1.0 / (t * t) - (1.0 + std::cos(t)) / (2.0 * t * std::sin(t));
  return Matrix3::Identity() - 0.5 * w + c * w * w;
}

struct Increment {
  Matrix3 r0, r1;
  Vector3 theta, w0, w1;  // Θ, W₀, W₁
};

Increment increment_of(const NodeInertia& node, double dt, const AnalysisState& state) {
  const auto n = static_cast<std::size_t>(node.node);
  Increment inc;
  inc.r0 = state.rotation_n[n];
  inc.r1 = state.rotation[n];
  inc.theta = rotation_log(inc.r0.transpose() * inc.r1);
  inc.w0 = inc.r0.transpose() * rotation_values(state.v_n, node.rotation);
  inc.w1 = 2.0 / dt * inc.theta - inc.w0;
  return inc;
}

}  // namespace

bool has_finite_rotary_inertia(const NodeInertia& node, bool nlgeom) {
  return nlgeom && !node.rotary.isZero() && node.rotation[0] >= 0 && node.rotation[1] >= 0 &&
         node.rotation[2] >= 0;
}

void update_finite_rotary_rates(std::span<const NodeInertia> inertia, double dt,
                                AnalysisState& state) {
  if (dt <= 0.0) return;  // no increment: the rates stay those of the converged state
  for (const NodeInertia& node : inertia) {
    if (!has_finite_rotary_inertia(node, !state.rotation.empty())) continue;
    const Increment inc = increment_of(node, dt, state);
    const Vector3 omega = inc.r1 * inc.w1;
    const Vector3 alpha = inc.r1 * ((inc.w1 - inc.w0) / dt);
    for (int k = 0; k < 3; ++k) {
      state.v[node.rotation[static_cast<std::size_t>(k)]] = omega[k];
      state.a[node.rotation[static_cast<std::size_t>(k)]] = alpha[k];
    }
  }
}

void add_finite_rotary_inertia(std::span<const NodeInertia> inertia, double dt,
                               const AnalysisState& state, const IncrementConditions& conditions,
                               InertiaTarget target, Eigen::VectorXd& inertia_force,
                               ForceEntries& entries) {
  if (dt <= 0.0) return;  // the step's start: no increment to balance
  for (const NodeInertia& node : inertia) {
    if (!has_finite_rotary_inertia(node, !state.rotation.empty())) continue;
    const Increment inc = increment_of(node, dt, state);
    const Vector3 pi0 = inc.r0 * (node.rotary * inc.w0);
    const Vector3 pi1 = inc.r1 * (node.rotary * inc.w1);
    const Vector3 moment = 2.0 / dt * (pi1 - pi0) + rotation_values(state.r_n, node.rotation);
    const Matrix3 k = 2.0 / dt *
                      (-skew(pi1) + 2.0 / dt * inc.r1 * node.rotary *
                                        inverse_left_jacobian(inc.theta) * inc.r0.transpose());
    for (int i = 0; i < 3; ++i) {
      const int row = node.rotation[static_cast<std::size_t>(i)];
      inertia_force[row] = moment[i];
      entries.add(1, std::abs(moment[i]));
      if (conditions.is_prescribed(row)) continue;
      target.residual[row] += moment[i];
      if (!target.tangent) continue;
      for (int j = 0; j < 3; ++j) {
        const int column = node.rotation[static_cast<std::size_t>(j)];
        if (conditions.is_prescribed(column)) {
          if (target.predictor) {
            (*target.predictor)[row] += k(i, j) * (conditions.target(column) - state.x[column]);
          }
          continue;
        }
        // The tangent is over the solved equations (dependent ones eliminated before them).
        const int solved_row = target.dependents.solved(row);
        const int solved_column = target.dependents.solved(column);
        double value = k(i, j);
        if (target.symmetric) {
          if (solved_column < solved_row) continue;  // the upper triangle holds both: their mean
          value = 0.5 * (k(i, j) + k(j, i));
        }
        // Under assembly by rows the rank that owns the row adds the entry.
        if (!target.tangent->owns_row(solved_row)) continue;
        const int position = row == column
                                 ? target.diagonal[static_cast<std::size_t>(solved_row)]
                                 : entry_position(*target.tangent, solved_row, solved_column);
        target.tangent->values[static_cast<std::size_t>(position)] += value;
      }
    }
  }
}

double finite_rotary_kinetic_energy(const NodeInertia& node, const Matrix3& rotation,
                                    const Vector3& omega) {
  const Vector3 w = rotation.transpose() * omega;
  return 0.5 * w.dot(node.rotary * w);
}

}  // namespace clinch
