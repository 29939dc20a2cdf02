// The tangent's sparsity pattern, computed once per analysis (ARCHITECTURE.md "Performance by
// design"): every element contributes the upper triangle of the coupling among its equations;
// the result is a CSC matrix with sorted rows and every diagonal present. Elements then look up
// the positions of their entries once (scatter indices), so assembly is a flat loop.
#pragma once

#include <span>
#include <vector>

#include "src/linalg/linear_solver.hpp"

namespace clinch {

class SparsityBuilder {
 public:
  explicit SparsityBuilder(int equations);
  // Couples every pair of the (non-negative) equations; negative entries are skipped.
  void couple(std::span<const int> equations);
  // The upper-triangular pattern (row ≤ column), values zero.
  SparseMatrix build();

 private:
  std::vector<std::vector<int>> rows_of_column_;
};

// Index into `values` of entry (row, column) of an upper-triangular pattern (the pair is swapped
// when row > column), or −1 when the entry is not in the pattern.
int entry_position(const SparseMatrix& pattern, int row, int column);

}  // namespace clinch
