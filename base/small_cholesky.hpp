// Cholesky factorization and solves of a small symmetric positive definite matrix of fixed size,
// for the local problems of the constitutive updates (the closest-point Newton of connector
// plasticity factors a 6×6 matrix at every local iteration). Plain loops over a compile-time
// size, which the compiler unrolls; Eigen's LLT routes fixed 6×6 solves through its blocked
// kernels and costs several times more here.
#pragma once

#include <cmath>

#include <Eigen/Core>

namespace clinch {

template <int N>
class SmallCholesky {
 public:
  using Matrix = Eigen::Matrix<double, N, N>;
  using Vector = Eigen::Matrix<double, N, 1>;

  // Factors A = L Lᵀ from the lower triangle of `a`. ok() is false when a pivot is not
  // positive (A not positive definite, or not finite).
  explicit SmallCholesky(const Matrix& a) {
    for (int j = 0; j < N; ++j) {
      double d = a(j, j);
      for (int k = 0; k < j; ++k) d -= l_[j][k] * l_[j][k];
      if (!(d > 0)) {
        ok_ = false;
        return;
      }
      const double ljj = std::sqrt(d);
      inverse_diagonal_[j] = 1.0 / ljj;
      for (int i = j + 1; i < N; ++i) {
        double s = a(i, j);
        for (int k = 0; k < j; ++k) s -= l_[i][k] * l_[j][k];
        l_[i][j] = s * inverse_diagonal_[j];
      }
      l_[j][j] = ljj;
    }
  }

  bool ok() const { return ok_; }

  // A⁻¹ b by forward and back substitution.
  Vector solve(const Vector& b) const {
    double y[N];
    for (int i = 0; i < N; ++i) {
      double s = b[i];
      for (int k = 0; k < i; ++k) s -= l_[i][k] * y[k];
      y[i] = s * inverse_diagonal_[i];
    }
    Vector x;
    for (int i = N - 1; i >= 0; --i) {
      double s = y[i];
      for (int k = i + 1; k < N; ++k) s -= l_[k][i] * x[k];
      x[i] = s * inverse_diagonal_[i];
    }
    return x;
  }

  // A⁻¹ (symmetric), as L⁻ᵀ L⁻¹.
  Matrix inverse() const {
    double w[N][N] = {};  // W = L⁻¹ (lower triangular)
    for (int j = 0; j < N; ++j) {
      w[j][j] = inverse_diagonal_[j];
      for (int i = j + 1; i < N; ++i) {
        double s = 0;
        for (int k = j; k < i; ++k) s -= l_[i][k] * w[k][j];
        w[i][j] = s * inverse_diagonal_[i];
      }
    }
    Matrix out;
    for (int i = 0; i < N; ++i) {
      for (int j = 0; j <= i; ++j) {
        double s = 0;
        for (int k = i; k < N; ++k) s += w[k][i] * w[k][j];
        out(i, j) = out(j, i) = s;
      }
    }
    return out;
  }

 private:
  double l_[N][N] = {};
  double inverse_diagonal_[N] = {};
  bool ok_ = true;
};

}  // namespace clinch
