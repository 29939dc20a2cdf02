// The forcing term of an inexact Newton method (Eisenstat and Walker 1996, choice 2): how
// accurately each Newton correction needs to be solved. Far from the solution a loose linear
// solve costs a few iterative-solver steps and loses nothing, since the next residual is
// evaluated exactly; as the residual falls quadratically the term tightens with it, so the
// converged increment is judged by the same criteria as with a direct solver
// (docs/parallel.md "Inexact Newton").
#pragma once

namespace clinch {

class ForcingTerm {
 public:
  // η for the correction of a state whose residual norm is `residual_norm` (iteration `k` of the
  // increment, 0 first): η_0 = kFirst, then η_k = γ (‖r_k‖ / ‖r_{k−1}‖)² with the safeguard
  // η_k ≥ γ η_{k−1}² while that exceeds 0.1, clamped to [kSmallest, kLargest].
  double next(int k, double residual_norm);

  static constexpr double kFirst = 0.1;
  static constexpr double kGamma = 0.9;
  static constexpr double kLargest = 0.5;
  // Below this an iterative solve costs as much as a tight one and gains nothing.
  static constexpr double kSmallest = 1e-10;

 private:
  double previous_norm_ = 0;
  double previous_eta_ = kFirst;
};

}  // namespace clinch
