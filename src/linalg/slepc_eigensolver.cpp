#include "src/linalg/slepc_eigensolver.hpp"

#include <slepceps.h>

#include <cmath>
#include <stdexcept>
#include <utility>

#include "src/linalg/petsc_runtime.hpp"

namespace clinch {
namespace {

// The symmetric matrix whose upper triangle is given by (row, column, value) triples, as an AIJ
// matrix over PETSC_COMM_WORLD of which this rank fills rows [first, first + local).
template <typename Visit>
PetscErrorCode symmetric_aij(int n, Visit&& visit, Mat* out) {
  PetscInt local = PETSC_DECIDE, global = n;
  PetscCall(PetscSplitOwnership(PETSC_COMM_WORLD, &local, &global));
  PetscInt first = 0;
  PetscCallMPI(MPI_Scan(&local, &first, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  first -= local;
  std::vector<std::vector<std::pair<PetscInt, PetscScalar>>> rows(static_cast<std::size_t>(local));
  auto add = [&](int row, int column, double value) {
    if (row >= first && row < first + local) {
      rows[static_cast<std::size_t>(row - first)].emplace_back(column, value);
    }
  };
  visit([&](int row, int column, double value) {
    add(row, column, value);
    if (row != column) add(column, row, value);
  });
  std::vector<PetscInt> diagonal(rows.size()), off(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (const auto& [column, value] : rows[i]) {
      ++(column >= first && column < first + local ? diagonal[i] : off[i]);
    }
  }
  PetscCall(MatCreateAIJ(PETSC_COMM_WORLD, local, local, n, n, 0, diagonal.data(), 0, off.data(),
                         out));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (const auto& [column, value] : rows[i]) {
      PetscCall(MatSetValue(*out, first + static_cast<PetscInt>(i), column, value, ADD_VALUES));
    }
  }
  PetscCall(MatAssemblyBegin(*out, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*out, MAT_FINAL_ASSEMBLY));
  return 0;
}

PetscErrorCode build(const SparseMatrix& k, const LumpedMass& mass, Mat* stiffness, Mat* m) {
  PetscCall(symmetric_aij(
      k.n,
      [&](auto&& emit) {
        for (int column = 0; column < k.n; ++column) {
          for (int at = k.col_ptr[static_cast<std::size_t>(column)];
               at < k.col_ptr[static_cast<std::size_t>(column) + 1]; ++at) {
            emit(k.row_idx[static_cast<std::size_t>(at)], column,
                 k.values[static_cast<std::size_t>(at)]);
          }
        }
      },
      stiffness));
  PetscCall(symmetric_aij(
      k.n,
      [&](auto&& emit) {
        for (const MassEntry& e : mass.entries) emit(e.row, e.column, e.value);
      },
      m));
  return 0;
}

// The text of PETSc's last error, for the step's message.
std::string petsc_error(PetscErrorCode code) {
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  return text != nullptr ? text : "PETSc error";
}

}  // namespace

SlepcEigensolver::SlepcEigensolver(const SparseMatrix& k, const LumpedMass& mass, double shift)
    : n_(k.n), shift_(shift) {
  std::string message;
  if (!ensure_petsc_initialized(&message)) throw std::runtime_error(message);
  // PETSc is already running: SlepcInitialize registers SLEPc's classes only, and finalizing
  // PETSc at exit finalizes SLEPc too.
  if (PetscErrorCode code = SlepcInitializeNoArguments(); code != 0) {
    throw std::runtime_error("SLEPc could not start: " + petsc_error(code));
  }
  if (PetscErrorCode code = build(k, mass, &stiffness_, &mass_); code != 0) {
    throw std::runtime_error("SLEPc matrices: " + petsc_error(code));
  }
}

SlepcEigensolver::~SlepcEigensolver() {
  EPSDestroy(&eps_);
  MatDestroy(&stiffness_);
  MatDestroy(&mass_);
}

std::string SlepcEigensolver::name() const {
  int ranks = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &ranks);
  return "SLEPc Krylov-Schur, shift-and-invert with MUMPS, on " + std::to_string(ranks) +
         (ranks == 1 ? " rank" : " ranks");
}

bool SlepcEigensolver::find(int wanted, std::string* error) {
  if (const PetscErrorCode code = solve(wanted); code != 0) {
    *error = "SLEPc could not solve K φ = λ M φ near σ = " + std::to_string(shift_) + ": " +
             petsc_error(code);
    return false;
  }
  if (!converged_) {
    *error = "SLEPc's Krylov-Schur iteration did not converge for " + std::to_string(wanted) +
             " eigenvalues (" + std::to_string(eigenvalues_.size()) + " converged, " + reason_ + ")";
    return false;
  }
  return true;
}

PetscErrorCode SlepcEigensolver::solve(int wanted) {
  if (eps_ == nullptr) {
    PetscCall(EPSCreate(PETSC_COMM_WORLD, &eps_));
    PetscCall(EPSSetOperators(eps_, stiffness_, mass_));
    PetscCall(EPSSetProblemType(eps_, EPS_GHEP));
    PetscCall(EPSSetType(eps_, EPSKRYLOVSCHUR));
    PetscCall(EPSSetTarget(eps_, shift_));
    PetscCall(EPSSetWhichEigenpairs(eps_, EPS_TARGET_MAGNITUDE));
    // The relative residual the serial Lanczos asks of Fᵀ(K − σM)⁻¹F (frequency_eigensolver.cpp).
    PetscCall(EPSSetTolerances(eps_, 1e-12, 1000));
    ST st = nullptr;
    PetscCall(EPSGetST(eps_, &st));
    PetscCall(STSetType(st, STSINVERT));
    KSP ksp = nullptr;
    PetscCall(STGetKSP(st, &ksp));
    PetscCall(KSPSetType(ksp, KSPPREONLY));
    PC pc = nullptr;
    PetscCall(KSPGetPC(ksp, &pc));
    PetscCall(PCSetType(pc, PCLU));
    PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
    PetscCall(EPSSetFromOptions(eps_));
  }
  PetscCall(EPSSetDimensions(eps_, wanted, PETSC_DEFAULT, PETSC_DEFAULT));
  PetscCall(EPSSolve(eps_));
  PetscInt converged = 0;
  PetscCall(EPSGetConverged(eps_, &converged));
  // A breakdown is the Krylov space in the M inner product becoming invariant: M has fewer
  // independent mass directions than asked for (the factor's columns may be dependent, as on the
  // tie nodes of a rigid body), a new direction has M-norm zero, and every finite eigenvalue is
  // among those converged. M is semi-definite, so no other breakdown can occur.
  EPSConvergedReason reason = EPS_CONVERGED_ITERATING;
  PetscCall(EPSGetConvergedReason(eps_, &reason));
  converged_ = reason > 0 || reason == EPS_DIVERGED_BREAKDOWN;
  reason_ = EPSConvergedReasons[reason];
  eigenvalues_.clear();
  vectors_.clear();
  Vec x = nullptr, whole = nullptr;
  VecScatter gather = nullptr;
  PetscCall(MatCreateVecs(stiffness_, &x, nullptr));
  PetscCall(VecScatterCreateToAll(x, &gather, &whole));
  for (PetscInt i = 0; i < converged; ++i) {
    PetscScalar lambda = 0;
    PetscCall(EPSGetEigenpair(eps_, i, &lambda, nullptr, x, nullptr));
    if (!std::isfinite(lambda)) continue;
    PetscCall(VecScatterBegin(gather, x, whole, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(gather, x, whole, INSERT_VALUES, SCATTER_FORWARD));
    const PetscScalar* values = nullptr;
    PetscCall(VecGetArrayRead(whole, &values));
    eigenvalues_.push_back(lambda);
    vectors_.emplace_back(Eigen::Map<const Eigen::VectorXd>(values, n_));
    PetscCall(VecRestoreArrayRead(whole, &values));
  }
  PetscCall(VecScatterDestroy(&gather));
  PetscCall(VecDestroy(&whole));
  PetscCall(VecDestroy(&x));
  return 0;
}

}  // namespace clinch
