#include "tests/support/model_problems.hpp"

namespace clinch {

SparseMatrix laplacian_3d(int points_per_side) {
  const int n = points_per_side;
  SparseMatrix m;
  m.n = n * n * n;
  m.symmetric_upper = true;
  m.col_ptr.reserve(m.n + 1);
  m.col_ptr.push_back(0);
  for (int z = 0; z < n; ++z) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        const int j = x + n * (y + n * z);
        // Rows above the diagonal in increasing order: the −z, −y, −x neighbours.
        if (z > 0) m.row_idx.push_back(j - n * n);
        if (y > 0) m.row_idx.push_back(j - n);
        if (x > 0) m.row_idx.push_back(j - 1);
        m.values.resize(m.row_idx.size(), -1.0);
        m.row_idx.push_back(j);
        m.values.push_back(6.0);
        m.col_ptr.push_back(static_cast<int>(m.row_idx.size()));
      }
    }
  }
  return m;
}

}  // namespace clinch
