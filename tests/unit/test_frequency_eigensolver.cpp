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
// With u2 = u3 eliminated by hand: K = [[150, −50], [−50, 80]], M = diag(2, 3), whose dense
// generalized eigensolve is the reference.
struct TiedSprings {
  SparseMatrix k = from_dense(
      Eigen::MatrixXd{{150, -50, 0, 0}, {-50, 50, 0, -1}, {0, 0, 30, 1}, {0, -1, 1, 0}},
      Storage::Upper);
  LumpedMass mass{{{0, 0, 2.0}, {2, 2, 3.0}}, {{{0, std::sqrt(2.0)}}, {{2, std::sqrt(3.0)}}}};
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> reference{
      Eigen::Matrix2d{{150, -50}, {-50, 80}}, Eigen::Matrix2d{{2, 0}, {0, 3}}};

  EigenResult solve(const EigenRequest& request) const {
    // Dense LU: K − σM is indefinite with the multiplier.
    std::unique_ptr<LinearSolver> solver = make_linear_solver(SolverChoice::Dense, true, false);
    std::string message;
    EXPECT_EQ(solver->analyze(k, &message), LinearStatus::Ok) << message;
    return solve_frequency_eigenproblem(k, mass, request, *solver);
  }
};

TEST(FrequencyEigensolver, MultiplierAndMasslessDofGiveTheEliminatedSystemsEigenpairs) {
  const TiedSprings system;
  EigenRequest request;
  request.shift = request.lower = -1e-3;
  request.count = 2;
  const EigenResult result = system.solve(request);
  ASSERT_TRUE(result.error.empty()) << result.error;
  ASSERT_EQ(result.pairs.size(), 2u);
  EXPECT_EQ(result.available, 2);
  const auto& reference = system.reference;
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
  const Eigen::Vector2d& lambda = system.reference.eigenvalues();
  EigenRequest request;
  // Between the two eigenvalues: only the higher one.
  request.shift = request.lower = 0.5 * (lambda[0] + lambda[1]);
  const EigenResult result = system.solve(request);
  ASSERT_TRUE(result.error.empty()) << result.error;
  ASSERT_EQ(result.pairs.size(), 1u);
  EXPECT_NEAR(result.pairs[0].eigenvalue, lambda[1], 1e-10);
}

}  // namespace
}  // namespace clinch
