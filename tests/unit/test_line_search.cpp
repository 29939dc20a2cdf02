// The line search of *CONTROLS, PARAMETERS=LINE SEARCH (keywords.md §16) on a problem where full
// Newton steps fail: R(x) = atan(x) − atan(0.2) from x = 3. The tangent 1/(1 + x²) is so flat
// out there that full steps overshoot farther and farther (Newton diverges for |x − 0.2| beyond
// about 1.4); with the line search the projected residual g(s) = dᵀR(x + s d) is driven down
// along each step and Newton converges to x = 0.2.
#include <gtest/gtest.h>

#include <cmath>

#include "src/solver/newton.hpp"
#include "tests/unit/one_unknown_newton.hpp"

namespace clinch {
namespace {

class ArctanProblem final : public OneUnknownProblem {
 public:
  explicit ArctanProblem(double x) : x_(x), x0_(x) {}
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
  double x() const { return x_; }
  int evaluations = 0;
  static constexpr double kRoot = 0.2;

 private:
  double x_, x0_;
};

NewtonReport solve(ArctanProblem& p, const LineSearchControls& line_search) {
  NewtonOptions options;
  options.line_search = line_search;
  return solve_one_unknown(p, options);
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

// A load P on a constrained direction (connection-types.md §3.8): unknowns (v, u, λ) with
// R_v = k v − F + e, R_u = λ − P, R_λ = u. The Newton correction restores R_u through λ alone, so
// it is orthogonal to that part of the residual, and g(0) = dᵀR is the round-off of R_v: e
// alternates between ±1e-12 at every evaluation, as the round-off of a converged friction row did.
// The line search must keep the full step (λ = P after one iteration); steered by e it took
// s = 1/3 and the multiplier crept towards P.
class ConstrainedLoadProblem final : public NonlinearProblem {
 public:
  ConstrainedLoadProblem() {
    pattern_.n = 3;
    pattern_.col_ptr = {0, 1, 2, 3};
    pattern_.row_idx = {0, 2, 1};  // K_vv = k, K_λu = K_uλ = 1
    pattern_.values = {kK, 1.0, 1.0};
  }
  int size() const override { return 3; }
  const SparseMatrix& pattern() const override { return pattern_; }
  EvalStatus evaluate(Eigen::VectorXd& residual, SparseMatrix* tangent) override {
    residual.resize(3);
    noise_ = -noise_;
    residual << kK * x_[0] - kF + noise_, x_[2] - kP, x_[1];
    if (tangent) tangent->values = pattern_.values;
    return {};
  }
  void apply_correction(const Eigen::VectorXd& correction) override { x_ += correction; }
  void measure(const Eigen::VectorXd& residual, const Eigen::VectorXd* correction,
               IterationNorms& norms) const override {
    norms.largest_residual[0] = residual.head<2>().cwiseAbs().maxCoeff();
    norms.flux[0] = kP;
    norms.largest_increment[0] = x_.head<2>().cwiseAbs().maxCoeff();
    if (correction) norms.largest_correction[0] = correction->head<2>().cwiseAbs().maxCoeff();
  }
  double multiplier() const { return x_[2]; }
  static constexpr double kK = 1e4, kF = 50.0, kP = 10.0;

 private:
  Eigen::Vector3d x_{kF / kK, 0.0, 0.0};
  double noise_ = 1e-12;
  SparseMatrix pattern_;
};

TEST(LineSearch, KeepsTheFullStepOfACorrectionOrthogonalToTheResidual) {
  ConstrainedLoadProblem p;
  Controls controls;
  controls.translation.residual = 1e-9;
  controls.translation.correction = 1e-9;
  ConvergenceCriteria criteria(controls);
  auto solver = make_linear_solver(SolverChoice::Dense, false, false);
  std::string message;
  ASSERT_EQ(solver->analyze(p.pattern(), &message), LinearStatus::Ok) << message;
  NewtonOptions options;
  options.max_iterations = 16;
  options.line_search.max_iterations = 5;
  const NewtonReport report = solve_increment(p, *solver, criteria, options);
  ASSERT_TRUE(report.converged()) << report.message;
  EXPECT_LE(report.iterations.size(), 3u);
  EXPECT_NEAR(p.multiplier(), ConstrainedLoadProblem::kP, 1e-12);
}

}  // namespace
}  // namespace clinch
