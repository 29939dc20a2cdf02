#include "src/fit/fit_statistics.hpp"

#include <cmath>
#include <limits>

namespace clinch {

FitStatistics fit_statistics(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& residuals) {
  const Eigen::Index m = jacobian.rows(), n = jacobian.cols();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  FitStatistics s;
  s.residual_variance = m > n ? residuals.squaredNorm() / static_cast<double>(m - n) : 0.0;
  s.standard_errors.assign(static_cast<std::size_t>(n), nan);
  s.correlation = Eigen::MatrixXd::Constant(n, n, nan);

  Eigen::VectorXd lengths = jacobian.colwise().norm().transpose();
  Eigen::MatrixXd scaled = jacobian;
  for (Eigen::Index j = 0; j < n; ++j) {
    if (lengths(j) > 0.0) scaled.col(j) /= lengths(j);
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(scaled, Eigen::ComputeThinV);
  const Eigen::VectorXd& sigma = svd.singularValues();
  s.smallest_singular_value = n > 0 ? sigma(n - 1) : 0.0;
  for (Eigen::Index j = 0; j < n; ++j) {
    if (lengths(j) == 0.0) s.undetermined.push_back(static_cast<std::size_t>(j));
  }
  if (s.undetermined.empty() && n > 0 && s.smallest_singular_value < kIdentifiableSingularValue) {
    // The parameters that move in the direction that leaves the residual unchanged.
    s.null_direction = svd.matrixV().col(n - 1);
    const double largest = s.null_direction.cwiseAbs().maxCoeff();
    for (Eigen::Index j = 0; j < n; ++j) {
      if (std::abs(s.null_direction(j)) > 0.1 * largest) {
        s.undetermined.push_back(static_cast<std::size_t>(j));
      }
    }
  }
  if (!s.identifiable()) return s;

  // (JᵀJ)⁻¹ = D⁻¹ V Σ⁻² Vᵀ D⁻¹ with D the column lengths: no normal equations formed.
  const Eigen::MatrixXd& v = svd.matrixV();
  const Eigen::MatrixXd inverse_scaled =
      v * sigma.cwiseInverse().cwiseAbs2().asDiagonal() * v.transpose();
  Eigen::MatrixXd covariance = s.residual_variance * inverse_scaled;
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) covariance(i, j) /= lengths(i) * lengths(j);
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    s.standard_errors[static_cast<std::size_t>(i)] = std::sqrt(covariance(i, i));
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) {
      // From the scaled inverse: the correlation does not need s², so it exists with m == n.
      s.correlation(i, j) =
          inverse_scaled(i, j) / std::sqrt(inverse_scaled(i, i) * inverse_scaled(j, j));
    }
  }
  return s;
}

}  // namespace clinch
