#include "src/linalg/petsc_solver.hpp"

#include <fmt/format.h>
#include <petscksp.h>
#include <petscsf.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "src/linalg/petsc_runtime.hpp"
#include "src/linalg/pivot_checks.hpp"
#include "src/parallel/communicator.hpp"

namespace clinch {
namespace {

// The pattern arrays are handed to PETSc as they are; PETSc's error codes are returned as int.
static_assert(std::is_same_v<PetscInt, int>, "PETSc built with 64-bit indices");
static_assert(std::is_same_v<PetscErrorCode, int>);
static_assert(std::is_same_v<PetscScalar, double>, "PETSc built for complex or single precision");

// Stops a run of conjugate gradients that no longer converges (a singular or badly
// preconditioned system) long before PETSc's default of 10⁴: AMG-preconditioned CG takes tens of
// iterations on the tangents it is meant for, whatever their size.
constexpr PetscInt kMaxIterations = 1000;
// The relative tolerance governs; the absolute one only ends a solve whose right-hand side is
// already zero.
constexpr double kAbsoluteTolerance = 1e-50;
// A reused AMG hierarchy is rebuilt once a solve needs more than twice the iterations of the first
// solve after the last setup, plus this slack so that small counts (3 → 7) do not trigger it.
// Rebuilding costs about as much as a few tens of iterations, so a hierarchy that has lost
// half its effectiveness is no longer worth keeping.
constexpr int kIterationSlack = 5;
// A solve on a reused hierarchy stops after this many iterations at the least (more where the
// rebuild rule allows more) and is repeated on a rebuilt one: more than twice what the irregular
// lattices' solves take on a good hierarchy (at most 14 with N = 30), a third of what a stale one
// took on the friction lattice at the first solve of a new step.
constexpr int kStaleCap = 25;
// Not a KSPConvergedReason: CG reported convergence but the true residual is above the tolerance.
constexpr int kTrueResidualTooLarge = -1000;

std::string reason_name(int reason) {
  if (reason == kTrueResidualTooLarge) return "a true residual above the tolerance";
  return KSPConvergedReasons[reason];
}

// BoomerAMG settings for 3-D problems (PETSc's defaults suit 2-D): HMIS coarsening with
// extended+i interpolation and at most 4 entries per row of the interpolation keep the hierarchy
// sparse (on the 20³ axial lattice, 24 000 dofs, CG + AMG went from 10.9 s to 0.8 s per two
// solves); one level of aggressive coarsening and a strength threshold of 0.7 thin the first
// levels further, where the smoother's sweeps cost most: the linear SPRINGA lattice with N = 40
// (192 000 dofs) went from 58 s to 15 s, and with N = 25 its four Newton iterations took 30 CG
// iterations instead of 57 (docs/parallel.md). An option given in PETSC_OPTIONS wins.
constexpr std::pair<const char*, const char*> kBoomerAmgDefaults[] = {
    {"-pc_hypre_boomeramg_strong_threshold", "0.7"},
    {"-pc_hypre_boomeramg_agg_nl", "1"},
    {"-pc_hypre_boomeramg_coarsen_type", "HMIS"},
    {"-pc_hypre_boomeramg_interp_type", "ext+i"},
    {"-pc_hypre_boomeramg_P_max", "4"},
};

// One forward sweep of hybrid Gauss–Seidel going down the V-cycle and one backward sweep coming
// up keep the cycle symmetric, as CG needs, at half the fine-level work of PETSc's default (a
// symmetric sweep each way): the fine level holds almost all of the operator (complexity 1.02
// on the irregular lattices), and its sweeps are most of a cycle. On the irregular NLGEOM
// lattice with N = 30 a cycle went from 67 ms to 37–42 ms for 19 % more CG iterations, the
// whole run from 16.5 s to 12.5–14.1 s (docs/parallel.md). A relax_type_all given in
// PETSC_OPTIONS replaces both.
constexpr std::pair<const char*, const char*> kRelaxationDefaults[] = {
    {"-pc_hypre_boomeramg_relax_type_down", "SOR/Jacobi"},
    {"-pc_hypre_boomeramg_relax_type_up", "backward-SOR/Jacobi"},
};
constexpr const char* kRelaxAll = "-pc_hypre_boomeramg_relax_type_all";

// For a matrix of node blocks (SparseMatrix::node_block > 1) PETSc hands the block size to
// BoomerAMG as its number of functions, and nodal coarsening by the row-sum norm of each node's
// block (HYPRE_BoomerAMGSetNodal 4) coarsens nodes rather than single equations, as elasticity
// wants: on the linear SPRINGA lattice with N = 40 a Newton iteration went from 3.5 s to 0.9 s,
// and the 10⁶-DOF lattice from 368 s to under 40 s (docs/parallel.md).
constexpr const char* kNodalCoarsening = "-pc_hypre_boomeramg_nodal_coarsen";
constexpr const char* kNodalNorm = "4";

// Whether the user set `name` in PETSC_OPTIONS (or the command line PETSc saw), as first seen:
// the defaults below are set in the same options database, so later looks cannot tell.
bool given_by_user(const char* name) {
  static std::vector<std::string> given = [] {
    std::vector<std::string> names;
    for (const auto& [option, value] : kBoomerAmgDefaults) names.emplace_back(option);
    for (const auto& [option, value] : kRelaxationDefaults) names.emplace_back(option);
    names.emplace_back(kNodalCoarsening);
    names.emplace_back(kRelaxAll);
    std::erase_if(names, [](const std::string& option) {
      PetscBool has = PETSC_FALSE;
      PetscOptionsHasName(nullptr, nullptr, option.c_str(), &has);
      return !has;
    });
    return names;
  }();
  return std::find(given.begin(), given.end(), name) != given.end();
}

PetscErrorCode set_boomeramg_defaults(bool nodal) {
  for (const auto& [name, value] : kBoomerAmgDefaults) {
    if (!given_by_user(name)) PetscCall(PetscOptionsSetValue(nullptr, name, value));
  }
  for (const auto& [name, value] : kRelaxationDefaults) {
    if (!given_by_user(name) && !given_by_user(kRelaxAll)) {
      PetscCall(PetscOptionsSetValue(nullptr, name, value));
    }
  }
  if (given_by_user(kNodalCoarsening)) return 0;
  if (nodal) {
    PetscCall(PetscOptionsSetValue(nullptr, kNodalCoarsening, kNodalNorm));
  } else {
    PetscCall(PetscOptionsClearValue(nullptr, kNodalCoarsening));
  }
  return 0;
}

LinearStatus petsc_failure(PetscErrorCode code, const char* stage, std::string* message) {
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  set_message(message,
              fmt::format("PETSc {} failed: {} (error {})", stage,
                          text != nullptr ? text : "unknown error", static_cast<int>(code)));
  return LinearStatus::Failure;
}

}  // namespace

PetscSolver::PetscSolver(bool symmetric, bool positive_definite)
    : symmetric_(symmetric), direct_(!positive_definite) {
  if (!ensure_petsc_initialized(&init_error_)) return;
  int ranks = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &ranks);
  distributed_ = ranks > 1;
}

PetscSolver::~PetscSolver() { release(); }

void PetscSolver::release() {
  if (ksp_ != nullptr) KSPDestroy(&ksp_);
  if (matrix_ != nullptr) MatDestroy(&matrix_);
  if (rhs_ != nullptr) VecDestroy(&rhs_);
  if (solution_ != nullptr) VecDestroy(&solution_);
  if (work_ != nullptr) VecDestroy(&work_);
  if (gather_ != nullptr) VecScatterDestroy(&gather_);
  if (diagonal_forest_ != nullptr) PetscSFDestroy(&diagonal_forest_);
  if (off_diagonal_forest_ != nullptr) PetscSFDestroy(&off_diagonal_forest_);
  if (whole_solution_ != nullptr) VecDestroy(&whole_solution_);
  factorized_ = false;
}

void PetscSolver::set_relative_tolerance(double rtol) {
  if (!(rtol > 0.0 && rtol < 1.0)) {
    throw std::invalid_argument(fmt::format("relative tolerance {} outside (0, 1)", rtol));
  }
  rtol_ = rtol;
  if (ksp_ != nullptr && !direct_) {
    limit_iterations(kMaxIterations);
  }
}

LinearStatus PetscSolver::analyze(const SparseMatrix& pattern, std::string* message) {
  validate_pattern(pattern);
  release();
  failed_pivot_ = -1;
  n_ = -1;
  if (!init_error_.empty()) {
    set_message(message, init_error_);
    return LinearStatus::Failure;
  }
  const int n = pattern.n;
  input_nonzeros_ = pattern.nonzeros();
  node_block_ = pattern.node_block;
  summed_ = pattern.partial();
  if (summed_ && !distributed_) {
    throw std::invalid_argument("PetscSolver::analyze: a part of a matrix on one process");
  }
  if (!summed_) {
    diagonal_ = diagonal_positions(pattern);
    line_entries_.assign(n, 0);
    // Full pattern in compressed rows (AIJ's layout) and its gather map.
    FullPattern full = full_pattern(pattern, true);
    row_ptr_ = std::move(full.ptr);
    col_idx_ = std::move(full.idx);
    source_ = std::move(full.source);
  }
  // A part over a rank's local equations may be empty while the summed system is not.
  if (pattern.summed_size() == 0) {
    n_ = 0;
    summed_rows_ = 0;
    return LinearStatus::Ok;
  }
  if (const PetscErrorCode code = summed_        ? create_summed_objects(pattern)
                                  : distributed_ ? create_distributed_objects()
                                                 : create_objects();
      code != 0) {
    release();
    return petsc_failure(code, "matrix and solver setup", message);
  }
  n_ = n;
  rebuild_preconditioner_ = true;
  baseline_iterations_ = -1;
  return LinearStatus::Ok;
}

PetscErrorCode PetscSolver::create_objects() {
  const PetscInt n = static_cast<PetscInt>(row_ptr_.size()) - 1;
  // Exact preallocation from the pattern; explicit zeros are kept (PETSc drops none unless told
  // to), so the layout is the pattern and never changes.
  const std::vector<PetscScalar> zeros(col_idx_.size(), 0.0);
  PetscCall(MatCreate(PETSC_COMM_SELF, &matrix_));
  PetscCall(MatSetSizes(matrix_, n, n, n, n));
  PetscCall(MatSetBlockSize(matrix_, node_block_));
  PetscCall(MatSetType(matrix_, MATSEQAIJ));
  PetscCall(MatSeqAIJSetPreallocationCSR(matrix_, row_ptr_.data(), col_idx_.data(), zeros.data()));
  PetscCall(MatSetOption(matrix_, MAT_NEW_NONZERO_LOCATION_ERR, PETSC_TRUE));
  // factorize writes values straight into the AIJ array in the order of col_idx_: check once
  // that PETSc kept that order.
  PetscInt rows = 0;
  const PetscInt *ia = nullptr, *ja = nullptr;
  PetscBool done = PETSC_FALSE;
  PetscCall(MatGetRowIJ(matrix_, 0, PETSC_FALSE, PETSC_FALSE, &rows, &ia, &ja, &done));
  const bool same = done && rows == n && std::equal(row_ptr_.begin(), row_ptr_.end(), ia) &&
                    std::equal(col_idx_.begin(), col_idx_.end(), ja);
  PetscCall(MatRestoreRowIJ(matrix_, 0, PETSC_FALSE, PETSC_FALSE, &rows, &ia, &ja, &done));
  if (!same) throw std::logic_error("PetscSolver: the AIJ matrix does not keep the given layout");
  // The vectors wrap the caller's arrays at each solve.
  PetscCall(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n, nullptr, &rhs_));
  PetscCall(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n, nullptr, &solution_));
  PetscCall(MatCreateVecs(matrix_, nullptr, &work_));
  return direct_ ? use_direct() : configure_iterative();
}

// Under mpirun: rank r owns a contiguous share of the node blocks (owned_rows,
// src/parallel/communicator.hpp), with global column indices.
PetscErrorCode PetscSolver::create_distributed_objects() {
  const PetscInt n = static_cast<PetscInt>(row_ptr_.size()) - 1;
  int rank = 0, ranks = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &ranks);
  const ItemRange rows = owned_rows(static_cast<int>(n), node_block_, rank, ranks);
  first_row_ = static_cast<int>(rows.begin);
  local_rows_ = static_cast<int>(rows.end - rows.begin);
  rhs_first_ = first_row_;
  const int offset = row_ptr_[first_row_];
  std::vector<PetscInt> local_row_ptr(local_rows_ + 1);
  for (int r = 0; r <= local_rows_; ++r) local_row_ptr[r] = row_ptr_[first_row_ + r] - offset;
  local_values_.assign(local_row_ptr[local_rows_], 0.0);
  // MatCreateMPIAIJWithArrays, with the block size set before preallocation.
  PetscCall(MatCreate(PETSC_COMM_WORLD, &matrix_));
  PetscCall(MatSetSizes(matrix_, local_rows_, local_rows_, n, n));
  PetscCall(MatSetBlockSize(matrix_, node_block_));
  PetscCall(MatSetType(matrix_, MATMPIAIJ));
  PetscCall(MatMPIAIJSetPreallocationCSR(matrix_, local_row_ptr.data(), col_idx_.data() + offset,
                                         local_values_.data()));
  PetscCall(MatSetOption(matrix_, MAT_NEW_NONZERO_LOCATION_ERR, PETSC_TRUE));
  PetscCall(VecCreateMPIWithArray(PETSC_COMM_WORLD, 1, local_rows_, n, nullptr, &rhs_));
  PetscCall(MatCreateVecs(matrix_, &solution_, &work_));
  PetscCall(VecScatterCreateToAll(solution_, &gather_, &whole_solution_));
  return direct_ ? use_direct() : configure_iterative();
}

PetscErrorCode PetscSolver::configure_iterative() {
  PC pc = nullptr;
  PetscCall(KSPCreate(distributed_ ? PETSC_COMM_WORLD : PETSC_COMM_SELF, &ksp_));
  PetscCall(KSPSetOperators(ksp_, matrix_, matrix_));
  PetscCall(KSPSetType(ksp_, symmetric_ ? KSPCG : KSPGMRES));
  // The true residual ‖b − Ax‖ ≤ rtol ‖b‖ is what the tolerance promises, not a preconditioned
  // norm that depends on the AMG hierarchy; GMRES measures it only when preconditioned from the
  // right.
  if (!symmetric_) PetscCall(KSPSetPCSide(ksp_, PC_RIGHT));
  PetscCall(KSPSetNormType(ksp_, KSP_NORM_UNPRECONDITIONED));
  PetscCall(limit_iterations(kMaxIterations));
  PetscCall(KSPGetPC(ksp_, &pc));
  PetscCall(PCSetType(pc, PCHYPRE));
  PetscCall(PCHYPRESetType(pc, "boomeramg"));
  PetscCall(set_boomeramg_defaults(node_block_ > 1));
  // PETSC_OPTIONS can adjust the method (-ksp_monitor, other AMG settings) for measurements.
  PetscCall(KSPSetFromOptions(ksp_));
  PetscCall(limit_iterations(kMaxIterations));
  return 0;
}

PetscErrorCode PetscSolver::use_direct() {
  PC pc = nullptr;
  Mat factor = nullptr;
  if (ksp_ != nullptr) PetscCall(KSPDestroy(&ksp_));
  direct_ = true;
  PetscCall(KSPCreate(distributed_ ? PETSC_COMM_WORLD : PETSC_COMM_SELF, &ksp_));
  PetscCall(KSPSetOperators(ksp_, matrix_, matrix_));
  PetscCall(KSPSetType(ksp_, KSPPREONLY));
  PetscCall(KSPGetPC(ksp_, &pc));
  PetscCall(PCSetType(pc, PCLU));
  PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  PetscCall(PCFactorSetUpMatSolverType(pc));
  PetscCall(PCFactorGetMatrix(pc, &factor));
  // Null-pivot detection (ICNTL(24)): a pivot whose remaining row or column is below CNTL(3)
  // times the norm of the scaled matrix is counted (INFOG(28)) instead of being divided by, so
  // that an exactly singular system is reported whatever rounding left in its last pivot. The
  // tolerance is the one every backend uses (pivot_checks.hpp), relative here to the whole
  // scaled matrix rather than to the pivot's column.
  PetscCall(MatMumpsSetIcntl(factor, 24, 1));
  PetscCall(MatMumpsSetCntl(factor, 3, kSingularPivotTolerance));
  return 0;
}

LinearStatus PetscSolver::factorize(const SparseMatrix& k, std::string* message) {
  if (n_ < 0 || k.n != n_ || k.nonzeros() != input_nonzeros_) {
    throw std::logic_error("PetscSolver::factorize: matrix does not match the analysed pattern");
  }
  factorized_ = false;
  failed_pivot_ = -1;
  if (summed_ ? summed_rows_ == 0 : n_ == 0) {
    factorized_ = true;
    return LinearStatus::Ok;
  }
  if (summed_) return factorize_summed(k, message);
  if (const int p = first_non_finite(k); p >= 0) {
    set_message(message, non_finite_message(k, p, name()));
    return LinearStatus::Failure;
  }
  // An equation without any stiffness (an unrestrained dof, connection-types.md §1.1) is named
  // here, as the factorizing backends name its zero pivot.
  std::fill(line_entries_.begin(), line_entries_.end(), 0);
  for (int j = 0; j < n_; ++j) {
    for (int p = k.col_ptr[j]; p < k.col_ptr[j + 1]; ++p) {
      if (k.values[p] == 0.0) continue;
      const int i = k.row_idx[p];
      if (i == j) {
        line_entries_[j] = std::max<char>(line_entries_[j], 1);
      } else {
        line_entries_[j] = line_entries_[i] = 2;
      }
    }
  }
  if (const auto zero = std::find(line_entries_.begin(), line_entries_.end(), 0);
      zero != line_entries_.end()) {
    failed_pivot_ = static_cast<int>(zero - line_entries_.begin());
    set_message(message, pivot_message(LinearStatus::Singular, failed_pivot_, name()));
    return LinearStatus::Singular;
  }
  decoupled_lines_.clear();
  for (int j = 0; j < n_; ++j) {
    if (line_entries_[j] == 1) decoupled_lines_.emplace_back(j, k.values[diagonal_[j]]);
  }
  if (const PetscErrorCode code = copy_values(k); code != 0) {
    return petsc_failure(code, "matrix access", message);
  }
  return factor_or_set_up(std::any_of(diagonal_.begin(), diagonal_.end(),
                                      [&](int p) { return p < 0 || k.values[p] <= 0.0; }),
                          message);
}

LinearStatus PetscSolver::factorize_summed(const SparseMatrix& part, std::string* message) {
  // The first rank with a non-finite entry in its part names it on every rank.
  const int p = first_non_finite(part);
  std::string text = p >= 0 ? non_finite_message(part, p, name()) : std::string();
  if (first_rank_with(p >= 0, text)) {
    set_message(message, text);
    return LinearStatus::Failure;
  }
  int zero_row = summed_rows_;
  bool indefinite = false;
  PetscErrorCode code = sum_parts(part);
  if (code == 0) code = classify_owned_rows(zero_row, indefinite);
  if (code != 0) return petsc_failure(code, "matrix assembly", message);
  if (zero_row < summed_rows_) {
    failed_pivot_ = zero_row;
    set_message(message, pivot_message(LinearStatus::Singular, failed_pivot_, name()));
    return LinearStatus::Singular;
  }
  return factor_or_set_up(indefinite, message);
}

LinearStatus PetscSolver::factor_or_set_up(bool indefinite, std::string* message) {
  if (!direct_) {
    // A diagonal entry a_jj <= 0 proves the matrix is not positive definite (e_jᵀ K e_j = a_jj):
    // CG is not meant for it, nor BoomerAMG's smoothers; LU takes over for good, as CHOLMOD hands
    // over to UMFPACK (automatic_solver.hpp).
    if (!indefinite) return set_up_iterative(message);
    if (const PetscErrorCode code = use_direct(); code != 0) {
      return petsc_failure(code, "MUMPS setup", message);
    }
  }
  return factor_directly(message);
}

LinearStatus PetscSolver::set_up_iterative(std::string* message) {
  // Newton's tangents change little from one iteration to the next, so the AMG hierarchy of an
  // earlier tangent stays a good preconditioner for a while: CG runs on the new values with the
  // old hierarchy until the iterations show it has gone stale (kIterationSlack).
  const bool rebuild = rebuild_preconditioner_;
  PetscErrorCode code = KSPSetReusePreconditioner(ksp_, rebuild ? PETSC_FALSE : PETSC_TRUE);
  if (code == 0) code = set_up_preconditioner();
  if (code != 0) {
    rebuild_preconditioner_ = true;
    return petsc_failure(code, "BoomerAMG setup", message);
  }
  if (rebuild) {
    ++preconditioner_setups_;
    baseline_iterations_ = -1;
    rebuild_preconditioner_ = false;
  }
  preconditioner_is_fresh_ = rebuild;
  factorized_ = true;
  return LinearStatus::Ok;
}

LinearStatus PetscSolver::factor_directly(std::string* message) {
  PC pc = nullptr;
  Mat factor = nullptr;
  PetscErrorCode code = set_up_preconditioner();
  if (code == 0) code = KSPGetPC(ksp_, &pc);
  if (code == 0) code = PCFactorGetMatrix(pc, &factor);
  MatFactorError error = MAT_FACTOR_NOERROR;
  PetscInt infog1 = 0, null_pivots = 0;
  if (code == 0) code = MatFactorGetError(factor, &error);
  if (code == 0) code = MatMumpsGetInfog(factor, 1, &infog1);
  if (code == 0) code = MatMumpsGetInfog(factor, 28, &null_pivots);
  if (code != 0) return petsc_failure(code, "MUMPS factorization", message);
  // MUMPS does not say which equation a null pivot belongs to.
  if (error == MAT_FACTOR_NUMERIC_ZEROPIVOT || null_pivots > 0) {
    set_message(message, pivot_message(LinearStatus::Singular, -1, "petsc, MUMPS"));
    return LinearStatus::Singular;
  }
  if (error != MAT_FACTOR_NOERROR) {
    set_message(message, fmt::format("MUMPS factorization failed (petsc): INFOG(1) = {}",
                                     static_cast<int>(infog1)));
    return LinearStatus::Failure;
  }
  factorized_ = true;
  return LinearStatus::Ok;
}

std::string PetscSolver::view() const {
  if (ksp_ == nullptr) return {};
  char* buffer = nullptr;
  std::size_t size = 0;
  FILE* stream = open_memstream(&buffer, &size);
  if (stream == nullptr) return {};
  PetscViewer viewer = nullptr;
  if (PetscViewerASCIIOpenWithFILE(PETSC_COMM_SELF, stream, &viewer) == 0) {
    KSPView(ksp_, viewer);
    PetscViewerDestroy(&viewer);
  }
  std::fclose(stream);
  std::string text(buffer, size);
  std::free(buffer);
  return text;
}

PetscErrorCode PetscSolver::copy_values(const SparseMatrix& k) {
  if (distributed_) {
    const int offset = row_ptr_[first_row_];
    for (std::size_t q = 0; q < local_values_.size(); ++q) {
      local_values_[q] = k.values[source_[offset + q]];
    }
    PetscCall(MatUpdateMPIAIJWithArray(matrix_, local_values_.data()));
    return 0;
  }
  PetscScalar* values = nullptr;
  PetscCall(MatSeqAIJGetArray(matrix_, &values));
  for (std::size_t q = 0; q < source_.size(); ++q) values[q] = k.values[source_[q]];
  // Restoring the array marks the matrix as changed, so that PETSc refactors or rebuilds.
  PetscCall(MatSeqAIJRestoreArray(matrix_, &values));
  return 0;
}

PetscErrorCode PetscSolver::set_up_preconditioner() {
  // Once a KSP is set up, KSPSetUp leaves the preconditioner to the next KSPSolve; PCSetUp
  // refactors (or rebuilds the hierarchy) now, so that its outcome can be read here.
  PC pc = nullptr;
  PetscCall(KSPSetUp(ksp_));
  PetscCall(KSPGetPC(ksp_, &pc));
  PetscCall(PCSetUp(pc));
  return 0;
}

PetscErrorCode PetscSolver::limit_iterations(int iterations) {
  return KSPSetTolerances(ksp_, rtol_, kAbsoluteTolerance, PETSC_DEFAULT, iterations);
}

PetscErrorCode PetscSolver::run_solve() {
  PetscInt iterations = 0;
  PetscCall(KSPSolve(ksp_, rhs_, solution_));
  KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
  PetscCall(KSPGetConvergedReason(ksp_, &reason));
  reason_ = reason;
  PetscCall(KSPGetIterationNumber(ksp_, &iterations));
  iterations_ = static_cast<int>(iterations);
  if (direct_ || reason_ < 0) return 0;
  // CG measures its residual by a recurrence, which can run away from b − Ax: on a singular
  // system whose right-hand side is not in the range, AMG's near-singular coarse solve lets the
  // recurrence report convergence while x grows along the null vector. One product checks the
  // promise ‖b − Ax‖ ≤ rtol ‖b‖ that callers rely on.
  PetscReal b_norm = 0.0, r_norm = 0.0;
  PetscCall(MatMult(matrix_, solution_, work_));
  PetscCall(VecAYPX(work_, -1.0, rhs_));
  PetscCall(VecNorm(work_, NORM_2, &r_norm));
  PetscCall(VecNorm(rhs_, NORM_2, &b_norm));
  if (r_norm > rtol_ * b_norm && r_norm > kAbsoluteTolerance) reason_ = kTrueResidualTooLarge;
  return 0;
}

LinearStatus PetscSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                std::string* message) {
  if (!factorized_ || b.size() != n_) {
    throw std::logic_error("PetscSolver::solve: no factorization of this size");
  }
  x.resize(n_);
  if (summed_ ? summed_rows_ == 0 : n_ == 0) return LinearStatus::Ok;
  // KSPSolve reads b only; PETSc's vector interface has no const array. Distributed: this rank's
  // share of b, and a solution of its own gathered into x at the end.
  PetscErrorCode code = VecPlaceArray(rhs_, const_cast<double*>(b.data()) + rhs_first_);
  if (code == 0) code = VecPlaceArray(distributed_ ? whole_solution_ : solution_, x.data());
  if (code != 0) return petsc_failure(code, "vector setup", message);
  const auto reset = [&] {
    VecResetArray(rhs_);
    VecResetArray(distributed_ ? whole_solution_ : solution_);
  };
  // A reused hierarchy gets a limited number of iterations (kStaleCap): one that has gone stale
  // (the first solve of a new step, whose tangent differs from the last step's) is then rebuilt
  // at once instead of being dragged through tens of iterations (the friction lattice at 10⁵
  // sliders: 72 GMRES iterations).
  const bool capped = !direct_ && !preconditioner_is_fresh_ && baseline_iterations_ >= 0;
  if (capped) {
    code = limit_iterations(std::max(2 * baseline_iterations_ + kIterationSlack, kStaleCap));
  }
  if (code == 0) code = run_solve();
  if (capped && code == 0) {
    code = limit_iterations(kMaxIterations);
  }
  std::string iterative_failure;
  if (code == 0 && reason_ < 0 && !direct_ && !preconditioner_is_fresh_) {
    // A stale hierarchy is never a reason to fail: rebuild it for the current values and retry.
    code = KSPSetReusePreconditioner(ksp_, PETSC_FALSE);
    if (code == 0) code = set_up_preconditioner();
    if (code == 0) code = run_solve();
    ++preconditioner_setups_;
    baseline_iterations_ = -1;
    preconditioner_is_fresh_ = true;
  }
  if (code == 0 && reason_ < 0 && !direct_) {
    // The Krylov method failed with a fresh hierarchy: the matrix is indefinite or singular
    // after all. MUMPS
    // either solves it or reports it singular.
    iterative_failure = fmt::format("{} stopped on {} after {} iterations", method(),
                                    reason_name(reason_), iterations_);
    code = use_direct();
    if (code == 0) {
      const LinearStatus factored = factor_directly(message);
      if (factored != LinearStatus::Ok) {
        reset();
        if (message != nullptr) *message += "; " + iterative_failure;
        return factored;
      }
      code = run_solve();
    }
  }
  if (code == 0 && summed_ && !direct_ && reason_ >= 0 && !decoupled_lines_.empty()) {
    // The owned lines coupled to no other take their exact solution before the gather.
    PetscScalar* owned = nullptr;
    code = VecGetArray(solution_, &owned);
    if (code == 0) {
      for (const auto& [line, diagonal] : decoupled_lines_) {
        owned[line - first_row_] = b[rhs_first_ + line - first_row_] / diagonal;
      }
      code = VecRestoreArray(solution_, &owned);
    }
  }
  if (code == 0 && distributed_ && reason_ >= 0) {
    code = VecScatterBegin(gather_, solution_, whole_solution_, INSERT_VALUES, SCATTER_FORWARD);
    if (code == 0) {
      code = VecScatterEnd(gather_, solution_, whole_solution_, INSERT_VALUES, SCATTER_FORWARD);
    }
  }
  reset();
  if (code != 0) return petsc_failure(code, "solve", message);
  // A line coupled to no other (a prescribed DOF's row Δu = target − u, its column moved to the
  // right-hand side) has its exact solution: an iterative solve leaves it within the tolerance
  // only, and Newton would then never see a prescribed DOF on its target.
  if (!direct_ && reason_ >= 0 && !summed_) {
    for (const auto& [line, diagonal] : decoupled_lines_) x[line] = b[line] / diagonal;
  }
  if (reason_ < 0) {
    PetscReal residual = 0.0;
    KSPGetResidualNorm(ksp_, &residual);
    set_message(message, fmt::format("PETSc {} did not converge: {} after {} iterations (residual "
                                     "norm {:.3g}, |b| = {:.3g}){}",
                                     method(), reason_name(reason_), iterations_,
                                     static_cast<double>(residual), b.stableNorm(),
                                     iterative_failure.empty() ? "" : "; " + iterative_failure));
    return LinearStatus::Failure;
  }
  if (!direct_) {
    if (baseline_iterations_ < 0) baseline_iterations_ = iterations_;
    rebuild_preconditioner_ = iterations_ > 2 * baseline_iterations_ + kIterationSlack;
  }
  return LinearStatus::Ok;
}

}  // namespace clinch
