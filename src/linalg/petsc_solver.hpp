// PETSc backend, the one that scales past a direct factorization (ARCHITECTURE.md "Beyond one
// machine"): conjugate gradients preconditioned by hypre BoomerAMG for symmetric positive definite
// tangents, GMRES with BoomerAMG for unsymmetric ones without multipliers (friction, damage:
// behaviors.md §7.4), MUMPS LU through PETSc for KKT systems with multipliers
// (connection-types.md §3.8) and for any system on which the Krylov method fails. On one process
// the matrix is a sequential AIJ; under mpirun each rank holds its share of the rows, and every
// rank passes the same whole matrix and right-hand side and receives the whole solution
// (docs/parallel.md).
#pragma once

#include <utility>
#include <vector>

#include "src/linalg/linear_solver.hpp"

// PETSc's handle types, declared as petscsys.h, petscmat.h, petscvec.h and petscksp.h do, so that
// this header does not pull PETSc and MPI into everything that builds a solver.
typedef struct _p_Mat* Mat;
typedef struct _p_Vec* Vec;
typedef struct _p_KSP* KSP;
typedef struct _p_PetscSF* PetscSF;  // VecScatter is PetscSF

namespace clinch {

class PetscSolver final : public LinearSolver {
 public:
  // `symmetric` and `positive_definite` as for make_linear_solver: both true selects CG + AMG,
  // positive_definite alone (no multipliers) GMRES + AMG, anything else MUMPS.
  PetscSolver(bool symmetric, bool positive_definite);
  ~PetscSolver() override;
  PetscSolver(const PetscSolver&) = delete;
  PetscSolver& operator=(const PetscSolver&) = delete;

  const char* name() const override { return "petsc"; }
  LinearStatus analyze(const SparseMatrix& pattern, std::string* message) override;
  // CG + AMG factors nothing, so beyond the checks every backend makes (non-finite entries, a
  // row and column of zeros) it cannot tell a singular matrix here; a singular system shows at
  // solve, where CG fails and MUMPS then reports it.
  LinearStatus factorize(const SparseMatrix& k, std::string* message) override;
  LinearStatus solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, std::string* message) override;
  int failed_pivot() const override { return failed_pivot_; }
  // Throws std::invalid_argument outside 0 < rtol < 1.
  void set_relative_tolerance(double rtol) override;
  // Assembled by rows: the sizes of the ranks' parts and of what they send per assembly.
  std::string choice() const override { return summed_ ? assembly_summary_ : std::string(); }

  // "cg+boomeramg", "gmres+boomeramg" or "mumps": the method the next solve uses.
  const char* method() const {
    return direct_ ? "mumps" : symmetric_ ? "cg+boomeramg" : "gmres+boomeramg";
  }
  // Krylov iterations of the last solve (1 for MUMPS), and how many AMG setups have been made;
  // for reports, tests and benchmarks.
  int iterations() const { return iterations_; }
  int preconditioner_setups() const { return preconditioner_setups_; }
  // PETSc's own description of the method after the last factorize (KSPView): what BoomerAMG
  // or MUMPS was actually told, for tests and diagnostics.
  std::string view() const;

 private:
  void release();
  // The AIJ matrix with its exact pattern, the vectors and the KSP of the current method.
  int create_objects();
  int create_distributed_objects();
  // Writes the values of `k` into the matrix (this rank's rows when distributed).
  int copy_values(const SparseMatrix& k);
  // A matrix assembled by rows (petsc_summed_matrix.cpp): the distributed matrix of the owned
  // rows of every rank's part, the parts summed into it, and its owned rows read for a row of
  // zeros, rows with their diagonal only and diagonals that are not positive.
  int create_summed_objects(const SparseMatrix& part);
  int sum_parts(const SparseMatrix& part);
  int classify_owned_rows(int& zero_row, bool& indefinite);
  LinearStatus factorize_summed(const SparseMatrix& part, std::string* message);
  // CG with BoomerAMG unless `indefinite` or the KSP is already MUMPS's; then LU.
  LinearStatus factor_or_set_up(bool indefinite, std::string* message);
  // True when some rank has `mine` set; `text` is then the lowest such rank's on every rank.
  static bool first_rank_with(bool mine, std::string& text);
  // Makes the KSP a MUMPS LU for good (the matrix proved indefinite or CG failed on it).
  int use_direct();
  int configure_iterative();
  // Numeric LU of the current values; Singular when MUMPS meets a null pivot.
  LinearStatus factor_directly(std::string* message);
  // Builds the AMG hierarchy of the current values, or keeps the last one (see the .cpp).
  LinearStatus set_up_iterative(std::string* message);
  // One KSPSolve on the vectors placed over b and x; the KSPConvergedReason is kept in
  // `reason_`. These helpers return PETSc error codes (PetscErrorCode).
  int run_solve();
  int set_up_preconditioner();
  // The KSP's tolerances: rtol_ and at most `iterations` iterations.
  int limit_iterations(int iterations);

  bool symmetric_;
  bool direct_;
  std::string init_error_;
  // Several ranks: this rank's rows [first_row_, first_row_ + local_rows_) of the distributed
  // matrix, its values in the order of that share of col_idx_ (of its compressed rows when
  // assembled by rows), and the scatter that gives every rank the whole solution.
  bool distributed_ = false;
  int first_row_ = 0, local_rows_ = 0;
  // Where the owned rows start in the caller's vectors: first_row_ when they run over every
  // equation, 0 over a rank's local equations (owned rows first: SparseMatrix::global_equation).
  int rhs_first_ = 0;
  // Assembled by rows (SparseMatrix::partial, petsc_summed_matrix.cpp): for each entry of this
  // rank's part (both triangles of upper storage) its place in the values of the owned rows'
  // diagonal block (2k) or off-diagonal block (2k + 1), or when its row is another rank's the
  // block it goes to there (negative); the values sent to each kind of block, and the star
  // forests that add them to their owners' blocks.
  bool summed_ = false;
  std::vector<int> entry_place_;
  int diagonal_entries_ = 0, off_diagonal_entries_ = 0;
  std::vector<double> sent_to_diagonal_, sent_to_off_diagonal_;
  PetscSF diagonal_forest_ = nullptr, off_diagonal_forest_ = nullptr;
  std::string assembly_summary_;
  std::vector<double> local_values_;
  // The scatter of the solution to the caller's vector: the whole of it, or over a rank's local
  // equations its owned and ghost entries; and the size of the summed system.
  PetscSF gather_ = nullptr;
  Vec whole_solution_ = nullptr;
  int summed_rows_ = 0;
  Mat matrix_ = nullptr;
  KSP ksp_ = nullptr;
  Vec rhs_ = nullptr, solution_ = nullptr, work_ = nullptr;
  int n_ = -1;
  int input_nonzeros_ = 0;
  int node_block_ = 1;  // SparseMatrix::node_block of the analysed pattern
  // The full pattern in compressed rows (PETSc's AIJ layout); `source_[q]` is the index in the
  // caller's values of AIJ entry q, so that factorize only gathers values.
  std::vector<int> row_ptr_, col_idx_;
  std::vector<int> source_;
  std::vector<int> diagonal_;
  // Per line of the current values: 0 no nonzero entry, 1 its diagonal only, 2 coupled to
  // another line; and the lines of kind 1 with their diagonal value (assembled by rows: the
  // owned rows with their diagonal only).
  std::vector<char> line_entries_;
  std::vector<std::pair<int, double>> decoupled_lines_;
  double rtol_ = 1e-10;
  bool factorized_ = false;
  int failed_pivot_ = -1;
  int reason_ = 0;
  int iterations_ = 0;
  // AMG reuse: the iterations of the first solve after the last setup, whether the current
  // hierarchy was built for the current values, and whether the next factorize must rebuild.
  int baseline_iterations_ = -1;
  bool preconditioner_is_fresh_ = false;
  bool rebuild_preconditioner_ = true;
  int preconditioner_setups_ = 0;
};

}  // namespace clinch
