#include "src/solver/line_search.hpp"

#include <algorithm>
#include <cmath>

namespace clinch {

EvalStatus search_line(NonlinearProblem& problem, Eigen::VectorXd& direction,
                       Eigen::VectorXd& residual, const LineSearchControls& controls) {
  // Only ratios of the projections g(s) = d·r(s) matter: they are taken on d and r scaled by
  // their largest entries at s = 0, so that residuals past 1e154 do not overflow them.
  // Over the owned entries of every process of a problem shared by rows (nonlinear_problem.hpp).
  const Eigen::Index owned = problem.owned_size();
  const auto inverse_of_largest = [&](const Eigen::VectorXd& v) {
    const double largest =
        problem.max_over_ranks(owned > 0 ? v.head(owned).cwiseAbs().maxCoeff() : 0.0);
    return largest > 0 && std::isfinite(largest) ? 1.0 / largest : 1.0;
  };
  const double direction_scale = inverse_of_largest(direction);
  const double residual_scale = inverse_of_largest(residual);
  const auto projection = [&] {
    return problem.sum_over_ranks(((direction.head(owned).array() * direction_scale) *
                                   (residual.head(owned).array() * residual_scale))
                                      .sum());
  };
  const double g0 = projection();
  // A correction orthogonal to the residual, as when the only imbalance is a load on a
  // constrained direction and the multiplier alone restores it (d has no entry where R has one),
  // gives g(0) = 0 up to round-off: g then says nothing about the step, whose sign would come from
  // round-off elsewhere, and the full step is kept.
  const auto norm = [&](const Eigen::VectorXd& v, double scale) {
    return std::sqrt(problem.sum_over_ranks((v.head(owned) * scale).squaredNorm()));
  };
  const double informative =
      1e-10 * norm(direction, direction_scale) * norm(residual, residual_scale);
  EvalStatus status = problem.evaluate(residual, nullptr);
  // Only a descent direction (g(0) < 0) has a step that reduces the projected residual.
  if (!status.ok || !(g0 < -informative)) return status;
  // g changes sign between `low` (g < 0, s = 0 at first) and `high` once a step has overshot
  // (g > 0). A stick–slip switch makes g piecewise linear with a steep piece as narrow as the
  // stick band: a secant through (0, g(0)) and the last point alone then swings between s_max and
  // f_s·s without ever landing in it, so the zero is sought inside the bracket (regula falsi,
  // Illinois variant: the end kept twice in a row has its g halved, so both ends move).
  double s = 1.0, g = projection();
  double low = 0.0, g_low = g0, high = -1.0, g_high = 0.0;
  int kept = 0;  // +1: `low` was kept in the last update, −1: `high`
  double best = s, g_best = std::abs(g);
  for (int iteration = 0; iteration < controls.max_iterations; ++iteration) {
    if (std::abs(g) <= controls.eta * std::abs(g0)) break;
    double next;
    if (g > 0) {
      if (kept == 1) g_low *= 0.5;
      high = s, g_high = g, kept = 1;
    } else {
      if (kept == -1) g_high *= 0.5;
      low = s, g_low = g, kept = high < 0 ? 0 : -1;
    }
    if (high >= 0) {
      next = low - g_low * (high - low) / (g_high - g_low);
    } else {
      // No overshoot yet: the zero of the secant through (0, g0) and (s, g); with g ≤ g0 the
      // secant has no zero ahead and the step grows to s_max.
      next = g > g0 ? s * g0 / (g0 - g) : controls.s_max;
    }
    // keywords.md §16: f_s limits the change of s in one iteration (here: how far it may fall).
    next = std::clamp(next, std::max(controls.f_s * s, controls.s_min), controls.s_max);
    if (next == s) break;
    problem.apply_correction((next - s) * direction);
    s = next;
    status = problem.evaluate(residual, nullptr);
    if (!status.ok) break;
    g = projection();
    if (std::abs(g) < g_best) best = s, g_best = std::abs(g);
  }
  // The search ends on the best step it evaluated, never on one it has not checked.
  if (status.ok && best != s) {
    problem.apply_correction((best - s) * direction);
    s = best;
    status = problem.evaluate(residual, nullptr);
  }
  direction *= s;
  return status;
}

}  // namespace clinch
