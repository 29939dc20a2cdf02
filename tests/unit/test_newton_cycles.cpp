// Newton's way out of a cycle under fixed increments (NewtonOptions::break_cycles): on
// R(x) = x³ − 2x + 2 from x = 0, full Newton steps cycle for good, 0 → 1 → 0 → 1 (R' = −2 at 0 and
// 1 at 1, so each step is exactly ±1). With break_cycles the first revisited state (x = 1 again,
// the same |R| = 1 and |Δx| = 1) takes half its correction, x = 0.5, from where Newton reaches the
// real root x* = −1.76929235… (the only one: the discriminant of the cubic is negative).
#include <gtest/gtest.h>

#include <cmath>

#include "src/solver/newton.hpp"
#include "tests/unit/one_unknown_newton.hpp"

namespace clinch {
namespace {

constexpr double kRoot = -1.7692923542386314;  // x³ − 2x + 2 = 0 (Cardano), to 17 digits

class CyclingCubic final : public OneUnknownProblem {
 public:
  EvalStatus evaluate(Eigen::VectorXd& residual, SparseMatrix* tangent) override {
    residual.resize(1);
    residual[0] = x_ * x_ * x_ - 2.0 * x_ + 2.0;
    if (tangent) tangent->values[0] = 3.0 * x_ * x_ - 2.0;
    return {};
  }
  void apply_correction(const Eigen::VectorXd& correction) override { x_ += correction[0]; }
  void measure(const Eigen::VectorXd& residual, const Eigen::VectorXd* correction,
               IterationNorms& norms) const override {
    norms.largest_residual[0] = norms.residual_norm = std::abs(residual[0]);
    norms.flux[0] = 1.0;  // q̄ = 1: the residual test is |R| ≤ Rₙ
    norms.largest_increment[0] = std::abs(x_);
    if (correction)
      norms.largest_correction[0] = norms.correction_norm = std::abs((*correction)[0]);
  }
  double x() const { return x_; }

 private:
  double x_ = 0.0;
};

NewtonReport solve(CyclingCubic& p, bool break_cycles) {
  NewtonOptions options;
  options.break_cycles = break_cycles;
  return solve_one_unknown(p, options);
}

TEST(NewtonCycles, FullStepsCycleForGood) {
  CyclingCubic p;
  const NewtonReport report = solve(p, false);
  EXPECT_EQ(report.outcome, NewtonOutcome::TooManyIterations);
  EXPECT_TRUE(p.x() == 0.0 || p.x() == 1.0) << p.x();  // still on the cycle, exactly
}

TEST(NewtonCycles, AHalfStepLeavesTheCycle) {
  CyclingCubic p;
  const NewtonReport report = solve(p, true);
  ASSERT_TRUE(report.converged()) << report.message;
  // Newton stops where the criteria of keywords.md §16 pass, 1.3e-11 from the root here; within
  // 1e-9 of it, the only real root, the iterate has left the cycle for good.
  EXPECT_NEAR(p.x(), kRoot, 1e-9);
}

}  // namespace
}  // namespace clinch
