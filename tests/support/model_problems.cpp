#include "tests/support/model_problems.hpp"

#include <array>
#include <cmath>
#include <map>
#include <vector>

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

SparseMatrix truss_lattice_3d(int points_per_side) {
  const int n = points_per_side;
  const int equations = 3 * n * n * n;
  std::vector<std::map<int, double>> columns(static_cast<std::size_t>(equations));
  // Every entry of the full matrix is added once; upper storage keeps those with row ≤ column.
  auto add = [&](int row, int column, double value) {
    if (row > column) return;
    columns[static_cast<std::size_t>(column)][row] += value;
  };
  constexpr std::array<std::array<int, 3>, 9> kOffsets = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                                           {1, 1, 0}, {1, -1, 0}, {1, 0, 1},
                                                           {1, 0, -1}, {0, 1, 1}, {0, 1, -1}}};
  auto node = [n](int x, int y, int z) { return x + n * (y + n * z); };
  for (int z = 0; z < n; ++z) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        const int a = node(x, y, z);
        if (x == 0) {
          for (int i = 0; i < 3; ++i) add(3 * a + i, 3 * a + i, 1.0);
        }
        for (const auto& o : kOffsets) {
          const int bx = x + o[0], by = y + o[1], bz = z + o[2];
          if (bx < 0 || bx >= n || by < 0 || by >= n || bz < 0 || bz >= n) continue;
          const int b = node(bx, by, bz);
          const double length = std::sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]);
          for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
              const double k = o[i] * o[j] / (length * length * length);
              if (k == 0.0) continue;
              add(3 * a + i, 3 * a + j, k);
              add(3 * b + i, 3 * b + j, k);
              add(3 * a + i, 3 * b + j, -k);
              add(3 * b + i, 3 * a + j, -k);
            }
          }
        }
      }
    }
  }
  SparseMatrix m;
  m.n = equations;
  m.symmetric_upper = true;
  m.node_block = 3;
  m.col_ptr.push_back(0);
  for (const auto& column : columns) {
    for (const auto& [row, value] : column) {
      m.row_idx.push_back(row);
      m.values.push_back(value);
    }
    m.col_ptr.push_back(static_cast<int>(m.row_idx.size()));
  }
  return m;
}

}  // namespace clinch
