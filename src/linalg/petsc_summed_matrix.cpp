// The tangent assembled by rows under mpirun (docs/parallel.md "Assembly by rows"): each rank
// passes its part of the matrix (SparseMatrix::partial, the entries of its own elements over
// global equations), and PETSc's COO assembly sums the parts into the rows each rank owns,
// sending the entries of rows owned elsewhere itself. No rank holds the whole matrix.
#include <fmt/format.h>
#include <petscksp.h>

#include <algorithm>
#include <string>
#include <vector>

#include "src/linalg/petsc_solver.hpp"

namespace clinch {

PetscErrorCode PetscSolver::create_summed_objects(const SparseMatrix& part) {
  const PetscInt n = part.n;
  first_row_ = part.first_owned_row;
  local_rows_ = part.owned_rows;
  // Every stored entry in the order of part.values, then the mirror of each entry off the
  // diagonal of an upper triangle: the values of MatSetValuesCOO are then a copy of part.values
  // followed by the mirrored ones.
  std::vector<PetscInt> coo_i, coo_j;
  mirrored_.clear();
  const std::size_t stored = part.row_idx.size();
  coo_i.reserve(part.symmetric_upper ? 2 * stored : stored);
  coo_j.reserve(coo_i.capacity());
  for (PetscInt j = 0; j < n; ++j) {
    for (int p = part.col_ptr[j]; p < part.col_ptr[j + 1]; ++p) {
      coo_i.push_back(part.row_idx[p]);
      coo_j.push_back(j);
    }
  }
  if (part.symmetric_upper) {
    for (PetscInt j = 0; j < n; ++j) {
      for (int p = part.col_ptr[j]; p < part.col_ptr[j + 1]; ++p) {
        if (part.row_idx[p] == j) continue;
        mirrored_.push_back(p);
        coo_i.push_back(j);
        coo_j.push_back(part.row_idx[p]);
      }
    }
  }
  coo_values_.assign(coo_i.size(), 0.0);
  PetscCall(MatCreate(PETSC_COMM_WORLD, &matrix_));
  PetscCall(MatSetSizes(matrix_, local_rows_, local_rows_, n, n));
  PetscCall(MatSetBlockSize(matrix_, node_block_));
  PetscCall(MatSetType(matrix_, MATMPIAIJ));
  PetscCall(MatSetPreallocationCOO(matrix_, static_cast<PetscCount>(coo_i.size()), coo_i.data(),
                                   coo_j.data()));
  PetscCall(VecCreateMPIWithArray(PETSC_COMM_WORLD, 1, local_rows_, n, nullptr, &rhs_));
  PetscCall(MatCreateVecs(matrix_, &solution_, &work_));
  PetscCall(VecScatterCreateToAll(solution_, &gather_, &whole_solution_));
  return direct_ ? use_direct() : configure_iterative();
}

PetscErrorCode PetscSolver::sum_parts(const SparseMatrix& part) {
  std::copy(part.values.begin(), part.values.end(), coo_values_.begin());
  std::size_t at = part.values.size();
  for (const int p : mirrored_) coo_values_[at++] = part.values[static_cast<std::size_t>(p)];
  // INSERT_VALUES: each entry becomes the sum of its COO contributions over every rank.
  PetscCall(MatSetValuesCOO(matrix_, coo_values_.data(), INSERT_VALUES));
  return 0;
}

PetscErrorCode PetscSolver::classify_owned_rows(int& zero_row, bool& indefinite) {
  // A row of zeros (an unrestrained DOF, connection-types.md §1.1), a row with its diagonal only
  // (solved exactly after an iterative solve), a diagonal that is not positive (not definite):
  // each rank reads its own rows, and the ranks agree on the first zero row and on definiteness.
  decoupled_lines_.clear();
  int my_zero = n_, my_indefinite = 0;
  for (PetscInt row = first_row_; row < first_row_ + local_rows_; ++row) {
    PetscInt count = 0;
    const PetscInt* columns = nullptr;
    const PetscScalar* values = nullptr;
    PetscCall(MatGetRow(matrix_, row, &count, &columns, &values));
    double diagonal = 0.0;
    bool any = false, coupled = false;
    for (PetscInt q = 0; q < count; ++q) {
      if (values[q] == 0.0) continue;
      any = true;
      if (columns[q] == row) {
        diagonal = values[q];
      } else {
        coupled = true;
      }
    }
    PetscCall(MatRestoreRow(matrix_, row, &count, &columns, &values));
    if (!any) my_zero = std::min(my_zero, static_cast<int>(row));
    if (any && !coupled) decoupled_lines_.emplace_back(static_cast<int>(row), diagonal);
    if (!(diagonal > 0.0)) my_indefinite = 1;
  }
  int any_indefinite = 0;
  PetscCallMPI(MPI_Allreduce(&my_zero, &zero_row, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD));
  PetscCallMPI(
      MPI_Allreduce(&my_indefinite, &any_indefinite, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD));
  indefinite = any_indefinite != 0;
  return 0;
}

bool PetscSolver::first_rank_with(bool mine, std::string& text) {
  int rank = 0, ranks = 1, first = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &ranks);
  const int candidate = mine ? rank : ranks;
  MPI_Allreduce(&candidate, &first, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD);
  if (first == ranks) return false;
  int length = static_cast<int>(text.size());
  MPI_Bcast(&length, 1, MPI_INT, first, PETSC_COMM_WORLD);
  text.resize(static_cast<std::size_t>(length));
  MPI_Bcast(text.data(), length, MPI_CHAR, first, PETSC_COMM_WORLD);
  return true;
}

}  // namespace clinch
