// Newton stops on a residual or a correction that is not finite (ARCHITECTURE.md principle 8)
// instead of letting it through the convergence tests, which a NaN passes. Two uncoupled
// springs, R = k∘x − f, solved by the dense backend: the report names the equation and the
// state is left as the last finite iterate, for the step driver to revert and cut back.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "src/linalg/linear_solver.hpp"
#include "src/solver/newton.hpp"

namespace clinch {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

class TwoSprings final : public NonlinearProblem {
 public:
  TwoSprings(Eigen::Vector2d k, Eigen::Vector2d f) : k_(k), f_(f) {
    pattern_.n = 2;
    pattern_.col_ptr = {0, 1, 2};
    pattern_.row_idx = {0, 1};
    pattern_.values = {0.0, 0.0};
    pattern_.symmetric_upper = true;
  }
  int size() const override { return 2; }
  const SparseMatrix& pattern() const override { return pattern_; }
  EvalStatus evaluate(Eigen::VectorXd& residual, SparseMatrix* tangent) override {
    residual = k_.cwiseProduct(x_) - f_;
    if (tangent) tangent->values = {k_[0], k_[1]};
    return {};
  }
  void apply_correction(const Eigen::VectorXd& correction) override { x_ += correction; }
  void measure(const Eigen::VectorXd& residual, const Eigen::VectorXd* correction,
               IterationNorms& norms) const override {
    norms.largest_residual[0] = residual.cwiseAbs().maxCoeff();
    norms.flux[0] = 1.0;
    norms.largest_increment[0] = x_.cwiseAbs().maxCoeff();
    if (correction) norms.largest_correction[0] = correction->cwiseAbs().maxCoeff();
  }
  const Eigen::Vector2d& x() const { return x_; }

 private:
  Eigen::Vector2d k_, f_, x_ = Eigen::Vector2d::Zero();
  SparseMatrix pattern_;
};

NewtonReport solve(TwoSprings& p) {
  ConvergenceCriteria criteria(Controls{});
  auto solver = make_linear_solver(SolverChoice::Dense, true, false);
  std::string message;
  EXPECT_EQ(solver->analyze(p.pattern(), &message), LinearStatus::Ok) << message;
  return solve_increment(p, *solver, criteria, NewtonOptions{});
}

// 1e308 / 1e-3 overflows in the solve: the correction of equation 1 is infinite, and it is not
// applied.
TEST(NewtonNonFinite, AnOverflowingCorrectionStopsAtItsEquation) {
  TwoSprings p({1.0, 1e-3}, {1.0, 1e308});
  const NewtonReport report = solve(p);
  EXPECT_EQ(report.outcome, NewtonOutcome::NonFinite);
  EXPECT_EQ(report.failed_equation, 1);
  EXPECT_EQ(report.message, "the correction is inf");
  EXPECT_TRUE(p.x().allFinite());
}

// A residual with a NaN at equation 0 and an infinity at equation 1 blames the infinity, where
// an overflow starts; no iteration is recorded for a state that cannot be measured.
TEST(NewtonNonFinite, AResidualNamesTheOverflowBeforeTheNaN) {
  TwoSprings p({1.0, 1.0}, {kNaN, kInf});
  const NewtonReport report = solve(p);
  EXPECT_EQ(report.outcome, NewtonOutcome::NonFinite);
  EXPECT_EQ(report.failed_equation, 1);
  EXPECT_EQ(report.message, "the residual is -inf");
  EXPECT_TRUE(report.iterations.empty());
}

// A NaN alone is named where it is (its sign, which fmt prints, is the hardware's choice).
TEST(NewtonNonFinite, ANaNResidualIsNamed) {
  TwoSprings p({1.0, 1.0}, {1.0, kNaN});
  const NewtonReport report = solve(p);
  EXPECT_EQ(report.outcome, NewtonOutcome::NonFinite);
  EXPECT_EQ(report.failed_equation, 1);
  EXPECT_TRUE(report.message == "the residual is nan" || report.message == "the residual is -nan")
      << report.message;
}

}  // namespace
}  // namespace clinch
