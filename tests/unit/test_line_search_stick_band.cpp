// The line search across a stick band much narrower than the Newton step (line_search.hpp): a
// friction spring (stick stiffness k, capacity F, slip u_s = 0) in parallel with a soft spring
// k_p under a load P, R(u) = clamp(k u, −F, F) + k_p u − P (friction.md §4.1 with F_N fixed).
// With |P| < F (1 + k_p/k) the solution sticks, u* = P/(k + k_p), inside a band of width 2F/k;
// from the slip side the consistent tangent is k_p, and full Newton steps jump across the band
// to the other slip side and back for good. Along a step that crosses the band g(s) = dᵀR(u + s d)
// changes sign on a steep piece 1/100 of the step wide: a secant through (0, g(0)) alone swings
// between s = 1 and s = 0.5 (10 Newton iterations here); inside the bracket where g changes sign
// the search lands in the band, and the next (stick) step is exact.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "src/solver/newton.hpp"
#include "tests/unit/one_unknown_newton.hpp"

namespace clinch {
namespace {

class StickBandProblem final : public OneUnknownProblem {
 public:
  explicit StickBandProblem(double u) : u_(u) {}
  EvalStatus evaluate(Eigen::VectorXd& residual, SparseMatrix* tangent) override {
    residual.resize(1);
    const double trial = kStick * u_;
    const bool sticks = std::abs(trial) <= kCapacity;
    residual[0] = std::clamp(trial, -kCapacity, kCapacity) + kParallel * u_ - kLoad;
    if (tangent) tangent->values[0] = (sticks ? kStick : 0.0) + kParallel;
    return {};
  }
  void apply_correction(const Eigen::VectorXd& correction) override { u_ += correction[0]; }
  void measure(const Eigen::VectorXd& residual, const Eigen::VectorXd* correction,
               IterationNorms& norms) const override {
    norms.largest_residual[0] = norms.residual_norm = std::abs(residual[0]);
    norms.flux[0] = 1.0;  // q̄ = 1: the residual test is |R| ≤ 1e-12
    norms.largest_increment[0] = std::abs(u_ - kStart);
    if (correction)
      norms.largest_correction[0] = norms.correction_norm = std::abs((*correction)[0]);
  }
  double u() const { return u_; }
  static constexpr double kStick = 1e4, kCapacity = 1.0, kParallel = 100.0, kLoad = 0.5;
  static constexpr double kStart = 0.015;  // slipping forward: R = 2, the step d = −0.02

 private:
  double u_;
};

NewtonReport solve(StickBandProblem& p, int line_search_iterations) {
  NewtonOptions options;
  options.line_search.max_iterations = line_search_iterations;
  return solve_one_unknown(p, options);
}

TEST(LineSearchStickBand, FullStepsJumpAcrossTheBandForGood) {
  StickBandProblem p(StickBandProblem::kStart);
  const NewtonReport report = solve(p, 0);
  EXPECT_FALSE(report.converged());
  // u = 0.015 and u = −0.005 in turn: R = ±2 with the slip tangent k_p on both sides.
  EXPECT_TRUE(std::abs(p.u() - 0.015) < 1e-12 || std::abs(p.u() + 0.005) < 1e-12) << p.u();
}

TEST(LineSearchStickBand, TheBracketLandsInTheBand) {
  StickBandProblem p(StickBandProblem::kStart);
  const NewtonReport report = solve(p, 5);  // N_ls = 5, clinch's choice in steps with friction
  ASSERT_TRUE(report.converged()) << report.message;
  // One search into the band, one exact stick step and the check: three corrections at most.
  EXPECT_LE(report.iterations.size(), 4u);
  // u* = P/(k + k_p) in the band (|k u*| = 0.495 < F); |R| ≤ 1e-12 with R' = k + k_p puts u
  // within 1e-16 of it, and the last correction is exact up to the round-off of k u (1e-20).
  const double exact =
      StickBandProblem::kLoad / (StickBandProblem::kStick + StickBandProblem::kParallel);
  EXPECT_NEAR(p.u(), exact, 1e-15);
}

}  // namespace
}  // namespace clinch
