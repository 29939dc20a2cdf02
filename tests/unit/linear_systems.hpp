// Small linear systems and their residuals, for the linear-solver tests (test_linear_solvers.cpp,
// test_petsc_solver.cpp): matrices stored as upper triangles or in full, built from Eigen ones,
// and residuals computed with Eigen, independently of the backends.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <vector>

#include "src/linalg/sparse_matrix.hpp"

namespace clinch {

enum class Storage { Upper, Full };

using EigenSparse = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// The matrix a SparseMatrix stands for, mirrored when stored as an upper triangle: residuals are
// computed with Eigen, independently of the backends.
inline EigenSparse to_eigen(const SparseMatrix& m) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int j = 0; j < m.n; ++j) {
    for (int p = m.col_ptr[j]; p < m.col_ptr[j + 1]; ++p) {
      const int i = m.row_idx[p];
      entries.emplace_back(i, j, m.values[p]);
      if (m.symmetric_upper && i != j) entries.emplace_back(j, i, m.values[p]);
    }
  }
  EigenSparse a(m.n, m.n);
  a.setFromTriplets(entries.begin(), entries.end());
  return a;
}

inline SparseMatrix from_eigen(const EigenSparse& a, Storage storage) {
  EigenSparse stored =
      storage == Storage::Upper ? EigenSparse(a.triangularView<Eigen::Upper>()) : a;
  stored.makeCompressed();
  SparseMatrix m;
  m.n = static_cast<int>(stored.rows());
  m.symmetric_upper = storage == Storage::Upper;
  m.col_ptr.assign(stored.outerIndexPtr(), stored.outerIndexPtr() + m.n + 1);
  m.row_idx.assign(stored.innerIndexPtr(), stored.innerIndexPtr() + stored.nonZeros());
  m.values.assign(stored.valuePtr(), stored.valuePtr() + stored.nonZeros());
  return m;
}

// Pattern of the nonzeros of `a` plus its whole diagonal (kept even where it is zero, as the
// assembler's pattern does).
inline SparseMatrix from_dense(const Eigen::MatrixXd& a, Storage storage) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int j = 0; j < a.cols(); ++j) {
    for (int i = 0; i < a.rows(); ++i) {
      if (a(i, j) != 0.0 || i == j) entries.emplace_back(i, j, a(i, j));
    }
  }
  EigenSparse s(a.rows(), a.cols());
  s.setFromTriplets(entries.begin(), entries.end());
  // Explicit zeros stay: neither setFromTriplets nor makeCompressed prunes.
  return from_eigen(s, storage);
}

inline double relative_residual(const SparseMatrix& m, const Eigen::VectorXd& x,
                                const Eigen::VectorXd& b) {
  return (to_eigen(m) * x - b).norm() / b.norm();
}

// Spring chain 0–1–2–3 on ground at node 0 (k = 2, 3.5, 1.25, 0.75): SPD.
inline Eigen::MatrixXd grounded_chain() {
  const std::vector<double> k = {2.0, 3.5, 1.25, 0.75};
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(4, 4);
  a(0, 0) = k[0];
  for (int e = 1; e < 4; ++e) {
    a(e - 1, e - 1) += k[e];
    a(e, e) += k[e];
    a(e - 1, e) -= k[e];
    a(e, e - 1) -= k[e];
  }
  return a;
}

}  // namespace clinch
