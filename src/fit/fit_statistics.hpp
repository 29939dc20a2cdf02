// What a fit can say about its parameters, from the Jacobian J of the scaled residuals at the
// optimum (docs/fit.md "Standard errors"): the covariance s²·(JᵀJ)⁻¹ with s² = Σr²/(m − n), the
// standard errors and the correlation matrix, and the parameters the data do not determine.
// Those show as a column of J that is zero (the curves do not depend on the parameter) or as
// columns that are (nearly) dependent: the smallest singular value of J with its columns scaled
// to unit length below kIdentifiableSingularValue. Two parameters that enter only as a product
// give dependent columns: ∂r/∂a = b·g and ∂r/∂b = a·g.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace clinch {

// Below this, the column-scaled Jacobian is taken as singular. Its singular values lie in
// [0, √n]; forward differences over whole runs carry a relative error of about 1e-6 (the
// step 1e-4 times the runs' round-off of about 1e-10), so two columns that are truly parallel
// give about 1e-6, and 1e-3 (a correlation above 1 − 5e-7) leaves three decades to either side.
inline constexpr double kIdentifiableSingularValue = 1e-3;

struct FitStatistics {
  double residual_variance = 0.0;  // s²: the scaled residuals' variance, m − n degrees of freedom
  std::vector<double> standard_errors;   // NaN for a parameter not determined
  Eigen::MatrixXd correlation;           // NaN rows and columns for those parameters
  double smallest_singular_value = 0.0;  // of the column-scaled Jacobian
  // The parameters the data do not determine (indices), and the direction in which the residual
  // does not change (in units of each column's length), for the message.
  std::vector<std::size_t> undetermined;
  Eigen::VectorXd null_direction;
  bool identifiable() const { return undetermined.empty(); }
};

// `jacobian` is m×n (m residuals, n parameters), `residuals` the m scaled residuals at the
// optimum. m > n is needed for s²; with m == n, s² is taken as 0 (no error estimate).
FitStatistics fit_statistics(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& residuals);

}  // namespace clinch
