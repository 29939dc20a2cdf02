// ForcingTerm (src/solver/forcing_term.hpp) against Eisenstat–Walker's choice 2 worked by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "src/solver/forcing_term.hpp"

namespace clinch {
namespace {

// Each expected value is a product of at most four decimal numbers: 1e-15 relative covers the
// rounding of those products.
constexpr double kTol = 1e-15;

TEST(ForcingTerm, FirstCorrectionUsesTheStartingTerm) {
  ForcingTerm forcing;
  EXPECT_DOUBLE_EQ(forcing.next(0, 123.0), ForcingTerm::kFirst);
}

TEST(ForcingTerm, QuadraticDecreaseTightensWithTheSquareOfTheRatio) {
  ForcingTerm forcing;
  forcing.next(0, 1.0);
  // ratio 0.1: 0.9·0.01 = 0.009; the safeguard 0.9·0.1² = 0.009 is below 0.1 and does not act.
  EXPECT_NEAR(forcing.next(1, 0.1), 0.009, 0.009 * kTol);
  // ratio 1e-3: 0.9e-6.
  EXPECT_NEAR(forcing.next(2, 1e-4), 0.9e-6, 0.9e-6 * kTol);
}

TEST(ForcingTerm, SlowProgressIsClampedAndCarriedOverASuddenDrop) {
  ForcingTerm forcing;
  forcing.next(0, 1.0);
  // ratio 0.9: 0.729, clamped to the largest term 0.5.
  EXPECT_DOUBLE_EQ(forcing.next(1, 0.9), ForcingTerm::kLargest);
  // ratio 0.01 would give 9e-5, but 0.9·0.5² = 0.225 > 0.1 is kept.
  EXPECT_NEAR(forcing.next(2, 0.009), 0.225, 0.225 * kTol);
  // Then 0.9·0.225² = 0.0455625 < 0.1: the plain term 0.9·(0.1)² = 0.009 again.
  EXPECT_NEAR(forcing.next(3, 0.0009), 0.009, 0.009 * kTol);
}

TEST(ForcingTerm, NeverAsksForLessThanTheSmallestTerm) {
  ForcingTerm forcing;
  forcing.next(0, 1.0);
  EXPECT_DOUBLE_EQ(forcing.next(1, 1e-9), ForcingTerm::kSmallest);
}

// An overflowing residual norm (inf) has no ratio to the last one: the term stays inside
// (0, 1), where an iterative solver accepts it, instead of becoming NaN (inf / inf).
TEST(ForcingTerm, NonFiniteNormsKeepTheTermInRange) {
  const double inf = std::numeric_limits<double>::infinity();
  ForcingTerm forcing;
  EXPECT_DOUBLE_EQ(forcing.next(0, inf), ForcingTerm::kFirst);
  EXPECT_DOUBLE_EQ(forcing.next(1, inf), ForcingTerm::kFirst);
  EXPECT_DOUBLE_EQ(forcing.next(2, std::nan("")), ForcingTerm::kFirst);
  // From a finite norm again the ratio of two finite norms is used: 0.9·(0.1)² = 0.009.
  forcing.next(3, 1.0);
  EXPECT_NEAR(forcing.next(4, 0.1), 0.009, 0.009 * kTol);
}

}  // namespace
}  // namespace clinch
