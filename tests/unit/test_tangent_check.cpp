// check_assembled_tangent (src/solver/tangent_check.hpp), the comparison behind
// `clinch run --check-tangent`, on a linear problem r = A x whose tangent is stored in full
// (A unsymmetric) or as the upper triangle of a symmetric A: the whole matrix is read in either
// storage, prescribed equations are left out, and the state is left as it was.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "src/solver/tangent_check.hpp"

namespace clinch {
namespace {

class LinearProblem : public NonlinearProblem {
 public:
  LinearProblem(const Eigen::Matrix3d& a, bool symmetric_upper) : a_(a), x_(0.2, -0.1, 0.4) {
    pattern_.n = 3;
    pattern_.symmetric_upper = symmetric_upper;
    pattern_.col_ptr = {0};
    for (int j = 0; j < 3; ++j) {
      for (int i = 0; i <= (symmetric_upper ? j : 2); ++i) pattern_.row_idx.push_back(i);
      pattern_.col_ptr.push_back(static_cast<int>(pattern_.row_idx.size()));
    }
    pattern_.values.assign(pattern_.row_idx.size(), 0.0);
  }
  int size() const override { return 3; }
  const SparseMatrix& pattern() const override { return pattern_; }
  EvalStatus evaluate(Eigen::VectorXd& residual, SparseMatrix* tangent) override {
    residual = a_ * x_;
    if (tangent) {
      for (int j = 0; j < 3; ++j) {
        for (int p = tangent->col_ptr[j]; p < tangent->col_ptr[j + 1]; ++p) {
          tangent->values[p] = a_(tangent->row_idx[p], j);
        }
      }
    }
    return {};
  }
  void apply_correction(const Eigen::VectorXd& correction) override { x_ += correction; }
  void measure(const Eigen::VectorXd&, const Eigen::VectorXd*, IterationNorms&) const override {}
  const Eigen::Vector3d& state() const { return x_; }

 private:
  Eigen::Matrix3d a_;
  Eigen::Vector3d x_;
  SparseMatrix pattern_;
};

SparseMatrix assembled(LinearProblem& problem) {
  SparseMatrix k = problem.pattern();
  Eigen::VectorXd r;
  problem.evaluate(r, &k);
  return k;
}

TEST(TangentCheck, FullStorageOfAnUnsymmetricTangentIsReadWhole) {
  Eigen::Matrix3d a;
  a << 4, 1, 0, 3, 5, -2, 0.5, 2, 6;
  LinearProblem problem(a, false);
  const Eigen::Vector3d before = problem.state();
  const SparseMatrix k = assembled(problem);
  const JacobianReport r = check_assembled_tangent(problem, k, Eigen::Vector3d::Constant(1e-6));
  EXPECT_EQ(r.compared, 9);
  EXPECT_TRUE(r.passes(1e-8, 0)) << r;
  EXPECT_TRUE((problem.state() - before).isZero(1e-15));
  // Its symmetric part differs from A: the comparison with ½(J + Jᵀ) must fail.
  EXPECT_FALSE(
      check_assembled_tangent(problem, k, Eigen::Vector3d::Constant(1e-6), true).passes(1e-3, 0));
}

TEST(TangentCheck, SymmetricUpperStorageIsMirrored) {
  Eigen::Matrix3d a;
  a << 4, 1, 0.5, 1, 5, 2, 0.5, 2, 6;
  LinearProblem problem(a, true);
  const SparseMatrix k = assembled(problem);
  const JacobianReport r = check_assembled_tangent(problem, k, Eigen::Vector3d::Constant(1e-6));
  EXPECT_EQ(r.compared, 9);
  EXPECT_TRUE(r.passes(1e-8, 0)) << r;
}

TEST(TangentCheck, PrescribedEquationsAreLeftOut) {
  Eigen::Matrix3d a;
  a << 4, 1, 0, 3, 5, -2, 0.5, 2, 6;
  // Upper storage of an unsymmetric A: the mirrored (1, 0), (2, 0), (2, 1) are wrong.
  LinearProblem problem(a, true);
  const SparseMatrix k = assembled(problem);
  const JacobianReport all = check_assembled_tangent(problem, k, Eigen::Vector3d::Constant(1e-6));
  EXPECT_FALSE(all.passes(1e-3, 0));
  ASSERT_FALSE(all.entries.empty());
  EXPECT_EQ(all.entries[0].row, 2);  // |−2 − 2| is the largest error
  EXPECT_EQ(all.entries[0].column, 1);
  // Equation 0 and 2 prescribed: only (1, 1) is compared, and it is right.
  const JacobianReport free = check_assembled_tangent(problem, k, Eigen::Vector3d(0, 1e-6, 0));
  EXPECT_EQ(free.compared, 1);
  EXPECT_TRUE(free.passes(1e-8, 0)) << free;
}

}  // namespace
}  // namespace clinch
