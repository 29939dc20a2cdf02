// The tangent's sparsity pattern, computed once per step structure (ARCHITECTURE.md "Performance
// by design"): every element couples all its equations; the result is a CSC matrix with sorted
// rows and every diagonal present, either the upper triangle (symmetric tangents) or the full
// pattern (unsymmetric ones). Elements then look up
// the positions of their entries once (scatter indices), so assembly is a flat loop.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "src/linalg/linear_solver.hpp"

namespace clinch {

class SparsityBuilder {
 public:
  // Every diagonal is present; with `diagonals` (a rank's part under assembly by rows) only
  // those of the equations in [first, last) and of the equations coupled.
  SparsityBuilder(int equations, bool symmetric);
  SparsityBuilder(int equations, bool symmetric, int first_diagonal, int last_diagonal);
  // Room for this many entries off the diagonal (what the couple calls will add).
  void reserve(std::size_t couplings);
  // Couples every pair of the (non-negative) equations; negative entries are skipped.
  void couple(std::span<const int> equations);
  // The pattern (upper triangle, row ≤ column, when symmetric), values zero.
  SparseMatrix build();

 private:
  // The entries are kept as coupled, (column, row) off the diagonal, and sorted into columns
  // once by counting: flat arrays, where a vector per equation cost an allocation or more each
  // (3·10⁶ of them for a 10⁶-connector chain).
  bool symmetric_;
  std::vector<int> count_;  // entries of each column, its diagonal included
  // Per column: 0 without its diagonal so far, 1 present from the start, 2 added by couple.
  std::vector<std::uint8_t> diagonal_;
  std::vector<std::pair<int, int>> entries_;
};

// Index into `values` of entry (row, column) (of (column, row) when row > column in upper-triangle
// storage), or −1 when the entry is not in the pattern.
int entry_position(const SparseMatrix& pattern, int row, int column);

}  // namespace clinch
