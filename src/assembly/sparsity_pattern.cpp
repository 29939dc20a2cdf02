#include "src/assembly/sparsity_pattern.hpp"

#include <algorithm>
#include <utility>

namespace clinch {
namespace {
constexpr std::uint8_t kPresetDiagonal = 1, kCoupledDiagonal = 2;
}  // namespace

SparsityBuilder::SparsityBuilder(int equations, bool symmetric)
    : SparsityBuilder(equations, symmetric, 0, equations) {}

SparsityBuilder::SparsityBuilder(int equations, bool symmetric, int first_diagonal,
                                 int last_diagonal)
    : symmetric_(symmetric),
      count_(static_cast<std::size_t>(equations), 0),
      diagonal_(static_cast<std::size_t>(equations), 0) {
  for (int i = first_diagonal; i < last_diagonal; ++i) {
    count_[static_cast<std::size_t>(i)] = 1;
    diagonal_[static_cast<std::size_t>(i)] = kPresetDiagonal;
  }
}

void SparsityBuilder::reserve(std::size_t couplings) { entries_.reserve(couplings); }

void SparsityBuilder::couple(std::span<const int> equations) {
  for (int a : equations) {
    if (a < 0) continue;
    if (!diagonal_[static_cast<std::size_t>(a)]) {
      diagonal_[static_cast<std::size_t>(a)] = kCoupledDiagonal;
      entries_.emplace_back(a, a);
      ++count_[static_cast<std::size_t>(a)];
    }
    for (int b : equations) {
      if (b < 0 || b == a || (symmetric_ && b > a)) continue;
      entries_.emplace_back(a, b);
      ++count_[static_cast<std::size_t>(a)];
    }
  }
}

SparseMatrix SparsityBuilder::build() {
  SparseMatrix m;
  m.n = static_cast<int>(count_.size());
  m.symmetric_upper = symmetric_;
  // Each column's rows in a slot of its count (a diagonal present from the start first), then
  // sorted and made unique, moving the columns down over the duplicates removed.
  std::vector<std::size_t> next(count_.size() + 1, 0);
  for (std::size_t c = 0; c < count_.size(); ++c) next[c + 1] = next[c] + count_[c];
  std::vector<int> rows(next.back());
  std::vector<std::size_t> fill(next.begin(), next.end() - 1);
  for (std::size_t c = 0; c < count_.size(); ++c) {
    if (diagonal_[c] == kPresetDiagonal) rows[fill[c]++] = static_cast<int>(c);
  }
  for (const auto& [column, row] : entries_) rows[fill[static_cast<std::size_t>(column)]++] = row;
  std::vector<std::pair<int, int>>().swap(entries_);
  m.col_ptr.assign(count_.size() + 1, 0);
  std::size_t kept = 0;
  for (std::size_t c = 0; c < count_.size(); ++c) {
    const auto first = rows.begin() + static_cast<std::ptrdiff_t>(next[c]);
    const auto last = rows.begin() + static_cast<std::ptrdiff_t>(next[c + 1]);
    std::sort(first, last);
    const auto end = std::unique(first, last);
    const auto to = rows.begin() + static_cast<std::ptrdiff_t>(kept);
    if (to != first) std::copy(first, end, to);  // down, to before `first`
    kept += static_cast<std::size_t>(end - first);
    m.col_ptr[c + 1] = static_cast<int>(kept);
  }
  rows.resize(kept);
  m.row_idx = std::move(rows);
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
