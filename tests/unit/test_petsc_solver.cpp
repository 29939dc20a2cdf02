// The PETSc backend's own behaviour, beyond the backend parity of test_linear_solvers.cpp: the
// KSP tolerance, AMG-CG iteration counts and the reuse of the AMG hierarchy, MUMPS recovering
// from a singular system. These tests build PetscSolver directly, so their executable links
// PETSc (clinch_petsc_unit_tests) where clinch and clinch_unit_tests load it as a plugin.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "src/linalg/linear_solver.hpp"
#include "src/linalg/petsc_solver.hpp"
#include "tests/support/model_problems.hpp"
#include "tests/unit/linear_systems.hpp"

namespace clinch {
namespace {

// Factorizes and solves K x = b with an analysed PETSc backend; the relative residual, computed
// independently of PETSc.
double petsc_lattice_residual(PetscSolver& solver, const SparseMatrix& k,
                              const Eigen::VectorXd& b) {
  std::string message;
  EXPECT_EQ(solver.factorize(k, &message), LinearStatus::Ok) << message;
  Eigen::VectorXd x;
  EXPECT_EQ(solver.solve(b, x, &message), LinearStatus::Ok) << message;
  return relative_residual(k, x, b);
}

TEST(PetscSolver, RelativeToleranceIsTheKspTolerance) {
  const SparseMatrix k = laplacian_3d(16);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(k.n, -1.0, 2.0);
  PetscSolver solver(true, true);
  std::string message;
  ASSERT_EQ(solver.analyze(k, &message), LinearStatus::Ok) << message;
  solver.set_relative_tolerance(1e-3);
  const double loose = petsc_lattice_residual(solver, k, b);
  const int loose_iterations = solver.iterations();
  solver.set_relative_tolerance(1e-10);
  const double tight = petsc_lattice_residual(solver, k, b);
  // CG stops at the first iterate within the tolerance (10 % margin as in the parity suite); one
  // AMG-CG iteration reduces the residual by about ten, so the loose solve stops far above the
  // tight one's residual and in fewer iterations.
  EXPECT_LE(loose, 1.1e-3);
  EXPECT_LE(tight, 1.1e-10);
  EXPECT_GT(loose, 1e3 * tight);
  EXPECT_LT(loose_iterations, solver.iterations());
  RecordProperty("iterations_rtol_1e-3", loose_iterations);
  RecordProperty("iterations_rtol_1e-10", solver.iterations());
}

TEST(PetscSolver, LargeLatticeTakesFewAmgCgIterations) {
  const SparseMatrix k = laplacian_3d(30);  // 27000 unknowns
  Eigen::VectorXd expected(k.n);
  for (int i = 0; i < k.n; ++i) expected(i) = std::sin(0.37 * i) + 0.1 * (i % 7);
  const Eigen::VectorXd b = to_eigen(k) * expected;
  PetscSolver solver(true, true);
  std::string message;
  ASSERT_EQ(solver.analyze(k, &message), LinearStatus::Ok) << message;
  EXPECT_LE(petsc_lattice_residual(solver, k, b), 1.1e-10);
  EXPECT_STREQ(solver.method(), "cg+boomeramg");
  // Multigrid makes the iteration count independent of the lattice size; BoomerAMG reaches 1e-10
  // on the 7-point Laplacian in about ten iterations. 25 would be a badly configured AMG.
  EXPECT_LE(solver.iterations(), 25);
  RecordProperty("iterations", solver.iterations());
}

TEST(PetscSolver, AmgHierarchyIsReusedAcrossCloseTangents) {
  const SparseMatrix k = laplacian_3d(12);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(k.n, -1.0, 2.0);
  PetscSolver solver(true, true);
  std::string message;
  ASSERT_EQ(solver.analyze(k, &message), LinearStatus::Ok) << message;
  EXPECT_LE(petsc_lattice_residual(solver, k, b), 1.1e-10);
  const int first = solver.iterations();
  // A tangent 2 % stiffer on the diagonal, as from one Newton iteration to the next: the old
  // hierarchy still preconditions it well, so it is kept.
  SparseMatrix stiffer = k;
  for (int j = 0; j < k.n; ++j) {
    for (int p = k.col_ptr[j]; p < k.col_ptr[j + 1]; ++p) {
      if (k.row_idx[p] == j) stiffer.values[p] *= 1.02;
    }
  }
  EXPECT_LE(petsc_lattice_residual(solver, stiffer, b), 1.1e-10);
  EXPECT_EQ(solver.preconditioner_setups(), 1);
  EXPECT_LE(solver.iterations(), 2 * first + 5);
}

TEST(PetscSolver, NodeBlocksReachBoomerAmgAsNodalCoarsening) {
  // 12³ nodes, 5 184 equations, three per node. With node_block 3 PETSc must hand BoomerAMG the
  // block size and nodal coarsening (as its own KSPView reports them); as a scalar system
  // neither. Both must solve to the tolerance: nodal AMG is an SPD preconditioner for CG.
  SparseMatrix k = truss_lattice_3d(12);
  Eigen::VectorXd b(k.n);
  for (int i = 0; i < k.n; ++i) b(i) = std::cos(0.11 * i);
  for (const int block : {3, 1}) {
    k.node_block = block;
    PetscSolver solver(true, true);
    std::string message;
    ASSERT_EQ(solver.analyze(k, &message), LinearStatus::Ok) << message;
    EXPECT_LE(petsc_lattice_residual(solver, k, b), 1.1e-10) << "node block " << block;
    const std::string view = solver.view();
    const bool nodal = view.find("nodal coarsening") != std::string::npos;
    const bool blocks = view.find("bs=3") != std::string::npos;
    EXPECT_EQ(nodal, block == 3) << view;
    EXPECT_EQ(blocks, block == 3) << view;
    RecordProperty(block == 3 ? "nodal_iterations" : "scalar_iterations", solver.iterations());
  }
}

// A line coupled to no other (the row Δu = target − u of a prescribed DOF, its column moved to the
// right-hand side) comes out exact from a loose iterative solve: Newton compares a prescribed DOF
// with its target exactly, and a solve that left it within 1e-2 would never let it arrive.
TEST(PetscSolver, DecoupledLineIsSolvedExactlyByALooseSolve) {
  SparseMatrix k = laplacian_3d(12);
  const int line = 700;
  for (int j = 0; j < k.n; ++j) {
    for (int p = k.col_ptr[j]; p < k.col_ptr[j + 1]; ++p) {
      const int i = k.row_idx[p];
      if ((i == line || j == line) && i != j) k.values[p] = 0.0;
      if (i == line && j == line) k.values[p] = 1.0;
    }
  }
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(k.n, -1.0, 2.0);
  b[line] = 0.1234567890123;
  PetscSolver solver(true, true);
  std::string message;
  ASSERT_EQ(solver.analyze(k, &message), LinearStatus::Ok) << message;
  solver.set_relative_tolerance(1e-2);
  ASSERT_EQ(solver.factorize(k, &message), LinearStatus::Ok) << message;
  Eigen::VectorXd x;
  ASSERT_EQ(solver.solve(b, x, &message), LinearStatus::Ok) << message;
  EXPECT_EQ(x[line], b[line]);
  // The other lines within the tolerance (10 % margin as in the parity suite).
  EXPECT_LE(relative_residual(k, x, b), 1.1e-2);
}

TEST(PetscSolver, MumpsReportsASingularSystemAndRecovers) {
  // An unsymmetric system (MUMPS) with a floating pair of dofs, then the same pattern with the
  // pair grounded: a failed factorization does not poison the next one.
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(6, 6);
  a.topLeftCorner(4, 4) = grounded_chain();
  a(1, 3) += 0.8;
  a.bottomRightCorner(2, 2) << 3.0, -3.0, -3.0, 3.0;
  const SparseMatrix singular = from_dense(a, Storage::Full);
  PetscSolver solver(false, false);
  std::string message;
  ASSERT_EQ(solver.analyze(singular, &message), LinearStatus::Ok) << message;
  EXPECT_EQ(solver.factorize(singular, &message), LinearStatus::Singular) << message;
  EXPECT_NE(message.find("singular system"), std::string::npos) << message;
  SparseMatrix grounded = singular;
  grounded.values[grounded.col_ptr[5] - 2] += 1.0;  // entry (4, 4): dof 4 on a support
  ASSERT_EQ(solver.factorize(grounded, &message), LinearStatus::Ok) << message;
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(6, 1.0, 2.0);
  Eigen::VectorXd x;
  ASSERT_EQ(solver.solve(b, x, &message), LinearStatus::Ok) << message;
  EXPECT_LT(relative_residual(grounded, x, b), 1e-12);  // LU: round-off, cond ≈ 1e2
}

}  // namespace
}  // namespace clinch
