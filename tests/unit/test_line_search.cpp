// The line search of *CONTROLS, PARAMETERS=LINE SEARCH (keywords.md §16) on a problem where full
// Newton steps fail: R(x) = atan(x) − atan(0.2) from x = 3. The tangent 1/(1 + x²) is so flat
// out there that full steps overshoot farther and farther (Newton diverges for |x − 0.2| beyond
// about 1.4); with the line search the projected residual g(s) = dᵀR(x + s d) is driven down
// along each step and Newton converges to x = 0.2.
#include <gtest/gtest.h>

#include <cmath>

#include "src/linalg/linear_solver.hpp"
#include "src/solver/newton.hpp"

namespace clinch {
namespace {

class ArctanProblem final : public NonlinearProblem {
 public:
  explicit ArctanProblem(double x) : x_(x), x0_(x) {
    pattern_.n = 1;
    pattern_.col_ptr = {0, 1};
    pattern_.row_idx = {0};
    pattern_.values = {0.0};
    pattern_.symmetric_upper = true;
  }
  int size() const override { return 1; }
  const SparseMatrix& pattern() const override { return pattern_; }
  EvalStatus evaluate(Eigen::VectorXd& residual, SparseMatrix* tangent) override {
    residual.resize(1);
    residual[0] = std::atan(x_) - std::atan(kRoot);
    if (tangent) tangent->values[0] = 1.0 / (1.0 + x_ * x_);
    ++evaluations;
    return {};
  }
  void apply_correction(const Eigen::VectorXd& correction) override { x_ += correction[0]; }
  void measure(const Eigen::VectorXd& residual, const Eigen::VectorXd* correction,
               IterationNorms& norms) const override {
    norms.largest_residual[0] = std::abs(residual[0]);
    norms.flux[0] = 1.0;  // q̄ = 1: the residual test is |R| ≤ Rₙ
    norms.largest_increment[0] = std::abs(x_ - x0_);
    if (correction) norms.largest_correction[0] = std::abs((*correction)[0]);
  }
  void commit() override { x0_ = x_; }
  void revert() override { x_ = x0_; }
  double x() const { return x_; }
  int evaluations = 0;
  static constexpr double kRoot = 0.2;

 private:
  double x_, x0_;
  SparseMatrix pattern_;
};

NewtonReport solve(ArctanProblem& p, const LineSearchControls& line_search) {
  Controls controls;
  controls.translation.residual = 1e-12;
  controls.translation.correction = 1e-12;
  ConvergenceCriteria criteria(controls);
  auto solver = make_linear_solver(SolverChoice::Dense, true, false);
  std::string message;
  EXPECT_EQ(solver->analyze(p.pattern(), &message), LinearStatus::Ok) << message;
  NewtonOptions options;
  options.max_iterations = 30;
  options.divergence_check_from = 30;
  options.line_search = line_search;
  return solve_increment(p, *solver, criteria, options);
}

TEST(LineSearch, FullNewtonStepsDivergeOnTheFlatTail) {
  ArctanProblem p(3.0);
  const NewtonReport report = solve(p, LineSearchControls{});
  EXPECT_FALSE(report.converged());
  EXPECT_GT(std::abs(p.x()), 3.0);  // the iterates run away
}

TEST(LineSearch, ConvergesWhereFullStepsDiverge) {
  ArctanProblem p(3.0);
  LineSearchControls ls;
  ls.max_iterations = 5;  // N_ls; s_max, s_min, f_s, η_ls at their defaults
  const NewtonReport report = solve(p, ls);
  ASSERT_TRUE(report.converged()) << report.message;
  // |R| ≤ 1e-12 at the end, and R' ≈ 1/(1 + 0.04) there: x within about 1e-12 of the root.
  EXPECT_NEAR(p.x(), ArctanProblem::kRoot, 1e-11);
  EXPECT_LE(report.iterations.size(), 20u);
}

TEST(LineSearch, LeavesAGoodStepAlone) {
  // Near the root the full step already reduces g(1) below η_ls|g(0)|: s stays 1, so the line
  // search costs one residual evaluation per iteration and changes nothing.
  ArctanProblem with(0.3), without(0.3);
  LineSearchControls ls;
  ls.max_iterations = 5;
  const NewtonReport a = solve(with, ls), b = solve(without, LineSearchControls{});
  ASSERT_TRUE(a.converged());
  ASSERT_TRUE(b.converged());
  EXPECT_EQ(a.iterations.size(), b.iterations.size());
  EXPECT_EQ(with.x(), without.x());
}

}  // namespace
}  // namespace clinch
