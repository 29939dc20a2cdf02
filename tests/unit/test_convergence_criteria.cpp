// The equilibrium tests of *CONTROLS (keywords.md §16) on hand-made iteration norms: the Rₙ and
// Cₙ tests of a loaded field, and the two round-off floors (IterationNorms::resolution and
// force_resolution) that keep a field with nothing in it from holding an increment forever.
#include <gtest/gtest.h>

#include "src/solver/convergence_criteria.hpp"

namespace clinch {
namespace {

// A translational field carrying forces of about 90 (q̄ = flux), converged in itself: residual
// 1e-3·q̄ < Rₙ·q̄, correction 1e-4 of the increment < Cₙ. Resolutions as ConnectorSystem sets
// them with L̄ = 1.
IterationNorms loaded_translations() {
  IterationNorms n;
  n.flux[0] = 90.0;
  n.largest_residual[0] = 0.09;
  n.largest_increment[0] = 0.36;
  n.largest_correction[0] = 3.6e-5;
  n.resolution[0] = 1e-12;
  n.resolution[1] = 1e-12;
  n.force_resolution[0] = 9e-11;
  n.force_resolution[1] = 9e-11;
  return n;
}

TEST(ConvergenceCriteria, LoadedFieldPassesOnlyBelowBothTolerances) {
  ConvergenceCriteria criteria{Controls{}};
  IterationNorms n = loaded_translations();
  EXPECT_TRUE(criteria.converged(n, 1));
  n.largest_residual[0] = 0.006 * 90.0;  // above Rₙ = 0.005
  EXPECT_FALSE(criteria.converged(n, 1));
  n = loaded_translations();
  n.largest_correction[0] = 0.02 * 0.36;  // above Cₙ = 0.01
  EXPECT_FALSE(criteria.converged(n, 1));
}

// Moments of 3e-14 beside forces of 90 are round-off: before force_resolution the moment field
// was its own q̄ (r = q̄ = flux) and failed Rₙ at every iteration, so the increment was cut back
// until the round-off vanished.
TEST(ConvergenceCriteria, RoundOffMomentsBesideForcesAreNoField) {
  ConvergenceCriteria criteria{Controls{}};
  IterationNorms n = loaded_translations();
  n.flux[1] = 2.8e-14;
  n.largest_residual[1] = 2.8e-14;
  n.largest_increment[1] = 0.36;
  n.largest_correction[1] = 1.1e-16;
  EXPECT_TRUE(criteria.converged(n, 2));
  // A real moment field of the same shape (flux and residual equal) does not pass.
  n.flux[1] = n.largest_residual[1] = 1.0;
  EXPECT_FALSE(criteria.converged(n, 2));
}

// A zero-force field that did not move (increment 0) with a correction of 1e-16: the C_ε test
// against an increment of 0 can never pass, the round-off floor of the correction does. The
// rotational residual is set above ε_l·q̄₀ = 1e-10, so that the field reaches the correction test
// instead of passing as linear.
TEST(ConvergenceCriteria, RoundOffCorrectionOfAFieldThatDoesNotMovePasses) {
  ConvergenceCriteria criteria{Controls{}};
  IterationNorms n = loaded_translations();
  n.largest_residual[1] = 1e-9;
  n.largest_correction[1] = 1.1e-16;  // rotations: no flux, no increment
  EXPECT_TRUE(criteria.converged(n, 2));
  n.largest_correction[1] = 1e-9;  // above 1e-12 rad: a real correction against no increment
  EXPECT_FALSE(criteria.converged(n, 2));
}

// A model with no force anywhere (a linkage turned by a connector motion alone): every
// entry of q̃ is round-off, 1e-30, and so is the residual. Such a flux is at most ε·q̄₀ = 1e-7:
// zero flux (§16 field 6), which takes the correction test and leaves q̄ at q̄₀. Before, the
// round-off was taken for q̄ (it is far above 1e-12 of itself) and Rₙ failed at every iteration.
TEST(ConvergenceCriteria, RoundOffFluxOfAModelWithoutForcesIsZeroFlux) {
  ConvergenceCriteria criteria{Controls{}};
  IterationNorms n;
  n.flux[0] = 6e-31;
  n.largest_residual[0] = 6e-31;
  n.largest_increment[0] = 2.0;
  n.largest_correction[0] = 1.4e-15;
  n.resolution[0] = n.resolution[1] = 1e-11;
  n.force_resolution[0] = n.force_resolution[1] = 6e-43;
  EXPECT_TRUE(criteria.converged(n, 3));
  EXPECT_DOUBLE_EQ(criteria.average_flux(n, 0), 0.01);
  criteria.accept_increment(n);
  EXPECT_DOUBLE_EQ(criteria.average_flux(n, 0), 0.01);
  // A flux and residual of 1e-9 (above ε_l·q̄₀ = 1e-10, so not passed as linear) are zero flux
  // as well: a round-off correction passes, a real one (above C_ε = 1e-3 of the increment) not.
  n.flux[0] = n.largest_residual[0] = 1e-9;
  n.force_resolution[0] = n.force_resolution[1] = 1e-21;
  EXPECT_TRUE(criteria.converged(n, 3));
  n.largest_correction[0] = 0.02;
  EXPECT_FALSE(criteria.converged(n, 3));
  // Once forces of 90 have set q̄, a flux of 1e-4 (≤ ε·q̄ = 9e-4) is zero flux too and does
  // not pull q̄ down.
  criteria.accept_increment(loaded_translations());
  IterationNorms small = loaded_translations();
  small.flux[0] = 1e-4;
  EXPECT_DOUBLE_EQ(criteria.average_flux(small, 0), 90.0);
}

}  // namespace
}  // namespace clinch
