#include "src/solver/line_search.hpp"

#include <algorithm>
#include <cmath>

namespace clinch {

EvalStatus search_line(NonlinearProblem& problem, Eigen::VectorXd& direction,
                       Eigen::VectorXd& residual, const LineSearchControls& controls) {
  // Only ratios of the projections g(s) = d·r(s) matter: they are taken on d and r scaled by
  // their largest entries at s = 0, so that residuals past 1e154 do not overflow them.
  const auto inverse_of_largest = [](const Eigen::VectorXd& v) {
    const double largest = v.size() > 0 ? v.cwiseAbs().maxCoeff() : 0.0;
    return largest > 0 && std::isfinite(largest) ? 1.0 / largest : 1.0;
  };
  const double direction_scale = inverse_of_largest(direction);
  const double residual_scale = inverse_of_largest(residual);
  const auto projection = [&] {
    return ((direction.array() * direction_scale) * (residual.array() * residual_scale)).sum();
  };
  const double g0 = projection();
  // A correction orthogonal to the residual, as when the only imbalance is a load on a
  // constrained direction and the multiplier alone restores it (d has no entry where R has one),
  // gives g(0) = 0 up to round-off: g then says nothing about the step, whose sign would come from
  // round-off elsewhere, and the full step is kept.
  const double informative =
      1e-10 * (direction * direction_scale).norm() * (residual * residual_scale).norm();
  EvalStatus status = problem.evaluate(residual, nullptr);
  // Only a descent direction (g(0) < 0) has a step that reduces the projected residual.
  if (!status.ok || !(g0 < -informative)) return status;
  double s = 1.0;
  for (int iteration = 0; iteration < controls.max_iterations; ++iteration) {
    const double g = projection();
    if (std::abs(g) <= controls.eta * std::abs(g0)) break;
    // Zero of the line through (0, g0) and (s, g); with g ≤ g0 the secant has no zero ahead
    // and the step grows to s_max.
    double next = g > g0 ? s * g0 / (g0 - g) : controls.s_max;
    // keywords.md §16: f_s limits the change of s in one iteration (here: how far it may fall).
    next = std::clamp(next, std::max(controls.f_s * s, controls.s_min), controls.s_max);
    if (next == s) break;
    problem.apply_correction((next - s) * direction);
    s = next;
    status = problem.evaluate(residual, nullptr);
    if (!status.ok) break;
  }
  direction *= s;
  return status;
}

}  // namespace clinch
