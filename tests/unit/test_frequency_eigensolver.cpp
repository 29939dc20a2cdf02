// The *FREQUENCY eigensolver (src/solver/frequency_eigensolver.hpp) on a system with a Lagrange
// multiplier and a massless DOF, the indefinite K − σM that connector constraints give, against
// the dense generalized eigensolve of the same system with the constraint eliminated by hand.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "src/solver/frequency_eigensolver.hpp"
#include "tests/unit/linear_systems.hpp"

namespace clinch {
namespace {

// u1 (mass 2) on a spring of 100 to the ground and one of 50 to u2 (no mass); u3 (mass 3) on a
// spring of 30 to the ground, tied to u2 by the multiplier λ of u3 − u2 = 0.
struct TiedSprings {
  Eigen::MatrixXd k{{150, -50, 0, 0}, {-50, 50, 0, -1}, {0, 0, 30, 1}, {0, -1, 1, 0}};
  LumpedMass mass{{{0, 0, 2.0}, {2, 2, 3.0}}, {{{0, std::sqrt(2.0)}}, {{2, std::sqrt(3.0)}}}};
};

TEST(FrequencyEigensolver, MultiplierAndMasslessDofGiveTheEliminatedSystemsEigenpairs) {
  const TiedSprings system;
  const SparseMatrix k = from_dense(system.k, Storage::Upper);
  std::unique_ptr<LinearSolver> solver = make_linear_solver(SolverChoice::Dense, true, false);
  std::string message;
  ASSERT_EQ(solver->analyze(k, &message), LinearStatus::Ok) << message;
  EigenRequest request;
  request.shift = request.lower = -1e-3;
  request.count = 2;
  const EigenResult result = solve_frequency_eigenproblem(k, system.mass, request, *solver);
  ASSERT_TRUE(result.error.empty()) << result.error;
  ASSERT_EQ(result.pairs.size(), 2u);
  EXPECT_EQ(result.available, 2);

  // With u2 = u3 eliminated: K = [[150, −50], [−50, 80]], M = diag(2, 3).
  const Eigen::Matrix2d reduced_k{{150, -50}, {-50, 80}};
  const Eigen::Matrix2d reduced_m{{2, 0}, {0, 3}};
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> reference(reduced_k,
                                                                            reduced_m);
  for (int i = 0; i < 2; ++i) {
    const EigenPair& pair = result.pairs[static_cast<std::size_t>(i)];
    // Both eigensolves are direct on a 2 × 2 problem: round-off of eigenvalues of order 100.
    EXPECT_NEAR(pair.eigenvalue, reference.eigenvalues()[i], 1e-10);
    const Eigen::VectorXd& phi = pair.vector;
    EXPECT_NEAR(phi[1], phi[2], 1e-12);  // the massless DOF moves with the tied one
    // The mode is the reference's up to its scale: u1 / u3 agree.
    const Eigen::Vector2d expected = reference.eigenvectors().col(i);
    EXPECT_NEAR(phi[0] / phi[2], expected[0] / expected[1], 1e-10);
    // Fᵀφ has unit length (the vector as the eigensolver returns it, before normalization).
    EXPECT_NEAR(2.0 * phi[0] * phi[0] + 3.0 * phi[2] * phi[2], 1.0, 1e-12);
  }
}

TEST(FrequencyEigensolver, TheRangeKeepsOnlyTheEigenvaluesInIt) {
  const TiedSprings system;
  const SparseMatrix k = from_dense(system.k, Storage::Upper);
  std::unique_ptr<LinearSolver> solver = make_linear_solver(SolverChoice::Dense, true, false);
  std::string message;
  ASSERT_EQ(solver->analyze(k, &message), LinearStatus::Ok) << message;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> reference(
      Eigen::Matrix2d{{150, -50}, {-50, 80}}, Eigen::Matrix2d{{2, 0}, {0, 3}});
  EigenRequest request;
  // Between the two eigenvalues: only the higher one.
  request.shift = request.lower = 0.5 * (reference.eigenvalues()[0] + reference.eigenvalues()[1]);
  const EigenResult result = solve_frequency_eigenproblem(k, system.mass, request, *solver);
  ASSERT_TRUE(result.error.empty()) << result.error;
  ASSERT_EQ(result.pairs.size(), 1u);
  EXPECT_NEAR(result.pairs[0].eigenvalue, reference.eigenvalues()[1], 1e-10);
}

}  // namespace
}  // namespace clinch
