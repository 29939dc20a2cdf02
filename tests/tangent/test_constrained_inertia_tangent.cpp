// The effective tangent of a *DYNAMIC increment with inertia on constrained nodes (docs/dynamics.md
// "Inertia on constrained nodes") against central differences of the residual, through the
// checker of `clinch run --check-tangent`: Tᵀ(∂a/∂u M/(1 + α))T of masses on a rigid body's tie
// nodes and of a mass tied to one of them by an *EQUATION (a chain), and under NLGEOM the
// curvature of the rigid arms under the inertia force and the HHT α force at the dependent DOFs,
// which turns with the reference node (an unsymmetric term: the full pattern is compared).
#include <gtest/gtest.h>

#include "tests/tangent/assembled_system.hpp"

namespace clinch {
namespace {

// Node 1 held; node 2 is the reference node of a rigid body with tie nodes 3 and 4 (masses 2.5
// and 1.5, off its axes); node 5 (mass 0.8) follows U1 of node 4 through an *EQUATION, a chain
// (under NLGEOM, which refuses a chain through a rigid arm, U1 of node 2). SPRINGAs
// from node 1 to nodes 3, 4 and 5 give the elements on dependent DOFs; the body starts with a
// velocity and a spin, so that the accelerations and the HHT α term are not zero.
std::string constrained_deck(bool nlgeom) {
  return std::string(
             "*NODE\n1, 0., 0., 0.\n2, 0.2, 0.1, 0.\n3, 1.0, 0.3, 0.2\n4, -0.4, 0.9, -0.3\n"
             "5, 1.5, 1.2, 0.4\n"
             "*NSET, NSET=TIES\n3, 4\n*RIGID BODY, REF NODE=2, TIE NSET=TIES\n"
             "*ELEMENT, TYPE=SPRINGA, ELSET=K\n1, 1, 3\n2, 1, 4\n3, 1, 5\n"
             "*SPRING, ELSET=K\n\n100.\n"
             "*ELEMENT, TYPE=MASS, ELSET=M3\n6, 3\n*MASS, ELSET=M3\n2.5\n"
             "*ELEMENT, TYPE=MASS, ELSET=M4\n7, 4\n*MASS, ELSET=M4\n1.5\n"
             "*ELEMENT, TYPE=MASS, ELSET=M5\n8, 5\n*MASS, ELSET=M5\n0.8\n"
             "*EQUATION\n2\n5, 1, 1., " + std::string(nlgeom ? "2" : "4") + ", 1, -1.\n"
             "*INITIAL CONDITIONS, TYPE=VELOCITY\n2, 1, 0.3\n2, 2, -0.2\n2, 4, 0.5\n2, 6, 0.7\n"
             "*BOUNDARY\n1, 1, 3\n") +
         (nlgeom ? "*STEP, NLGEOM" : "*STEP") +
         "\n*DYNAMIC, DIRECT, ALPHA=-0.1\n0.01, 0.1\n*END STEP\n";
}

void check_constrained_tangent(bool nlgeom) {
  auto a = analyse(constrained_deck(nlgeom));
  ASSERT_TRUE(a->system);
  ConnectorSystem& s = *a->system;
  ASSERT_FALSE(a->plan->dependents.empty());
  start_dynamic_trial(s, *a->plan, nlgeom, *a->deck.model.history.steps[0].dynamic, 0.01,
                      nlgeom ? 5u : 13u);
  double largest = 0;
  // Central differences with h = 1e-7 on values of 0.05: truncation O(h²|r'''|) and rounding
  // O(ε|r|/h) ≈ 1e-9 of the largest entry (≈ 4e4 from the condensed M/(βΔt²)); 1e-6 of it
  // bounds both.
  const JacobianReport report =
      tangent_against_differences(s, [](int) { return 1e-7; }, false, largest);
  ASSERT_TRUE(report.evaluated()) << report;
  EXPECT_GT(largest, 1e4);  // the condensed mass term dominates
  EXPECT_LE(report.max_error, 1e-6 * largest) << report;
  // The free solved equations are the six DOFs of the reference node and U2, U3 of node 5 (node
  // 1 is held, the tie nodes and U1 of node 5 are dependent; node 5's block mixes both): every
  // entry of their rows and columns.
  EXPECT_EQ(report.compared, 64);
}

TEST(ConstrainedInertiaTangent, SmallDisplacements) { check_constrained_tangent(false); }
TEST(ConstrainedInertiaTangent, NlgeomRigidArmsTurn) { check_constrained_tangent(true); }

}  // namespace
}  // namespace clinch
