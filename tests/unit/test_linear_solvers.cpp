// Backend parity of the linear solvers (ARCHITECTURE.md, testing habit 7): CHOLMOD, UMFPACK,
// the dense reference and PETSc run on the same systems, stored as upper triangles and as full
// matrices: SPD, 3-D lattice, symmetric indefinite KKT (connection-types.md §3.8), unsymmetric,
// singular (connection-types.md §1.1: the failed pivot is named), and refactorization on one
// pattern. PETSc solves SPD systems with CG + AMG, to its KSP tolerance rather than to round-off,
// and the others with MUMPS.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <cmath>
#include <limits>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "src/linalg/automatic_solver.hpp"
#include "src/linalg/fill_estimate.hpp"
#include "src/linalg/cholmod_solver.hpp"
#include "src/linalg/linear_solver.hpp"
#include "src/linalg/pivot_checks.hpp"
#include "tests/support/model_problems.hpp"
#include "tests/unit/linear_systems.hpp"

namespace clinch {

void PrintTo(LinearStatus status, std::ostream* os) { *os << to_string(status); }

namespace {

// The relative tolerance of PETSc's CG when none is set (petsc_solver.hpp).
constexpr double kKspRtol = 1e-10;

struct Case {
  SolverChoice choice;
  Storage storage;
};

std::string case_name(const Case& c) {
  const char* backend = c.choice == SolverChoice::Cholmod   ? "Cholmod"
                        : c.choice == SolverChoice::Umfpack ? "Umfpack"
                        : c.choice == SolverChoice::Petsc   ? "Petsc"
                                                            : "Dense";
  return std::string(backend) + (c.storage == Storage::Upper ? "Upper" : "Full");
}

void PrintTo(const Case& c, std::ostream* os) { *os << case_name(c); }

class LinearSolverParity : public ::testing::TestWithParam<Case> {
 protected:
  SolverChoice choice() const { return GetParam().choice; }
  Storage storage() const { return GetParam().storage; }
  bool is(SolverChoice c) const { return choice() == c; }
  // Whether a system announced SPD is solved iteratively (PETSc: CG + BoomerAMG).
  bool iterative() const { return is(SolverChoice::Petsc); }
  // Relative residual an SPD solve is held to: a backward-stable factorization leaves a few
  // machine epsilons (1e-12 keeps a margin of ~1e3); CG stops at ‖b − Ax‖ ≤ rtol ‖b‖ measured on
  // its recursively updated residual, which drifts from the true one by round-off: 10 % margin.
  double spd_residual_tolerance() const { return iterative() ? 1.1 * kKspRtol : 1e-12; }

  // Analyze and factorize `m` with a backend built for (symmetric, positive definite).
  LinearStatus factor(const SparseMatrix& m, bool symmetric, bool positive_definite) {
    solver_ = make_linear_solver(choice(), symmetric, positive_definite);
    message_.clear();
    EXPECT_EQ(solver_->analyze(m, &message_), LinearStatus::Ok) << message_;
    return solver_->factorize(m, &message_);
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) {
    Eigen::VectorXd x;
    EXPECT_EQ(solver_->solve(b, x, &message_), LinearStatus::Ok) << message_;
    return x;
  }

  // CG factors nothing, so a singular SPD matrix whose lines are not zero passes factorize. The
  // right-hand side of ones has a component along the null vector of both singular systems
  // below (the floating pair, the rigid translation), which CG cannot reduce: CG fails, MUMPS
  // takes over and reports the system singular, without naming the equation.
  void expect_singular_at_solve(const SparseMatrix& m) {
    ASSERT_EQ(factor(m, true, true), LinearStatus::Ok) << message_;
    Eigen::VectorXd x;
    EXPECT_EQ(solver_->solve(Eigen::VectorXd::Ones(m.n), x, &message_), LinearStatus::Singular)
        << message_;
    EXPECT_NE(message_.find("singular system"), std::string::npos) << message_;
    EXPECT_EQ(solver_->failed_pivot(), -1);
  }

  std::unique_ptr<LinearSolver> solver_;
  std::string message_;
};

TEST_P(LinearSolverParity, SmallSpdSystemHasItsKnownSolution) {
  Eigen::MatrixXd a(5, 5);
  a << 4.0, -1.0, 0.0, 0.5, 0.0,   //
      -1.0, 5.0, -2.0, 0.0, 0.0,   //
      0.0, -2.0, 6.0, -1.5, 0.25,  //
      0.5, 0.0, -1.5, 3.0, 0.0,    //
      0.0, 0.0, 0.25, 0.0, 2.0;
  Eigen::VectorXd expected(5);
  expected << 1.0, -2.0, 3.0, -4.0, 5.0;
  const Eigen::VectorXd b = a * expected;
  const SparseMatrix m = from_dense(a, storage());
  ASSERT_EQ(factor(m, true, true), LinearStatus::Ok) << message_;
  const Eigen::VectorXd x = solve(b);
  // A backward-stable factorization leaves a residual of a few machine epsilons; the condition
  // number is below 10, so the error of x is of the same order. 1e-12 leaves a margin of ~1e3.
  // For CG the relative error is at most cond · 1.1e-10 ≈ 1.1e-9 of ‖x‖₂ ≈ 7.4: below 1e-8.
  EXPECT_LT(relative_residual(m, x, b), spd_residual_tolerance());
  EXPECT_LT((x - expected).lpNorm<Eigen::Infinity>(), iterative() ? 1e-8 : 1e-12);
  EXPECT_EQ(solver_->failed_pivot(), -1);
}

TEST_P(LinearSolverParity, LaplacianOfA3dLatticeIsSolved) {
  const SparseMatrix upper = laplacian_3d(13);  // 2197 unknowns
  const SparseMatrix m = from_eigen(to_eigen(upper), storage());
  Eigen::VectorXd expected(m.n);
  for (int i = 0; i < m.n; ++i) expected(i) = std::sin(0.37 * i) + 0.1 * (i % 7);
  const Eigen::VectorXd b = to_eigen(m) * expected;
  ASSERT_EQ(factor(m, true, true), LinearStatus::Ok) << message_;
  const Eigen::VectorXd x = solve(b);
  // Residual as above; the condition number of the lattice Laplacian is ≈ 4 (N + 1)² / π² ≈ 80,
  // so the relative error is ~1e-14, far below 1e-11; for CG at most 80 · 1.1e-10 < 1e-8.
  EXPECT_LT(relative_residual(m, x, b), spd_residual_tolerance());
  EXPECT_LT((x - expected).norm() / expected.norm(), iterative() ? 1e-8 : 1e-11);
}

// [K Cᵀ; C 0] with the grounded chain and two constraints, u0 − u2 = g1 and u3 = g2: symmetric,
// nonsingular, with a zero diagonal block (connection-types.md §3.8).
Eigen::MatrixXd kkt_system() {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(6, 6);
  a.topLeftCorner(4, 4) = grounded_chain();
  a(4, 0) = a(0, 4) = 1.0;
  a(4, 2) = a(2, 4) = -1.0;
  a(5, 3) = a(3, 5) = 1.0;
  return a;
}

TEST_P(LinearSolverParity, SymmetricIndefiniteKktSystem) {
  const Eigen::MatrixXd a = kkt_system();
  Eigen::VectorXd expected(6);
  expected << 0.1, -0.2, 0.3, 0.05, 12.0, -7.5;
  const Eigen::VectorXd b = a * expected;
  const SparseMatrix m = from_dense(a, storage());
  const LinearStatus status = factor(m, true, false);
  if (is(SolverChoice::Cholmod)) {
    // Whatever the ordering, the first multiplier to be eliminated meets a pivot −C K⁻¹ Cᵀ ≤ 0
    // (or its zero diagonal), before any dof of K can fail: the failed pivot is 4 or 5.
    EXPECT_EQ(status, LinearStatus::NotPositiveDefinite) << message_;
    EXPECT_TRUE(solver_->failed_pivot() == 4 || solver_->failed_pivot() == 5)
        << solver_->failed_pivot();
    EXPECT_NE(message_.find("not positive definite"), std::string::npos) << message_;
    return;
  }
  ASSERT_EQ(status, LinearStatus::Ok) << message_;
  const Eigen::VectorXd x = solve(b);
  // Condition number ≈ 18: the error of x is ~1e-15, 1e-11 keeps a wide margin.
  EXPECT_LT(relative_residual(m, x, b), 1e-12);
  EXPECT_LT((x - expected).lpNorm<Eigen::Infinity>(), 1e-11);
}

TEST_P(LinearSolverParity, UnsymmetricSystem) {
  if (is(SolverChoice::Cholmod)) GTEST_SKIP() << "CHOLMOD takes symmetric matrices only";
  if (storage() == Storage::Upper) GTEST_SKIP() << "an unsymmetric matrix has no upper storage";
  // The grounded chain with an unsymmetric friction-like coupling of dofs 1 and 3 (behaviors.md
  // §7.4: unsymmetric tangents go to LU).
  Eigen::MatrixXd a = grounded_chain();
  a(1, 3) += 0.8;
  a(3, 0) -= 0.6;
  Eigen::VectorXd expected(4);
  expected << 0.25, -1.5, 2.0, 0.75;
  const Eigen::VectorXd b = a * expected;
  const SparseMatrix m = from_dense(a, storage());
  ASSERT_EQ(factor(m, false, false), LinearStatus::Ok) << message_;
  const Eigen::VectorXd x = solve(b);
  EXPECT_LT(relative_residual(m, x, b), 1e-12);  // as for the SPD system: cond ≈ 22
  EXPECT_LT((x - expected).lpNorm<Eigen::Infinity>(), 1e-12);
}

TEST_P(LinearSolverParity, UnrestrainedDofIsNamed) {
  // Dof 2 of a 5-dof system has a diagonal in the pattern but no stiffness at all (an activated,
  // unrestrained rotation, connection-types.md §1.1): an exact zero pivot, whatever the order.
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(5, 5);
  a.topLeftCorner(4, 4) = grounded_chain();
  a.row(2).setZero();
  a.col(2).setZero();
  a(4, 4) = 3.0;
  a(4, 1) = a(1, 4) = -0.5;
  const SparseMatrix m = from_dense(a, storage());
  EXPECT_EQ(factor(m, true, true), LinearStatus::Singular) << message_;
  EXPECT_EQ(solver_->failed_pivot(), 2);
  EXPECT_NE(message_.find("singular system: zero pivot at equation 2"), std::string::npos)
      << message_;
}

TEST_P(LinearSolverParity, FloatingSpringIsSingularNotIndefinite) {
  // The grounded chain and a separate spring between dofs 4 and 5 with no support: whichever of
  // the two is eliminated second meets the pivot k − k·k/k = 0 exactly, on a positive diagonal
  // and a nonzero line. Cholesky stops there: the value of that pivot, recovered from the
  // columns left of it, makes the difference between singular and indefinite.
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(6, 6);
  a.topLeftCorner(4, 4) = grounded_chain();
  a.bottomRightCorner(2, 2) << 3.0, -3.0, -3.0, 3.0;
  const SparseMatrix m = from_dense(a, storage());
  if (iterative()) {
    expect_singular_at_solve(m);
    return;
  }
  EXPECT_EQ(factor(m, true, true), LinearStatus::Singular) << message_;
  EXPECT_TRUE(solver_->failed_pivot() == 4 || solver_->failed_pivot() == 5)
      << solver_->failed_pivot();
}

TEST_P(LinearSolverParity, RigidBodyModeIsSingular) {
  // A free-floating lattice of springs (every node pulled only by its neighbours, stiffness
  // varying from spring to spring) has the rigid translation in its null space. Rounding leaves
  // the last pivot at a few machine epsilons instead of zero, which the pivot test must catch.
  const int side = 8;
  const SparseMatrix lattice = laplacian_3d(side);
  std::vector<Eigen::Triplet<double>> entries;
  for (int j = 0; j < lattice.n; ++j) {
    for (int p = lattice.col_ptr[j]; p < lattice.col_ptr[j + 1]; ++p) {
      const int i = lattice.row_idx[p];
      if (i == j) continue;
      const double k = 1.0 + 0.37 * ((i * 7 + j * 3) % 11);
      entries.emplace_back(i, j, -k);
      entries.emplace_back(j, i, -k);
      entries.emplace_back(i, i, k);
      entries.emplace_back(j, j, k);
    }
  }
  EigenSparse a(lattice.n, lattice.n);
  a.setFromTriplets(entries.begin(), entries.end());
  const SparseMatrix m = from_eigen(a, storage());
  if (iterative()) {
    expect_singular_at_solve(m);
    return;
  }
  EXPECT_EQ(factor(m, true, true), LinearStatus::Singular) << message_;
  if (!is(SolverChoice::Umfpack)) {
    EXPECT_GE(solver_->failed_pivot(), 0);
    EXPECT_LT(solver_->failed_pivot(), m.n);
  }
}

TEST_P(LinearSolverParity, NegativePivotIsNotPositiveDefiniteForCholesky) {
  // A softening dof (behaviors.md §7.4: negative tangent) decoupled from the rest: Cholesky
  // backends stop on it; LU solves the indefinite system.
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(5, 5);
  a.topLeftCorner(4, 4) = grounded_chain();
  a.row(1).setZero();
  a.col(1).setZero();
  a(1, 1) = -450.0;
  a(4, 4) = 2.0;
  Eigen::VectorXd expected(5);
  expected << 1.0, 0.5, -1.0, 2.0, -0.25;
  const Eigen::VectorXd b = a * expected;
  const SparseMatrix m = from_dense(a, storage());
  const LinearStatus status = factor(m, true, true);
  // PETSc: the negative diagonal proves the matrix indefinite, and MUMPS LU takes over from CG.
  if (is(SolverChoice::Umfpack) || is(SolverChoice::Petsc)) {
    ASSERT_EQ(status, LinearStatus::Ok) << message_;
    EXPECT_LT((solve(b) - expected).lpNorm<Eigen::Infinity>(),
              1e-12);  // the chain block: cond ≈ 39
    return;
  }
  EXPECT_EQ(status, LinearStatus::NotPositiveDefinite) << message_;
  EXPECT_EQ(solver_->failed_pivot(), 1);
}

TEST_P(LinearSolverParity, RefactorizationReusesTheAnalysis) {
  const SparseMatrix pattern = from_eigen(to_eigen(laplacian_3d(6)), storage());
  solver_ = make_linear_solver(choice(), true, true);
  ASSERT_EQ(solver_->analyze(pattern, &message_), LinearStatus::Ok) << message_;
  SparseMatrix m = pattern;
  const auto check_solve = [&](const SparseMatrix& k) {
    ASSERT_EQ(solver_->factorize(k, &message_), LinearStatus::Ok) << message_;
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(k.n, -1.0, 2.0);
    Eigen::VectorXd x;
    ASSERT_EQ(solver_->solve(b, x, &message_), LinearStatus::Ok) << message_;
    EXPECT_LT(relative_residual(k, x, b), spd_residual_tolerance());  // cond ≈ 20
  };
  check_solve(m);
  // New values on the same pattern, still diagonally dominant: 8 + 0.3 (j mod 5) against at
  // most six neighbours of −1.3.
  for (int j = 0; j < m.n; ++j) {
    for (int p = m.col_ptr[j]; p < m.col_ptr[j + 1]; ++p) {
      m.values[p] = m.row_idx[p] == j ? 8.0 + 0.3 * (j % 5) : -1.3;
    }
  }
  check_solve(m);
  // A failed factorization, then recovery without a new analysis.
  SparseMatrix singular = m;
  const int dof = 7;
  for (int j = 0; j < m.n; ++j) {
    for (int p = m.col_ptr[j]; p < m.col_ptr[j + 1]; ++p) {
      if (j == dof || m.row_idx[p] == dof) singular.values[p] = 0.0;
    }
  }
  EXPECT_EQ(solver_->factorize(singular, &message_), LinearStatus::Singular);
  EXPECT_EQ(solver_->failed_pivot(), dof);
  check_solve(m);
  EXPECT_EQ(solver_->failed_pivot(), -1);
  // The same values again (a backend may keep its factor), then one diagonal entry changed: the
  // solve must be that of the new matrix, not of a factor kept from the old one.
  check_solve(m);
  for (int p = m.col_ptr[3]; p < m.col_ptr[4]; ++p) {
    if (m.row_idx[p] == 3) m.values[p] += 4.0;
  }
  check_solve(m);
}

TEST_P(LinearSolverParity, NonFiniteEntryIsAFailure) {
  SparseMatrix m = from_dense(grounded_chain(), storage());
  m.values[2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(factor(m, true, true), LinearStatus::Failure);
  EXPECT_NE(message_.find("non-finite entry"), std::string::npos) << message_;
}

TEST_P(LinearSolverParity, SolveWithoutFactorizationIsABug) {
  solver_ = make_linear_solver(choice(), true, true);
  Eigen::VectorXd x;
  EXPECT_THROW(solver_->solve(Eigen::VectorXd::Ones(3), x, nullptr), std::logic_error);
}

INSTANTIATE_TEST_SUITE_P(Backends, LinearSolverParity,
                         ::testing::Values(Case{SolverChoice::Cholmod, Storage::Upper},
                                           Case{SolverChoice::Cholmod, Storage::Full},
                                           Case{SolverChoice::Umfpack, Storage::Upper},
                                           Case{SolverChoice::Umfpack, Storage::Full},
                                           Case{SolverChoice::Dense, Storage::Upper},
                                           Case{SolverChoice::Dense, Storage::Full},
                                           Case{SolverChoice::Petsc, Storage::Upper},
                                           Case{SolverChoice::Petsc, Storage::Full}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return case_name(info.param);
                         });

// A system announced as SPD that turns out indefinite ([[1, 2], [2, 1]], eigenvalues 3 and −1)
// is still solved: the automatic solver switches to LU. x = (1, 1) for b = (3, 3), exact in
// binary arithmetic up to the LU's rounding (1e-14).
TEST(LinearSolverChoice, AutomaticFallsBackToLuOnAnIndefiniteMatrix) {
  SparseMatrix k;
  k.n = 2;
  k.symmetric_upper = true;
  k.col_ptr = {0, 1, 3};
  k.row_idx = {0, 0, 1};
  k.values = {1.0, 2.0, 1.0};
  auto solver = make_linear_solver(SolverChoice::Automatic, true, true);
  std::string message;
  ASSERT_EQ(solver->analyze(k, &message), LinearStatus::Ok) << message;
  ASSERT_EQ(solver->factorize(k, &message), LinearStatus::Ok) << message;
  EXPECT_STREQ(solver->name(), "umfpack");
  Eigen::VectorXd x;
  ASSERT_EQ(solver->solve(Eigen::Vector2d(3.0, 3.0), x, &message), LinearStatus::Ok) << message;
  EXPECT_NEAR(x[0], 1.0, 1e-14);
  EXPECT_NEAR(x[1], 1.0, 1e-14);
}

// A chain of unit springs, every node also on a spring of stiffness 1 to ground: 3 on the
// diagonal, −1 beside it (well conditioned), upper storage.
SparseMatrix grounded_spring_chain(int n) {
  SparseMatrix chain;
  chain.n = n;
  chain.symmetric_upper = true;
  chain.col_ptr.push_back(0);
  for (int j = 0; j < chain.n; ++j) {
    if (j > 0) {
      chain.row_idx.push_back(j - 1);
      chain.values.push_back(-1.0);
    }
    chain.row_idx.push_back(j);
    chain.values.push_back(3.0);
    chain.col_ptr.push_back(static_cast<int>(chain.row_idx.size()));
  }
  return chain;
}

// The fill estimate (one AMD ordering of the node graph) bounds what CHOLMOD's analysis finds
// from above, within a small factor on a 3-D lattice (AMD against METIS), and is exact on a chain
// whose AMD ordering has no fill.
TEST(LinearSolverChoice, FillEstimateBoundsCholmodsPrediction) {
  const SparseMatrix lattice = truss_lattice_3d(16);
  CholmodSolver cholmod;
  std::string message;
  ASSERT_EQ(cholmod.analyze(lattice, &message), LinearStatus::Ok) << message;
  const double estimate = estimated_cholesky_flops(lattice);
  EXPECT_GE(estimate, cholmod.predicted_flops());
  EXPECT_LE(estimate, 10.0 * cholmod.predicted_flops());
  RecordProperty("estimate_over_cholmod", std::to_string(estimate / cholmod.predicted_flops()));
  const SparseMatrix chain = grounded_spring_chain(1000);
  ASSERT_EQ(cholmod.analyze(chain, &message), LinearStatus::Ok) << message;
  EXPECT_DOUBLE_EQ(estimated_cholesky_flops(chain), cholmod.predicted_flops());
}

// The automatic choice hands a pattern whose factorization is costly even once to the PETSc
// backend at analysis (the truss lattice with 22³ nodes, 31 944 equations: estimated above
// kAtOnceFlops) and keeps CHOLMOD for a chain of the same order (a few flops per entry). Both are
// then solved to the tolerance of their backend.
TEST(LinearSolverChoice, AutomaticHandsCostlyFactorizationsToPetscAtOnce) {
  const SparseMatrix lattice = truss_lattice_3d(22);
  ASSERT_GE(estimated_cholesky_flops(lattice), 1.5 * kAtOnceFlops);
  const SparseMatrix chain = grounded_spring_chain(lattice.n);
  ASSERT_LE(estimated_cholesky_flops(chain), 100.0 * chain.nonzeros());

  std::string message;
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(lattice.n, -1.0, 2.0);
  for (const auto& [matrix, expected] : {std::pair{&lattice, "petsc"}, {&chain, "cholmod"}}) {
    auto solver = make_linear_solver(SolverChoice::Automatic, true, true);
    ASSERT_EQ(solver->analyze(*matrix, &message), LinearStatus::Ok) << message;
    EXPECT_STREQ(solver->name(), expected);
    // The step's log line says why the automatic choice left CHOLMOD, or kept it.
    const bool left = std::string(expected) == "petsc";
    EXPECT_NE(solver->choice().find(left ? "flops per factorization, so CG with BoomerAMG"
                                         : "flops per factorization, below the hand-over"),
              std::string::npos)
        << solver->choice();
    ASSERT_EQ(solver->factorize(*matrix, &message), LinearStatus::Ok) << message;
    Eigen::VectorXd x;
    ASSERT_EQ(solver->solve(b, x, &message), LinearStatus::Ok) << message;
    EXPECT_LE(relative_residual(*matrix, x, b), 1.1e-10) << expected;
  }
}

// A pattern whose factorization is affordable once but costs more than AMG-preconditioned solves
// (the truss lattice with 14³ nodes: CHOLMOD predicts between kOnChangeFlops and kAtOnceFlops,
// above kOnChangeFlopsPerEntry) stays with CHOLMOD while the matrix is the same (a linear step)
// and goes to the PETSc backend once it changes (a Newton iteration of a nonlinear step). Every
// solve is checked against its own matrix.
TEST(LinearSolverChoice, AutomaticHandsOverOnceTheTangentChanges) {
  const SparseMatrix lattice = truss_lattice_3d(14);
  CholmodSolver cholmod;
  std::string message;
  ASSERT_EQ(cholmod.analyze(lattice, &message), LinearStatus::Ok) << message;
  ASSERT_GE(cholmod.predicted_flops(), kOnChangeFlops);
  ASSERT_GE(cholmod.predicted_flops(), kOnChangeFlopsPerEntry * lattice.nonzeros());
  ASSERT_LT(estimated_cholesky_flops(lattice), kAtOnceFlops);

  auto solver = make_linear_solver(SolverChoice::Automatic, true, true);
  ASSERT_EQ(solver->analyze(lattice, &message), LinearStatus::Ok) << message;
  EXPECT_NE(solver->choice().find("takes over once the tangent changes"), std::string::npos)
      << solver->choice();
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(lattice.n, -1.0, 2.0);
  SparseMatrix changed = lattice;
  for (double& value : changed.values) value *= 1.5;
  for (const auto& [matrix, expected] :
       {std::pair{&lattice, "cholmod"}, {&lattice, "cholmod"}, {&changed, "petsc"}}) {
    ASSERT_EQ(solver->factorize(*matrix, &message), LinearStatus::Ok) << message;
    EXPECT_STREQ(solver->name(), expected);
    Eigen::VectorXd x;
    ASSERT_EQ(solver->solve(b, x, &message), LinearStatus::Ok) << message;
    EXPECT_LE(relative_residual(*matrix, x, b), 1.1e-10) << expected;
  }
  EXPECT_NE(solver->choice().find("the tangent changed"), std::string::npos) << solver->choice();
}

// An unsymmetric system without multipliers (friction, damage) that is costly to factorize goes
// to GMRES with BoomerAMG: the lattice of 22³ nodes in full storage with every entry above the
// diagonal scaled by 1.01, which keeps it positive definite in its symmetric part.
TEST(LinearSolverChoice, AutomaticHandsCostlyUnsymmetricSystemsToGmres) {
  const SparseMatrix upper = truss_lattice_3d(22);
  SparseMatrix full = from_eigen(to_eigen(upper), Storage::Full);
  full.node_block = upper.node_block;
  for (int j = 0; j < full.n; ++j) {
    for (int p = full.col_ptr[j]; p < full.col_ptr[j + 1]; ++p) {
      if (full.row_idx[p] < j) full.values[p] *= 1.01;
    }
  }
  auto solver = make_linear_solver(SolverChoice::Automatic, false, true);
  std::string message;
  ASSERT_EQ(solver->analyze(full, &message), LinearStatus::Ok) << message;
  EXPECT_STREQ(solver->name(), "petsc");
  EXPECT_NE(solver->choice().find("so GMRES with BoomerAMG"), std::string::npos)
      << solver->choice();
  ASSERT_EQ(solver->factorize(full, &message), LinearStatus::Ok) << message;
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(full.n, -1.0, 2.0);
  Eigen::VectorXd x;
  ASSERT_EQ(solver->solve(b, x, &message), LinearStatus::Ok) << message;
  EXPECT_LE(relative_residual(full, x, b), 1.1e-10);
  // Under multipliers (not positive definite) UMFPACK keeps the system.
  EXPECT_STREQ(make_linear_solver(SolverChoice::Automatic, false, false)->name(), "umfpack");
}

TEST(LinearSolverChoice, AutomaticTakesCholeskyOnlyForSpdSystems) {
  EXPECT_STREQ(make_linear_solver(SolverChoice::Automatic, true, true)->name(), "cholmod");
  EXPECT_STREQ(make_linear_solver(SolverChoice::Automatic, true, false)->name(), "umfpack");
  EXPECT_STREQ(make_linear_solver(SolverChoice::Automatic, false, false)->name(), "umfpack");
  EXPECT_STREQ(make_linear_solver(SolverChoice::Dense, false, false)->name(), "dense");
  EXPECT_STREQ(make_linear_solver(SolverChoice::Petsc, true, true)->name(), "petsc");
  EXPECT_THROW(make_linear_solver(SolverChoice::Cholmod, false, false), std::invalid_argument);
}

TEST(LinearSolverChoice, MalformedPatternIsABug) {
  SparseMatrix lower_entry = from_dense(grounded_chain(), Storage::Full);
  lower_entry.symmetric_upper = true;  // rows below the diagonal in upper storage
  SparseMatrix unsorted = from_dense(grounded_chain(), Storage::Full);
  std::swap(unsorted.row_idx[0], unsorted.row_idx[1]);
  for (SolverChoice choice :
       {SolverChoice::Cholmod, SolverChoice::Umfpack, SolverChoice::Dense, SolverChoice::Petsc}) {
    const auto solver = make_linear_solver(choice, true, true);
    EXPECT_THROW(solver->analyze(lower_entry, nullptr), std::invalid_argument);
    EXPECT_THROW(solver->analyze(unsorted, nullptr), std::invalid_argument);
  }
}

TEST(CholmodOrdering, KeepsTheBetterOfAmdAndMetisOnA3dLattice) {
  CholmodSolver solver;
  std::string message;
  ASSERT_EQ(solver.analyze(laplacian_3d(20), &message), LinearStatus::Ok) << message;
  const auto trials = solver.ordering_trials();
  ASSERT_EQ(trials.size(), 2u);
  EXPECT_STREQ(trials[0].ordering, "AMD");
  EXPECT_STREQ(trials[1].ordering, "METIS");
  // METIS ran (CHOLMOD built with it): both orderings produced a factor estimate.
  EXPECT_GT(trials[0].factor_nonzeros, 0.0);
  EXPECT_GT(trials[1].factor_nonzeros, 0.0);
  const auto& kept = trials[0].factor_nonzeros <= trials[1].factor_nonzeros ? trials[0] : trials[1];
  EXPECT_STREQ(solver.ordering(), kept.ordering);
  for (const auto& trial : trials) {
    RecordProperty(std::string("nnz_L_") + trial.ordering, std::to_string(trial.factor_nonzeros));
  }
  RecordProperty("kept", solver.ordering());
}

TEST(PivotChecks, ClassifiesFailedCholeskyPivots) {
  EXPECT_EQ(classify_cholesky_failure(-1e-16, 1.0, false), LinearStatus::Singular);
  EXPECT_EQ(classify_cholesky_failure(-1e-3, 1.0, false), LinearStatus::NotPositiveDefinite);
  // Zero diagonal with a coupling (a multiplier): indefinite, not singular.
  EXPECT_EQ(classify_cholesky_failure(0.0, 0.0, false), LinearStatus::NotPositiveDefinite);
  EXPECT_EQ(classify_cholesky_failure(0.0, 0.0, true), LinearStatus::Singular);
  EXPECT_TRUE(negligible_pivot(1e-14, 1.0));
  EXPECT_FALSE(negligible_pivot(1e-12, 1.0));
}

}  // namespace
}  // namespace clinch
