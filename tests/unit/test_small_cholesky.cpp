// SmallCholesky (base/small_cholesky.hpp) against Eigen's LLT on random symmetric positive
// definite 6×6 matrices with condition numbers up to about 1e8 (stiffness contrasts of connector
// behaviours), and its refusal of indefinite and singular matrices.
#include <gtest/gtest.h>

#include <random>

#include <Eigen/Cholesky>

#include "base/small_cholesky.hpp"
#include "base/small_types.hpp"

namespace clinch {
namespace {

Matrix6 random_spd(std::mt19937& rng, double contrast) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Matrix6 q = Matrix6::Zero();
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) q(i, j) = unit(rng);
  }
  const Eigen::HouseholderQR<Matrix6> qr(q);
  const Matrix6 orthogonal = qr.householderQ();
  Vector6 eigenvalues;
  for (int i = 0; i < 6; ++i) eigenvalues[i] = std::pow(contrast, i / 5.0);
  return orthogonal * eigenvalues.asDiagonal() * orthogonal.transpose();
}

TEST(SmallCholesky, SolveAndInverseMatchEigen) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (double contrast : {1.0, 1e3, 1e8}) {
    for (int trial = 0; trial < 20; ++trial) {
      const Matrix6 a = random_spd(rng, contrast);
      Vector6 b;
      for (int i = 0; i < 6; ++i) b[i] = unit(rng);
      const SmallCholesky<6> chol(a);
      ASSERT_TRUE(chol.ok());
      const Eigen::LLT<Matrix6> reference(a);
      // Both are backward stable: the solutions agree to about cond(A)·eps relative.
      const double tolerance = 1e-14 * contrast * 10;
      const Vector6 x = chol.solve(b), y = reference.solve(b);
      EXPECT_LE((x - y).norm(), tolerance * y.norm()) << contrast;
      const Matrix6 inverse = chol.inverse();
      EXPECT_LE((inverse - reference.solve(Matrix6::Identity())).norm(),
                tolerance * inverse.norm());
      EXPECT_EQ(inverse, inverse.transpose());
      // The residual of the solve is at round-off of ‖A‖‖x‖.
      EXPECT_LE((a * x - b).norm(), 1e-13 * a.norm() * x.norm());
    }
  }
}

TEST(SmallCholesky, RefusesIndefiniteSingularAndNonFiniteMatrices) {
  Matrix6 indefinite = Matrix6::Identity();
  indefinite(3, 3) = -1.0;
  EXPECT_FALSE(SmallCholesky<6>(indefinite).ok());
  Matrix6 singular = Matrix6::Identity();
  singular(5, 5) = 0.0;
  EXPECT_FALSE(SmallCholesky<6>(singular).ok());
  Matrix6 nan = Matrix6::Identity();
  nan(2, 2) = std::nan("");
  EXPECT_FALSE(SmallCholesky<6>(nan).ok());
}

}  // namespace
}  // namespace clinch
