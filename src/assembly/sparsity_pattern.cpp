#include "src/assembly/sparsity_pattern.hpp"

#include <algorithm>
#include <utility>

namespace clinch {

SparsityBuilder::SparsityBuilder(int equations, bool symmetric)
    : symmetric_(symmetric),
      rows_of_column_(static_cast<std::size_t>(equations)) {
  for (int i = 0; i < equations; ++i) rows_of_column_[static_cast<std::size_t>(i)].push_back(i);
}

void SparsityBuilder::couple(std::span<const int> equations) {
  for (int a : equations) {
    if (a < 0) continue;
    for (int b : equations) {
      if (b < 0 || b == a || (symmetric_ && b > a)) continue;
      rows_of_column_[static_cast<std::size_t>(a)].push_back(b);
    }
  }
}

SparseMatrix SparsityBuilder::build() {
  SparseMatrix m;
  m.n = static_cast<int>(rows_of_column_.size());
  m.symmetric_upper = symmetric_;
  m.col_ptr.assign(static_cast<std::size_t>(m.n) + 1, 0);
  for (std::size_t c = 0; c < rows_of_column_.size(); ++c) {
    std::vector<int>& rows = rows_of_column_[c];
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    m.col_ptr[c + 1] = m.col_ptr[c] + static_cast<int>(rows.size());
  }
  m.row_idx.reserve(static_cast<std::size_t>(m.col_ptr.back()));
  for (std::vector<int>& rows : rows_of_column_) {
    m.row_idx.insert(m.row_idx.end(), rows.begin(), rows.end());
    std::vector<int>().swap(rows);
  }
  m.values.assign(m.row_idx.size(), 0.0);
  return m;
}

int entry_position(const SparseMatrix& pattern, int row, int column) {
  if (pattern.symmetric_upper && row > column) std::swap(row, column);
  const auto first = pattern.row_idx.begin() + pattern.col_ptr[static_cast<std::size_t>(column)];
  const auto last = pattern.row_idx.begin() + pattern.col_ptr[static_cast<std::size_t>(column) + 1];
  const auto it = std::lower_bound(first, last, row);
  if (it == last || *it != row) return -1;
  return static_cast<int>(it - pattern.row_idx.begin());
}

}  // namespace clinch
