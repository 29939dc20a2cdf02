#include "src/linalg/sparse_matrix.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace clinch {

void validate_pattern(const SparseMatrix& m) {
  if (m.n < 0 || m.col_ptr.size() != static_cast<std::size_t>(m.n) + 1 || m.col_ptr[0] != 0) {
    throw std::invalid_argument(
        fmt::format("sparse matrix of order {}: {} column pointers", m.n, m.col_ptr.size()));
  }
  const auto nnz = static_cast<std::size_t>(m.nonzeros());
  if (m.row_idx.size() != nnz || m.values.size() != nnz) {
    throw std::invalid_argument(
        fmt::format("sparse matrix with {} entries: {} row indices, {} values", nnz,
                    m.row_idx.size(), m.values.size()));
  }
  if (m.node_block < 1 || m.n % m.node_block != 0) {
    throw std::invalid_argument(
        fmt::format("sparse matrix of order {}: node block {}", m.n, m.node_block));
  }
  const int last_row = m.n - 1;
  for (int j = 0; j < m.n; ++j) {
    if (m.col_ptr[j + 1] < m.col_ptr[j]) {
      throw std::invalid_argument(fmt::format("column {}: decreasing column pointer", j));
    }
    for (int p = m.col_ptr[j]; p < m.col_ptr[j + 1]; ++p) {
      const int i = m.row_idx[p];
      const bool in_range = i >= 0 && i <= (m.symmetric_upper ? j : last_row);
      if (!in_range || (p > m.col_ptr[j] && i <= m.row_idx[p - 1])) {
        throw std::invalid_argument(
            fmt::format("column {}: row index {} out of range or out of order", j, i));
      }
    }
  }
}

double entry(const SparseMatrix& m, int row, int column) {
  if (m.symmetric_upper && row > column) std::swap(row, column);
  const auto first = m.row_idx.begin() + m.col_ptr[column];
  const auto last = m.row_idx.begin() + m.col_ptr[column + 1];
  const auto found = std::lower_bound(first, last, row);
  return found != last && *found == row ? m.values[found - m.row_idx.begin()] : 0.0;
}

FullPattern full_pattern(const SparseMatrix& m, bool by_rows) {
  // One pass over the stored columns in order places every entry (and, in upper storage, its
  // mirror) at the end of its line, and each line receives its entries in increasing order:
  // by columns, column c gets its stored rows (<= c) while column c is read and its mirrored
  // rows (> c) from the later columns; by rows, row r gets the mirrors (columns < r) and the
  // diagonal while column r is read and its stored entries (r, j > r) from the later columns.
  FullPattern full;
  const auto for_each_entry = [&](auto&& place) {
    for (int j = 0; j < m.n; ++j) {
      for (int p = m.col_ptr[j]; p < m.col_ptr[j + 1]; ++p) {
        const int i = m.row_idx[p];
        by_rows ? place(i, j, p) : place(j, i, p);
        if (m.symmetric_upper && i != j) by_rows ? place(j, i, p) : place(i, j, p);
      }
    }
  };
  full.ptr.assign(static_cast<std::size_t>(m.n) + 1, 0);
  for_each_entry([&](int line, int, int) { ++full.ptr[static_cast<std::size_t>(line) + 1]; });
  for (int r = 0; r < m.n; ++r) full.ptr[r + 1] += full.ptr[r];
  full.idx.resize(static_cast<std::size_t>(full.ptr[m.n]));
  full.source.resize(full.idx.size());
  std::vector<int> next(full.ptr.begin(), full.ptr.end() - 1);
  for_each_entry([&](int line, int index, int p) {
    const int at = next[static_cast<std::size_t>(line)]++;
    full.idx[static_cast<std::size_t>(at)] = index;
    full.source[static_cast<std::size_t>(at)] = p;
  });
  return full;
}

std::vector<int> diagonal_positions(const SparseMatrix& m) {
  std::vector<int> positions(m.n, -1);
  for (int j = 0; j < m.n; ++j) {
    for (int p = m.col_ptr[j]; p < m.col_ptr[j + 1]; ++p) {
      if (m.row_idx[p] == j) positions[j] = p;
    }
  }
  return positions;
}

int first_non_finite(const SparseMatrix& m) {
  for (std::size_t p = 0; p < m.values.size(); ++p) {
    if (!std::isfinite(m.values[p])) return static_cast<int>(p);
  }
  return -1;
}

bool row_and_column_are_zero(const SparseMatrix& m, int j) {
  for (int c = 0; c < m.n; ++c) {
    for (int p = m.col_ptr[c]; p < m.col_ptr[c + 1]; ++p) {
      if ((c == j || m.row_idx[p] == j) && m.values[p] != 0.0) return false;
    }
  }
  return true;
}

}  // namespace clinch
