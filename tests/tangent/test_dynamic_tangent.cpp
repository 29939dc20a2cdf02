// The effective tangent of a *DYNAMIC increment (docs/dynamics.md) against central differences
// of the residual, through the checker of `clinch run --check-tangent`: K + ∂a/∂u M/(1 + α) with
// the nodal masses and a full rotary inertia tensor, and the dashpots at the step's velocities
// (∂v/∂u c ∇Δ∇Δᵀ, and under NLGEOM the turn of a DASHPOTA's line with the nodal velocities, an
// unsymmetric term: the full pattern is compared). The state, the velocities and the
// accelerations are not zero, so every term is exercised.
#include <gtest/gtest.h>

#include "tests/tangent/assembled_system.hpp"

namespace clinch {
namespace {

// Node 1 held, node 2 carries a mass and the ends of a SPRINGA and of a DASHPOTA at an angle;
// node 3 carries a mass on a DASHPOTA to node 2; initial velocities on several free DOFs. With
// small displacements node 2 also turns: SPRING1s and a DASHPOT1 on its rotations and a rotary
// inertia tensor with products of inertia (under NLGEOM the multiplicative rotation update of the
// springs has a Jacobian term clinch leaves out, test_assembled_tangent; the finite-rotation
// inertia has a test of its own below).
std::string dynamic_deck(bool nlgeom) {
  const std::string turning =
      "*ELEMENT, TYPE=SPRING1, ELSET=KR\n4, 2\n*SPRING, ELSET=KR\n6\n20.\n"
      "*ELEMENT, TYPE=DASHPOT1, ELSET=CR\n5, 2\n*DASHPOT, ELSET=CR\n6\n3.\n"
      "*ELEMENT, TYPE=SPRING1, ELSET=KR4\n8, 2\n*SPRING, ELSET=KR4\n4\n20.\n"
      "*ELEMENT, TYPE=SPRING1, ELSET=KR5\n9, 2\n*SPRING, ELSET=KR5\n5\n20.\n"
      "*ELEMENT, TYPE=ROTARYI, ELSET=J\n10, 2\n"
      "*ROTARY INERTIA, ELSET=J\n0.4, 0.5, 0.6, 0.05, -0.03, 0.02\n"
      "*INITIAL CONDITIONS, TYPE=VELOCITY\n2, 6, 0.7\n";
  return "*NODE\n1, 0., 0., 0.\n2, 0.6, 0.8, 0.\n3, 1.5, 0.7, 0.3\n"
         "*ELEMENT, TYPE=SPRINGA, ELSET=K\n1, 1, 2\n"
         "*SPRING, ELSET=K\n\n100.\n"
         "*ELEMENT, TYPE=DASHPOTA, ELSET=C\n2, 1, 2\n3, 2, 3\n"
         "*DASHPOT, ELSET=C\n\n30.\n"
         "*ELEMENT, TYPE=MASS, ELSET=M\n6, 2\n7, 3\n*MASS, ELSET=M\n2.5\n"
         "*INITIAL CONDITIONS, TYPE=VELOCITY\n2, 1, 0.3\n2, 2, -0.2\n3, 3, 0.5\n"
         "*BOUNDARY\n1, 1, 3\n" +
         (nlgeom ? std::string("*STEP, NLGEOM") : turning + "*STEP") +
         "\n*DYNAMIC, DIRECT, ALPHA=-0.1\n0.01, 0.1\n*END STEP\n";
}

void check_dynamic_tangent(bool nlgeom, bool backward_euler) {
  auto a = analyse(dynamic_deck(nlgeom));
  ASSERT_TRUE(a->system);
  ConnectorSystem& s = *a->system;
  DynamicProcedure procedure = *a->deck.model.history.steps[0].dynamic;
  procedure.backward_euler = backward_euler;
  // Accelerations at the start from the dashpots' forces at the initial velocities, then a
  // random trial state of the increment.
  start_dynamic_trial(s, *a->plan, nlgeom, procedure, 0.01, nlgeom ? 7u : 11u);
  double largest = 0;
  // Central differences with h = 1e-7 on values of 0.05: truncation O(h²|r'''|) and rounding
  // O(ε|r|/h) ≈ 1e-9 of the largest entry (≈ 2.5e4 from M/(βΔt²)); 1e-6 of it bounds both.
  const JacobianReport report =
      tangent_against_differences(s, [](int) { return 1e-7; }, false, largest);
  ASSERT_TRUE(report.evaluated()) << report;
  EXPECT_GT(largest, 1e4);  // the mass term dominates: M/(β Δt²) ≈ 2.5·10⁴
  EXPECT_LE(report.max_error, 1e-6 * largest) << report;
  // Every entry of the free rows and columns (node 1 is held).
  EXPECT_EQ(report.compared, (s.size() - 3) * (s.size() - 3));
}

// Under NLGEOM a node with a full rotary inertia tensor turns by finite rotations
// (rotary_inertia_finite.hpp): its rows 2(π₁ − π₀)/Δt + r₀ against central differences of spins
// R ← exp(δθ̂)R, at a trial rotation 0.05 rad from a converged one that is itself turned and
// spinning, so that the unsymmetric −π̂₁ and the T(Θ)⁻¹ terms are exercised.
void check_finite_rotary_tangent(const std::string& deck, int compared) {
  auto a = analyse(deck);
  ASSERT_TRUE(a->system);
  ConnectorSystem& s = *a->system;
  s.set_nlgeom(true);
  s.use_storage(false);  // −π̂₁ is unsymmetric
  const DynamicProcedure procedure = *a->deck.model.history.steps[0].dynamic;
  s.start_dynamic_step(true);
  s.set_integration(&procedure, 0.01);
  s.start_increment(0.0);
  s.apply_correction(random_state(s.size(), 5u, 0.3));
  s.commit();  // a turned converged state R₀ ≠ I
  s.start_increment(0.0);
  s.apply_correction(random_state(s.size(), 9u, 0.05));
  double largest = 0;
  // Central differences with h = 1e-7: the entries are ≈ 4J/Δt² ≈ 1e5; truncation O(h²) and
  // rounding O(ε|r|/h) ≈ 1e-9 of the largest; 1e-6 of it bounds both.
  const JacobianReport report =
      tangent_against_differences(s, [](int) { return 1e-7; }, false, largest);
  ASSERT_TRUE(report.evaluated()) << report;
  EXPECT_GT(largest, 1e4);
  EXPECT_LE(report.max_error, 1e-6 * largest) << report;
  EXPECT_EQ(report.compared, compared);
}

const char* const kRotaryInertia =
    "*ELEMENT, TYPE=ROTARYI, ELSET=J\n4, 1\n"
    "*ROTARY INERTIA, ELSET=J\n2., 3., 4., 0.1, -0.2, 0.15\n"
    "*INITIAL CONDITIONS, TYPE=VELOCITY\n1, 4, 1.0\n1, 5, 0.3\n1, 6, 0.8\n"
    "*STEP, NLGEOM\n*DYNAMIC, DIRECT\n0.01, 0.1\n*END STEP\n";

// One node; three SPRING1 of zero stiffness only make its rotations active.
TEST(DynamicTangent, NlgeomFiniteRotaryInertia) {
  check_finite_rotary_tangent(
      std::string("*NODE\n1, 0., 0., 0.\n"
                  "*ELEMENT, TYPE=SPRING1, ELSET=S4\n1, 1\n*SPRING, ELSET=S4\n4\n0.\n"
                  "*ELEMENT, TYPE=SPRING1, ELSET=S5\n2, 1\n*SPRING, ELSET=S5\n5\n0.\n"
                  "*ELEMENT, TYPE=SPRING1, ELSET=S6\n3, 1\n*SPRING, ELSET=S6\n6\n0.\n") +
          kRotaryInertia,
      9);
}

// The same node as a rigid body's reference node, after a tie node with a MASS in the node
// order: the tie node's equations come first and are eliminated, so the rotary rows sit at
// solved positions below their equation numbers (the tangent is over the solved equations).
TEST(DynamicTangent, NlgeomFiniteRotaryInertiaAfterADependentNode) {
  check_finite_rotary_tangent(
      std::string("*NODE\n5, 0.4, -0.3, 0.2\n1, 0., 0., 0.\n*NSET, NSET=TIE\n5\n"
                  "*RIGID BODY, REF NODE=1, TIE NSET=TIE\n"
                  "*ELEMENT, TYPE=MASS, ELSET=M\n6, 5\n*MASS, ELSET=M\n3.\n") +
          kRotaryInertia,
      36);
}

}  // namespace
}  // namespace clinch
