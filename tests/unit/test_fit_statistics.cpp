// The statistics of a fit (src/fit/fit_statistics.hpp) against the closed forms of a straight
// line y = a + b·t fitted by least squares: s² = Σr²/(m − 2), se(b) = s/√Sxx,
// se(a) = s·√(1/m + t̄²/Sxx), corr(a, b) = −t̄/√(Sxx/m + t̄²) with Sxx = Σ(t − t̄)². Tolerance
// 1e-12 relative: the SVD and the closed forms differ by round-off only.
#include <gtest/gtest.h>

#include <cmath>

#include "src/fit/fit_statistics.hpp"

namespace clinch {
namespace {

TEST(FitStatistics, StraightLineMatchesClosedForm) {
  const Eigen::VectorXd t = (Eigen::VectorXd(6) << 0.0, 1.0, 2.0, 3.0, 5.0, 8.0).finished();
  const Eigen::VectorXd r = (Eigen::VectorXd(6) << 0.1, -0.2, 0.05, 0.15, -0.1, 0.02).finished();
  Eigen::MatrixXd j(6, 2);
  j.col(0).setOnes();
  j.col(1) = t;
  const FitStatistics s = fit_statistics(j, r);
  const double m = 6.0, mean = t.mean();
  const double sxx = (t.array() - mean).square().sum();
  const double variance = r.squaredNorm() / (m - 2.0);
  EXPECT_NEAR(s.residual_variance, variance, 1e-12 * variance);
  const double se_b = std::sqrt(variance / sxx);
  const double se_a = std::sqrt(variance * (1.0 / m + mean * mean / sxx));
  EXPECT_NEAR(s.standard_errors[0], se_a, 1e-12 * se_a);
  EXPECT_NEAR(s.standard_errors[1], se_b, 1e-12 * se_b);
  const double correlation = -mean / std::sqrt(sxx / m + mean * mean);
  EXPECT_NEAR(s.correlation(0, 1), correlation, 1e-12);
  EXPECT_NEAR(s.correlation(1, 0), correlation, 1e-12);
  EXPECT_DOUBLE_EQ(s.correlation(0, 0), 1.0);
  EXPECT_TRUE(s.identifiable());
}

// Two parameters that enter only as their product a·b: ∂r/∂a = b·g, ∂r/∂b = a·g. Both are named,
// and the direction that leaves the residual unchanged is (1, −1)/√2 in unit-column terms.
TEST(FitStatistics, ProductIsNotDetermined) {
  const Eigen::VectorXd g = (Eigen::VectorXd(4) << 1.0, 2.0, 3.0, 4.0).finished();
  const double a = 2.0, b = 5.0;
  Eigen::MatrixXd j(4, 2);
  j.col(0) = b * g;
  j.col(1) = a * g;
  const FitStatistics s = fit_statistics(j, Eigen::VectorXd::Constant(4, 0.01));
  EXPECT_FALSE(s.identifiable());
  EXPECT_EQ(s.undetermined, (std::vector<std::size_t>{0, 1}));
  EXPECT_LT(s.smallest_singular_value, 1e-12);
  EXPECT_NEAR(std::abs(s.null_direction(0)), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(s.null_direction(0), -s.null_direction(1), 1e-12);
  EXPECT_TRUE(std::isnan(s.standard_errors[0]));
}

// A parameter the curves do not depend on (a zero column) is named alone.
TEST(FitStatistics, ZeroColumnIsNotDetermined) {
  Eigen::MatrixXd j(3, 2);
  j << 1.0, 0.0, 2.0, 0.0, 3.0, 0.0;
  const FitStatistics s = fit_statistics(j, Eigen::VectorXd::Constant(3, 0.1));
  EXPECT_EQ(s.undetermined, (std::vector<std::size_t>{1}));
}

}  // namespace
}  // namespace clinch
