// The tangent's sparsity pattern, computed once per step structure (ARCHITECTURE.md "Performance
// by design"): every element couples all its equations; the result is a CSC matrix with sorted
// rows and every diagonal present, either the upper triangle (symmetric tangents) or the full
// pattern (unsymmetric ones). Elements then look up
// the positions of their entries once (scatter indices), so assembly is a flat loop.
#pragma once

#include <span>
#include <vector>

#include "src/linalg/linear_solver.hpp"

namespace clinch {

class SparsityBuilder {
 public:
  SparsityBuilder(int equations, bool symmetric);
  // Couples every pair of the (non-negative) equations; negative entries are skipped.
  void couple(std::span<const int> equations);
  // The pattern (upper triangle, row ≤ column, when symmetric), values zero.
  SparseMatrix build();

 private:
  bool symmetric_;
  std::vector<std::vector<int>> rows_of_column_;
};

// Index into `values` of entry (row, column) (of (column, row) when row > column in upper-triangle
// storage), or −1 when the entry is not in the pattern.
int entry_position(const SparseMatrix& pattern, int row, int column);

}  // namespace clinch
