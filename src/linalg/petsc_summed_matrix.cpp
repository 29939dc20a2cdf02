// The tangent assembled by rows under mpirun (docs/parallel.md "Assembly by rows"): each rank
// passes its part of the matrix (SparseMatrix::partial, the entries of its own elements over
// global equations). Once per pattern the ranks tell the owners of the rows their parts touch
// which entries they will send; the owner builds the compressed rows of the rows it owns from
// its own entries and those it is sent, and two star forests (PetscSF) carry the values of the
// entries in rows owned elsewhere straight into the owner's diagonal and off-diagonal blocks at
// every assembly. No rank holds the whole matrix; what it sends per assembly is one value per
// entry of its part in another rank's rows.
#include <fmt/format.h>
#include <petscksp.h>
#include <petscsf.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/linalg/petsc_solver.hpp"
#include "src/parallel/communicator.hpp"

namespace clinch {
namespace {

// entry_place_ of an entry in another rank's rows: the block of that rank it goes to.
constexpr int kSentToDiagonal = -1, kSentToOffDiagonal = -2;

// The global equation of row or column i of `part` (a part over a rank's local equations maps
// them; SparseMatrix::global_equation), and the global rows the part owns.
int global_index(const SparseMatrix& part, int i) {
  return part.over_local_equations() ? part.global_equation[static_cast<std::size_t>(i)] : i;
}
int global_first_row(const SparseMatrix& part) {
  return part.over_local_equations() ? part.global_first_row : part.first_owned_row;
}
bool owns_global_row(const SparseMatrix& part, int i) {
  const int first = global_first_row(part);
  return i >= first && i < first + part.owned_rows;
}

// Calls `entry(i, j, p)` for every entry (i, j) of the matrix `part` stands for, in global
// equations, with p its index in part.values, in a fixed order: each stored entry, then, in
// upper storage, its mirror when it lies off the diagonal.
template <typename Entry>
void for_each_entry(const SparseMatrix& part, Entry entry) {
  for (int j = 0; j < part.n; ++j) {
    const int gj = global_index(part, j);
    for (int p = part.col_ptr[j]; p < part.col_ptr[j + 1]; ++p) {
      const int i = part.row_idx[p];
      const int gi = global_index(part, i);
      entry(gi, gj, p);
      if (part.symmetric_upper && i != j) entry(gj, gi, p);
    }
  }
}

// The compressed rows [first_row, first_row + rows) from this rank's entries in them and the
// (row, column) pairs `received` from the others: row pointers and each row's columns, sorted and
// unique.
struct CompressedRows {
  std::vector<PetscInt> row_ptr, columns;
};
CompressedRows compress_owned_rows(const SparseMatrix& part, int first_row, int rows,
                                   const std::vector<int>& received) {
  std::vector<int> count(static_cast<std::size_t>(rows) + 1, 0);
  for_each_entry(part, [&](int i, int, int) {
    if (owns_global_row(part, i)) ++count[static_cast<std::size_t>(i - first_row) + 1];
  });
  for (std::size_t q = 0; q < received.size(); q += 2) {
    ++count[static_cast<std::size_t>(received[q] - first_row) + 1];
  }
  for (int r = 0; r < rows; ++r) count[r + 1] += count[r];
  CompressedRows out;
  out.columns.resize(static_cast<std::size_t>(count[rows]));
  {
    std::vector<int> fill(count.begin(), count.end() - 1);
    for_each_entry(part, [&](int i, int j, int) {
      if (owns_global_row(part, i))
        out.columns[static_cast<std::size_t>(fill[i - first_row]++)] = j;
    });
    for (std::size_t q = 0; q < received.size(); q += 2) {
      out.columns[static_cast<std::size_t>(fill[received[q] - first_row]++)] = received[q + 1];
    }
  }
  out.row_ptr.assign(static_cast<std::size_t>(rows) + 1, 0);
  std::size_t kept = 0;
  for (int r = 0; r < rows; ++r) {
    const auto first = out.columns.begin() + count[r];
    const auto last = out.columns.begin() + count[r + 1];
    std::sort(first, last);
    const auto end = std::unique(first, last);
    std::copy(first, end, out.columns.begin() + static_cast<std::ptrdiff_t>(kept));
    kept += static_cast<std::size_t>(end - first);
    out.row_ptr[static_cast<std::size_t>(r) + 1] = static_cast<PetscInt>(kept);
  }
  out.columns.resize(kept);
  return out;
}

}  // namespace

PetscErrorCode PetscSolver::create_summed_objects(const SparseMatrix& part) {
  const int n = part.summed_size();
  int rank = 0, ranks = 1;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &ranks));
  first_row_ = global_first_row(part);
  local_rows_ = part.owned_rows;
  // The first row of every rank (and n): the owner of row i is the last rank starting at or
  // before it.
  std::vector<int> starts(static_cast<std::size_t>(ranks) + 1, n);
  PetscCallMPI(MPI_Allgather(&first_row_, 1, MPI_INT, starts.data(), 1, MPI_INT, PETSC_COMM_WORLD));
  const auto owner = [&](int i) {
    return static_cast<int>(std::upper_bound(starts.begin(), starts.end() - 1, i) -
                            starts.begin()) -
           1;
  };
  // The entries in rows owned elsewhere, grouped by owner, as (row, column) pairs.
  std::vector<int> send_counts(static_cast<std::size_t>(ranks), 0);
  for_each_entry(part, [&](int i, int, int) {
    if (!owns_global_row(part, i)) send_counts[static_cast<std::size_t>(owner(i))] += 2;
  });
  std::vector<int> send_offsets(static_cast<std::size_t>(ranks) + 1, 0);
  for (int r = 0; r < ranks; ++r) send_offsets[r + 1] = send_offsets[r] + send_counts[r];
  std::vector<int> sent(static_cast<std::size_t>(send_offsets[ranks]));
  {
    std::vector<int> fill(send_offsets.begin(), send_offsets.end() - 1);
    for_each_entry(part, [&](int i, int j, int) {
      if (owns_global_row(part, i)) return;
      int& at = fill[static_cast<std::size_t>(owner(i))];
      sent[static_cast<std::size_t>(at++)] = i;
      sent[static_cast<std::size_t>(at++)] = j;
    });
  }
  std::vector<int> receive_counts(static_cast<std::size_t>(ranks));
  PetscCallMPI(MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT,
                            PETSC_COMM_WORLD));
  std::vector<int> receive_offsets(static_cast<std::size_t>(ranks) + 1, 0);
  for (int r = 0; r < ranks; ++r) receive_offsets[r + 1] = receive_offsets[r] + receive_counts[r];
  std::vector<int> received(static_cast<std::size_t>(receive_offsets[ranks]));
  PetscCallMPI(MPI_Alltoallv(sent.data(), send_counts.data(), send_offsets.data(), MPI_INT,
                             received.data(), receive_counts.data(), receive_offsets.data(),
                             MPI_INT, PETSC_COMM_WORLD));
  // The owned rows in compressed form: this rank's entries there and those it was sent.
  const CompressedRows owned = compress_owned_rows(part, first_row_, local_rows_, received);
  const std::vector<PetscInt>& row_ptr = owned.row_ptr;
  const std::vector<PetscInt>& columns = owned.columns;
  const std::size_t kept = columns.size();
  // PETSc keeps the owned rows as two blocks, the columns it owns (diagonal block) and the others
  // (off-diagonal block), each row's entries in the order of their columns: the place of entry
  // q of the compressed rows is 2k for the k-th value of the diagonal block, 2k + 1 for the k-th
  // of the other.
  std::vector<int> block_place(kept);
  diagonal_entries_ = off_diagonal_entries_ = 0;
  for (std::size_t q = 0; q < kept; ++q) {
    const bool diagonal = columns[q] >= first_row_ && columns[q] < first_row_ + local_rows_;
    block_place[q] = diagonal ? 2 * diagonal_entries_++ : 2 * off_diagonal_entries_++ + 1;
  }
  const auto place = [&](int i, int j) {
    const auto first = columns.begin() + row_ptr[static_cast<std::size_t>(i - first_row_)];
    const auto last = columns.begin() + row_ptr[static_cast<std::size_t>(i - first_row_) + 1];
    return block_place[static_cast<std::size_t>(std::lower_bound(first, last, j) -
                                                columns.begin())];
  };
  // Where each entry of the part goes: its place among the owned values, or for a value sent to
  // another rank kSentToDiagonal or kSentToOffDiagonal, the block it goes to there.
  std::size_t entries = 0;
  for_each_entry(part, [&](int, int, int) { ++entries; });
  entry_place_.clear();
  entry_place_.reserve(entries);
  for_each_entry(part, [&](int i, int j, int) {
    entry_place_.push_back(owns_global_row(part, i) ? place(i, j) : -1);
  });
  // The places of the received entries, sent back: the roots of the sent values.
  std::vector<int> received_places(received.size() / 2);
  for (std::size_t q = 0; q < received.size(); q += 2) {
    received_places[q / 2] = place(received[q], received[q + 1]);
  }
  for (int r = 0; r <= ranks; ++r) {
    send_offsets[r] /= 2;
    receive_offsets[r] /= 2;
  }
  for (int r = 0; r < ranks; ++r) {
    send_counts[r] /= 2;
    receive_counts[r] /= 2;
  }
  std::vector<int> sent_places(static_cast<std::size_t>(send_offsets[ranks]));
  PetscCallMPI(MPI_Alltoallv(received_places.data(), receive_counts.data(), receive_offsets.data(),
                             MPI_INT, sent_places.data(), send_counts.data(), send_offsets.data(),
                             MPI_INT, PETSC_COMM_WORLD));
  // The sent values in the order of for_each_entry, owner by owner as grouped above, go to the
  // owner's diagonal block or to its other one: a star forest for each.
  std::vector<PetscSFNode> to_diagonal, to_off_diagonal;
  {
    std::vector<int> fill(send_offsets.begin(), send_offsets.end() - 1);
    std::size_t entry = 0;
    for_each_entry(part, [&](int i, int, int) {
      const std::size_t e = entry++;
      if (owns_global_row(part, i)) return;
      const int r = owner(i);
      const int at = sent_places[static_cast<std::size_t>(fill[r]++)];
      if (at % 2 == 0) {
        to_diagonal.push_back({r, at / 2});
      } else {
        to_off_diagonal.push_back({r, at / 2});
        entry_place_[e] = kSentToOffDiagonal;
      }
    });
  }
  // For the step's log line: how the parts and what they send compare over the ranks.
  {
    const double mine[2] = {static_cast<double>(entries),
                            static_cast<double>(to_diagonal.size() + to_off_diagonal.size())};
    double sum[2] = {0, 0}, most[2] = {0, 0};
    PetscCallMPI(MPI_Allreduce(mine, sum, 2, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD));
    PetscCallMPI(MPI_Allreduce(mine, most, 2, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD));
    assembly_summary_ = fmt::format(
        "assembled by rows on {} ranks: each assembles its part ({:.3g} entries at most, {:.3g} "
        "in all) and sends the values of those in other ranks' rows to them ({:.3g} at most, "
        "{:.3g} in all, per assembly)",
        ranks, most[0], sum[0], most[1], sum[1]);
  }
  sent_to_diagonal_.assign(to_diagonal.size(), 0.0);
  sent_to_off_diagonal_.assign(to_off_diagonal.size(), 0.0);
  const auto star_forest = [&](PetscSF& forest, std::vector<PetscSFNode>& roots, int count) {
    PetscCall(PetscSFCreate(PETSC_COMM_WORLD, &forest));
    PetscCall(PetscSFSetGraph(forest, count, static_cast<PetscInt>(roots.size()), nullptr,
                              PETSC_COPY_VALUES, roots.data(), PETSC_COPY_VALUES));
    PetscCall(PetscSFSetUp(forest));
    return PetscErrorCode(0);
  };
  PetscCall(star_forest(diagonal_forest_, to_diagonal, diagonal_entries_));
  PetscCall(star_forest(off_diagonal_forest_, to_off_diagonal, off_diagonal_entries_));
  PetscCall(MatCreate(PETSC_COMM_WORLD, &matrix_));
  PetscCall(MatSetSizes(matrix_, local_rows_, local_rows_, n, n));
  PetscCall(MatSetBlockSize(matrix_, node_block_));
  PetscCall(MatSetType(matrix_, MATMPIAIJ));
  {
    // Explicit zeros are kept (PETSc drops none unless told to): the blocks hold every entry.
    const std::vector<PetscScalar> zeros(columns.size(), 0.0);
    PetscCall(MatMPIAIJSetPreallocationCSR(matrix_, row_ptr.data(), columns.data(), zeros.data()));
  }
  PetscCall(MatSetOption(matrix_, MAT_NEW_NONZERO_LOCATION_ERR, PETSC_TRUE));
  {
    Mat diagonal = nullptr, off_diagonal = nullptr;
    const PetscInt* off_diagonal_columns = nullptr;
    PetscCall(MatMPIAIJGetSeqAIJ(matrix_, &diagonal, &off_diagonal, &off_diagonal_columns));
    MatInfo a{}, b{};
    PetscCall(MatGetInfo(diagonal, MAT_LOCAL, &a));
    PetscCall(MatGetInfo(off_diagonal, MAT_LOCAL, &b));
    if (a.nz_used != diagonal_entries_ || b.nz_used != off_diagonal_entries_) {
      throw std::logic_error("PetscSolver: the MPIAIJ blocks do not keep the given layout");
    }
  }
  PetscCall(VecCreateMPIWithArray(PETSC_COMM_WORLD, 1, local_rows_, n, nullptr, &rhs_));
  PetscCall(MatCreateVecs(matrix_, &solution_, &work_));
  summed_rows_ = n;
  if (!part.over_local_equations()) {
    // The solution gathered whole to every rank.
    PetscCall(VecScatterCreateToAll(solution_, &gather_, &whole_solution_));
    rhs_first_ = first_row_;
  } else {
    // Vectors by rows: a rank's right-hand side is its owned rows, and it gets the solution of
    // its owned and ghost equations only (docs/parallel.md "Vectors by rows").
    const std::vector<PetscInt> held(part.global_equation.begin(), part.global_equation.end());
    IS from = nullptr;
    PetscCall(ISCreateGeneral(PETSC_COMM_SELF, static_cast<PetscInt>(held.size()), held.data(),
                              PETSC_COPY_VALUES, &from));
    PetscCall(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, part.n, nullptr, &whole_solution_));
    PetscCall(VecScatterCreate(solution_, from, whole_solution_, nullptr, &gather_));
    PetscCall(ISDestroy(&from));
    rhs_first_ = 0;
  }
  return direct_ ? use_direct() : configure_iterative();
}

PetscErrorCode PetscSolver::sum_parts(const SparseMatrix& part) {
  Mat diagonal = nullptr, off_diagonal = nullptr;
  const PetscInt* off_diagonal_columns = nullptr;
  PetscScalar *a = nullptr, *b = nullptr;
  PetscCall(MatMPIAIJGetSeqAIJ(matrix_, &diagonal, &off_diagonal, &off_diagonal_columns));
  PetscCall(MatSeqAIJGetArray(diagonal, &a));
  PetscCall(MatSeqAIJGetArray(off_diagonal, &b));
  std::fill(a, a + diagonal_entries_, 0.0);
  std::fill(b, b + off_diagonal_entries_, 0.0);
  std::size_t entry = 0, to_a = 0, to_b = 0;
  for_each_entry(part, [&](int, int, int p) {
    const double value = part.values[static_cast<std::size_t>(p)];
    const int at = entry_place_[entry++];
    if (at >= 0) {
      (at % 2 == 0 ? a : b)[at / 2] += value;
    } else if (at == kSentToDiagonal) {
      sent_to_diagonal_[to_a++] = value;
    } else {
      sent_to_off_diagonal_[to_b++] = value;
    }
  });
  PetscCall(
      PetscSFReduceBegin(diagonal_forest_, MPIU_SCALAR, sent_to_diagonal_.data(), a, MPI_SUM));
  PetscCall(PetscSFReduceBegin(off_diagonal_forest_, MPIU_SCALAR, sent_to_off_diagonal_.data(), b,
                               MPI_SUM));
  PetscCall(PetscSFReduceEnd(diagonal_forest_, MPIU_SCALAR, sent_to_diagonal_.data(), a, MPI_SUM));
  PetscCall(PetscSFReduceEnd(off_diagonal_forest_, MPIU_SCALAR, sent_to_off_diagonal_.data(), b,
                             MPI_SUM));
  PetscCall(MatSeqAIJRestoreArray(diagonal, &a));
  PetscCall(MatSeqAIJRestoreArray(off_diagonal, &b));
  // The blocks changed under the distributed matrix: an assembly (nothing is stashed) marks it
  // changed, so that the preconditioner sees new values.
  PetscCall(MatAssemblyBegin(matrix_, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(matrix_, MAT_FINAL_ASSEMBLY));
  return 0;
}

PetscErrorCode PetscSolver::classify_owned_rows(int& zero_row, bool& indefinite) {
  // A row of zeros (an unrestrained DOF, connection-types.md §1.1), a row with its diagonal only
  // (solved exactly after an iterative solve), a diagonal that is not positive (not definite):
  // each rank reads its own rows, and the ranks agree on the first zero row and on definiteness.
  decoupled_lines_.clear();
  int my_zero = summed_rows_, my_indefinite = 0;
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
