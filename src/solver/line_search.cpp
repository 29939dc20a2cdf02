#include "src/solver/line_search.hpp"

#include <algorithm>
#include <cmath>

namespace clinch {

LineSearchResult search_line(NonlinearProblem& problem, const Eigen::VectorXd& direction,
                             double g0, Eigen::VectorXd& residual,
                             const LineSearchOptions& options) {
  LineSearchResult result;
  // Only a descent direction (g(0) < 0) has a step that reduces the projected residual.
  if (!(g0 < 0)) return result;
  double s = 1.0;
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    const double g = direction.dot(residual);
    if (std::abs(g) <= options.eta * std::abs(g0)) break;
    // Zero of the line through (0, g0) and (s, g); with g ≤ g0 the secant has no zero ahead
    // and the step grows to s_max.
    double next = g > g0 ? s * g0 / (g0 - g) : options.s_max;
    // keywords.md §16: f_s limits the change of s in one iteration (here: how far it may fall).
    next = std::clamp(next, std::max(options.f_s * s, options.s_min), options.s_max);
    if (next == s) break;
    problem.apply_correction((next - s) * direction);
    s = next;
    result.status = problem.evaluate(residual, nullptr);
    ++result.evaluations;
    if (!result.status.ok) break;
  }
  result.step = s;
  return result;
}

}  // namespace clinch
