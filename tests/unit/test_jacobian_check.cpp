// The shared finite-difference checker (base/jacobian_check.hpp) on functions with known
// Jacobians: the report's numbers and ordering, the §1.4 pass rule of behaviors.md, left-out
// rows and columns, the symmetric part, failed evaluations and NaN; and entry() reading a sparse
// tangent in full and in symmetric-upper storage.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "base/jacobian_check.hpp"
#include "src/linalg/sparse_matrix.hpp"

namespace clinch {
namespace {

// f(x) = (x0² x1, sin x1, x0 + 3 x1) at (1.5, 0.7).
bool smooth(const Eigen::VectorXd& x, Eigen::VectorXd& f) {
  f.resize(3);
  f << x[0] * x[0] * x[1], std::sin(x[1]), x[0] + 3 * x[1];
  return true;
}

Eigen::Vector2d point() { return {1.5, 0.7}; }

Eigen::MatrixXd smooth_jacobian() {
  const Eigen::Vector2d x = point();
  Eigen::MatrixXd d(3, 2);
  d << 2 * x[0] * x[1], x[0] * x[0], 0, std::cos(x[1]), 1, 3;
  return d;
}

JacobianReport check(const Eigen::MatrixXd& analytic, const JacobianCheckOptions& options = {}) {
  return check_jacobian(perturb_additively(smooth, point()), Eigen::Vector2d::Constant(1e-6),
                        analytic, options);
}

TEST(JacobianCheck, ExactJacobianPasses) {
  const JacobianReport r = check(smooth_jacobian());
  EXPECT_TRUE(r.evaluated());
  EXPECT_EQ(r.rows, 3);
  EXPECT_EQ(r.columns, 2);
  EXPECT_EQ(r.compared, 6);
  EXPECT_EQ(r.entries.size(), 5u);  // the (1, 0) zero is differenced to exactly 0
  EXPECT_DOUBLE_EQ(r.largest_analytic, 3.0);
  // Truncation h²|f'''|/6 and round-off ε|f|/h: about 1e-10 here.
  EXPECT_LT(r.max_error, 1e-8);
  EXPECT_NEAR(r.largest_numeric, 3.0, 1e-8);
  EXPECT_TRUE(r.passes(1e-5, 0.0));
  EXPECT_TRUE(r.meets_tangent_rule(0.0));
  for (std::size_t e = 1; e < r.entries.size(); ++e) {
    EXPECT_GE(r.entries[e - 1].error, r.entries[e].error);
  }
}

TEST(JacobianCheck, WrongEntryFailsAndIsReportedFirst) {
  Eigen::MatrixXd d = smooth_jacobian();
  d(2, 1) += 1e-3;  // 3.3e-4 of the largest entry
  const JacobianReport r = check(d);
  EXPECT_FALSE(r.meets_tangent_rule(1.0));
  EXPECT_TRUE(r.passes(1e-3, 0.0));
  EXPECT_TRUE(r.meets_tangent_rule(1e5));  // the stiffness term of §1.4 covers 1e-3
  ASSERT_FALSE(r.entries.empty());
  EXPECT_EQ(r.entries[0].row, 2);
  EXPECT_EQ(r.entries[0].column, 1);
  EXPECT_NEAR(r.entries[0].error, 1e-3, 1e-8);
  EXPECT_DOUBLE_EQ(r.max_error, r.entries[0].error);
  EXPECT_NE(r.summary().find("at [2,1]"), std::string::npos) << r.summary();
  const std::string table = r.table(1, "K");
  EXPECT_EQ(table.rfind("\n  K[2,1] = 3.001, finite difference 3", 0), 0u) << table;
  EXPECT_EQ(table.find('\n', 1), std::string::npos) << "one line only:" << table;
  std::ostringstream os;
  os << r;
  EXPECT_NE(os.str().find("D[2,1]"), std::string::npos) << os.str();
}

TEST(JacobianCheck, LeftOutColumnsAndRowsAreNotCompared) {
  Eigen::MatrixXd d = smooth_jacobian();
  d(0, 1) = 99;  // wrong, in a column left out
  d(1, 0) = 99;  // wrong, in a row left out
  int evaluations = 0;
  const PerturbedFunction f = [&](int column, double step, Eigen::VectorXd& value) {
    ++evaluations;
    EXPECT_EQ(column, 0);
    Eigen::VectorXd x = point();
    x[column] += step;
    return smooth(x, value);
  };
  JacobianCheckOptions options;
  options.compare_row = [](int i) { return i != 1; };
  const JacobianReport r = check_jacobian(f, Eigen::Vector2d(1e-6, 0.0), d, options);
  EXPECT_EQ(evaluations, 2);
  EXPECT_EQ(r.compared, 2);
  EXPECT_TRUE(r.meets_tangent_rule(0.0)) << r;
  EXPECT_DOUBLE_EQ(r.largest_analytic, 2 * 1.5 * 0.7);
}

TEST(JacobianCheck, FailedEvaluationFails) {
  const PerturbedFunction f = [](int column, double step, Eigen::VectorXd& value) {
    value = Eigen::VectorXd::Zero(3);
    return !(column == 1 && step < 0);
  };
  const JacobianReport r = check_jacobian(f, Eigen::Vector2d::Constant(1e-6), smooth_jacobian());
  EXPECT_FALSE(r.evaluated());
  EXPECT_EQ(r.failed_column, 1);
  EXPECT_EQ(r.failed_step, -1e-6);
  EXPECT_FALSE(r.passes(1.0, 1e300));
  EXPECT_NE(r.summary().find("column 1"), std::string::npos) << r.summary();
}

TEST(JacobianCheck, NanFailsEveryTolerance) {
  Eigen::MatrixXd d = smooth_jacobian();
  d(1, 1) = std::numeric_limits<double>::quiet_NaN();
  const JacobianReport r = check(d);
  EXPECT_EQ(r.max_error, std::numeric_limits<double>::infinity());
  EXPECT_FALSE(r.passes(1.0, 1e300));
  EXPECT_EQ(r.entries[0].row, 1);
  EXPECT_EQ(r.entries[0].column, 1);
}

TEST(JacobianCheck, SymmetricPartOfTheDifferences) {
  // f(x) = A x with A unsymmetric: D_fd = A, its symmetric part ½(A + Aᵀ).
  Eigen::Matrix3d a;
  a << 4, 1, 0, 3, 5, -2, 0, 2, 6;
  const VectorFunction f = [&a](const Eigen::VectorXd& x, Eigen::VectorXd& value) {
    value = a * x;
    return true;
  };
  const Eigen::Vector3d x(0.1, -0.2, 0.3);
  JacobianCheckOptions options;
  options.symmetric_part = true;
  const Eigen::Matrix3d sym = 0.5 * (a + a.transpose());
  const Eigen::Vector3d steps = Eigen::Vector3d::Constant(1e-6);
  EXPECT_TRUE(check_jacobian(perturb_additively(f, x), steps, sym, options).passes(1e-8, 0));
  EXPECT_FALSE(check_jacobian(perturb_additively(f, x), steps, a, options).passes(1e-3, 0));
  EXPECT_TRUE(check_jacobian(perturb_additively(f, x), steps, a).passes(1e-8, 0));
  // Without column 2 its row is left out too: rows and columns 0, 1 only.
  const JacobianReport r =
      check_jacobian(perturb_additively(f, x), Eigen::Vector3d(1e-6, 1e-6, 0), sym, options);
  EXPECT_EQ(r.compared, 4);
  EXPECT_THROW(check_jacobian(perturb_additively(smooth, point()), Eigen::Vector2d::Constant(1e-6),
                              smooth_jacobian(), options),
               std::invalid_argument);
}

TEST(JacobianCheck, StepOfSection1_4) {
  EXPECT_DOUBLE_EQ(tangent_check_step(0.3, 0.12), 3e-7);
  EXPECT_DOUBLE_EQ(tangent_check_step(1e-5, 1e-3), 1e-9);
}

// [[4, 1, 0], [2, 5, 0], [0, 0, 6]] in full storage.
SparseMatrix small_full() {
  SparseMatrix m;
  m.n = 3;
  m.col_ptr = {0, 2, 4, 5};
  m.row_idx = {0, 1, 0, 1, 2};
  m.values = {4, 2, 1, 5, 6};
  return m;
}

TEST(SparseEntry, FullStorageIsReadDirectly) {
  const SparseMatrix m = small_full();
  validate_pattern(m);
  EXPECT_EQ(entry(m, 0, 1), 1.0);
  EXPECT_EQ(entry(m, 1, 0), 2.0);
  EXPECT_EQ(entry(m, 2, 2), 6.0);
  EXPECT_EQ(entry(m, 2, 0), 0.0);
  EXPECT_EQ(entry(m, 0, 2), 0.0);
}

TEST(SparseEntry, SymmetricUpperStorageIsMirrored) {
  SparseMatrix m;
  m.n = 3;
  m.symmetric_upper = true;
  m.col_ptr = {0, 1, 3, 4};
  m.row_idx = {0, 0, 1, 2};
  m.values = {4, 1.5, 5, 6};
  validate_pattern(m);
  EXPECT_EQ(entry(m, 0, 1), 1.5);
  EXPECT_EQ(entry(m, 1, 0), 1.5);
  EXPECT_EQ(entry(m, 1, 1), 5.0);
  EXPECT_EQ(entry(m, 2, 1), 0.0);
}

}  // namespace
}  // namespace clinch
