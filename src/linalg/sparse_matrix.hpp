// The global tangent in compressed sparse column form. The assembler builds the pattern once per
// step structure and scatters values into it every iteration; the linear solvers read it
// (ARCHITECTURE.md "Performance by design"). Helpers here check a pattern once, at analysis.
#pragma once

#include <vector>

namespace clinch {

// Square, int32 indices, row indices strictly increasing within each column. When
// `symmetric_upper` is set only the upper triangle (row <= column) is stored and the matrix is
// the symmetric matrix it stands for.
struct SparseMatrix {
  int n = 0;
  std::vector<int> col_ptr, row_idx;
  std::vector<double> values;
  bool symmetric_upper = false;
  // When > 1: the equations come node by node in groups of this many, every node with the same
  // DOFs (a translational lattice: 3). Solvers of nodal systems use it (BoomerAMG coarsens nodes
  // instead of single equations); the others ignore it.
  int node_block = 1;
  // Assembled by rows under mpirun (docs/parallel.md "Assembly by rows"): this rank's part of
  // the matrix, which the distributed solver sums with the other ranks' parts. It holds the
  // entries of the rank's own elements and what is added per row for the rows
  // [first_owned_row, first_owned_row + owned_rows) it owns in the solver's partition. −1: the
  // whole matrix.
  int first_owned_row = 0, owned_rows = -1;
  // A part over the rank's local equations (vectors by rows, docs/parallel.md): the global
  // equation of each row and column, its owned rows first; empty when the part is over the
  // global equations. global_n (0 for a part over the global equations) is then the size of the
  // summed system, and global_first_row the global number of the first owned row.
  std::vector<int> global_equation;
  int global_n = 0, global_first_row = 0;

  int nonzeros() const { return col_ptr.empty() ? 0 : col_ptr.back(); }
  // The size of the system the parts sum to (n unless the part is over local equations).
  bool over_local_equations() const { return global_n > 0; }
  int summed_size() const { return over_local_equations() ? global_n : n; }
  bool partial() const { return owned_rows >= 0; }
  // Whether this part adds what belongs to row i alone (every row of a whole matrix).
  bool owns_row(int i) const {
    return owned_rows < 0 || (i >= first_owned_row && i < first_owned_row + owned_rows);
  }
};

// Throws std::invalid_argument when the arrays do not form a valid pattern of the kind above
// (sizes, ranges, sorted rows, no lower entry in upper storage): a malformed pattern is a bug of
// its builder, not a numerical condition.
void validate_pattern(const SparseMatrix& m);

// Entry (row, column) of the matrix `m` stands for, 0 outside the pattern: read directly from a
// full pattern, from its mirror (column, row) in the lower triangle of symmetric-upper storage.
double entry(const SparseMatrix& m, int row, int column);

// The matrix `m` stands for in full storage, compressed by columns (`by_rows` false) or by rows,
// indices sorted within each line, and for each entry its index into m.values: a solver that
// needs full storage builds this once per pattern and gathers the values through `source`.
struct FullPattern {
  std::vector<int> ptr, idx, source;
};
FullPattern full_pattern(const SparseMatrix& m, bool by_rows);

// Index into `values` of each diagonal entry, −1 where the pattern has none.
std::vector<int> diagonal_positions(const SparseMatrix& m);

// Index into `values` of the first entry that is NaN or infinite, −1 if every value is finite.
int first_non_finite(const SparseMatrix& m);

// True when row and column j of the (symmetric or full) matrix hold only zero values.
bool row_and_column_are_zero(const SparseMatrix& m, int j);

}  // namespace clinch
