// Kinematic constraints by elimination (docs/constraints.md "Elimination"): the condensed tangent
// (TᵀKT plus the NLGEOM curvature of rigid arms and links) against central differences of the
// condensed residual, in both regimes, through the shared checker; and Newton on a rigid lever
// at a finite rotation against its closed form, converging quadratically. The constraints are
// built here by hand, as the resolve stage builds them from *RIGID BODY, *MPC and *EQUATION.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/tangent/assembled_system.hpp"

namespace clinch {
namespace {

NodeFollower follow(std::int32_t node, std::int32_t reference, DofMask dofs, bool arm = true) {
  NodeFollower f;
  f.node = node;
  f.reference = reference;
  f.dofs = dofs;
  f.rigid_arm = arm;
  return f;
}

// Two rigid bodies (references 1 and 3, tie nodes 2 and 4, pin node 5 of body 3) joined by a
// BUSHING between their tie nodes; body 3 anchored at its tie node 4 in translation 1, as a
// *BOUNDARY there makes it (anchor_rigid_bodies.cpp), with a load on its reference node's u₁; a CARTESIAN from the pin node to node 6, which an MPC LINK
// keeps at its distance from node 7; a SPRINGA from 7 to 8, whose DOF 2 an equation ties to
// 0.5·u₇,₁; an MPC TIE (no arm) makes node 9 follow node 8, with a SPRING1 on node 9.
std::string scene_deck(bool nlgeom) {
  return "*NODE\n1, 0., 0., 0.\n2, 0.8, 0.3, -0.2\n3, 2.0, 0.5, 0.1\n4, 1.5, 0.2, 0.3\n"
         "5, 2.4, -0.3, 0.6\n6, 3.0, 0.1, 0.2\n7, 3.7, 0.6, 0.5\n8, 4.5, 0.2, 0.1\n"
         "9, 4.9, 0.4, 0.3\n"
         "*ELEMENT, TYPE=CONN3D2, ELSET=C1\n1, 2, 4\n*ELEMENT, TYPE=CONN3D2, ELSET=C2\n2, 5, 6\n"
         "*ELEMENT, TYPE=SPRINGA, ELSET=S\n3, 7, 8\n*ELEMENT, TYPE=SPRING1, ELSET=S1\n4, 9\n"
         "*ORIENTATION, NAME=O\n0.9, 0.3, 0.1, -0.2, 0.8, 0.4\n"
         "*CONNECTOR SECTION, ELSET=C1, BEHAVIOR=B\nBUSHING,\nO\n"
         "*CONNECTOR SECTION, ELSET=C2, BEHAVIOR=B\nCARTESIAN,\nO\n"
         "*CONNECTOR BEHAVIOR, NAME=B\n*CONNECTOR ELASTICITY\n"
         "1000., 100., 800., 50., 40., 900., 0., 0.\n0., 30., 0., 0., 0., 0., 20., 0.\n"
         "0., 0., 0., 5., 25.\n*SPRING, ELSET=S\n\n300.\n*SPRING, ELSET=S1\n2\n70.\n*STEP" +
         std::string(nlgeom ? ", NLGEOM" : "") + "\n*STATIC\n*END STEP\n";
}

void add_scene_constraints(Model& model) {
  ConstraintModel& c = model.constraints;
  c.followers.push_back(follow(1, 0, 0b111111));
  c.followers.push_back(follow(3, 2, 0b111110));
  c.followers.push_back(follow(4, 2, 0b000110));
  for (std::int32_t node : {2, 4}) {
    NodeFollower anchored = follow(node, 2, 0b000001);
    anchored.anchor = 3;
    c.followers.push_back(anchored);
  }
  // The reference node's u₁ takes part when a *CLOAD names it (active_dofs.cpp).
  ConcentratedLoad load;
  load.resolved = {2};
  load.dof = 1;
  model.history.steps.front().loads.push_back(load);
  c.followers.push_back(follow(8, 7, 0b111111, false));
  c.links.push_back({5, 6, -1});
  c.equations.push_back({{{7, 2, 1.0}, {6, 1, -0.5}}, true, -1});
}

// At random states, with loads on dependent DOFs (their curvature is part of the tangent under
// NLGEOM). Tolerance as for the connector families (test_assembled_tangent.cpp): central
// differences with h = 1e-6 err by O(h²·|K'''|) + O(ε·|r|/h), within 1e-5 of the largest entry.
// Under NLGEOM the assembled tangent is the symmetric part of the Jacobian, as for the
// connectors' own rotations (connection-types.md §3.7).
TEST(ConstraintElimination, CondensedTangentMatchesFiniteDifferences) {
  for (bool nlgeom : {false, true}) {
    auto a = analyse(scene_deck(nlgeom), add_scene_constraints);
    ASSERT_TRUE(a->system);
    ConnectorSystem& s = *a->system;
    const DofMap& dofs = a->plan->dofs;
    EXPECT_EQ(a->plan->dependents.dofs.size(), 6u + 6 + 3 + 1 + 1 + 1);
    s.set_nlgeom(nlgeom);
    s.conditions().clear();
    s.conditions().add_load(dofs.equation(1, 2), 40.0);   // a tie node
    s.conditions().add_load(dofs.equation(1, 6), -15.0);  // its rotation
    s.conditions().add_load(dofs.equation(4, 3), 25.0);   // the pin node
    s.conditions().add_load(dofs.equation(2, 1), 30.0);   // a reference node that follows
    s.start_increment(0.0);
    for (unsigned seed : {7u, 8u}) {
      const Eigen::VectorXd state = random_state(s.size(), seed, 0.15);
      s.apply_correction(state);
      double largest = 0;
      const JacobianReport report =
          tangent_against_differences(s, [](int) { return 1e-6; }, true, largest);
      ASSERT_TRUE(report.evaluated()) << report;
      EXPECT_LE(report.max_error, 1e-5 * largest) << (nlgeom ? "NLGEOM" : "") << "\n" << report;
      EXPECT_GE(report.compared, 100);
      s.apply_correction(-state);
    }
  }
}

// A rigid lever: reference node 1 at the origin, turning about z only (DOFs 1–5 held), tie node 2
// at (L, 0, 0) with a SPRING1 of stiffness k on its DOF 2. A moment M about z — on the reference
// node, or on the tie node, where it acts on the body — turns the lever by θ with
// M = k·L sin θ·L cos θ under NLGEOM (the spring's force k·u₂ stays along y, its arm is L cos θ),
// and M = k L² θ in small displacements. The reaction at the reference node is the spring's force
// k L sin θ along y.
TEST(ConstraintElimination, RigidLeverTurnsToItsClosedForm) {
  const double k = 200.0, length = 1.5;
  for (bool nlgeom : {false, true}) {
    for (bool on_tie : {false, true}) {
      auto a = analyse(
          "*NODE\n1, 0., 0., 0.\n2, 1.5, 0., 0.\n*ELEMENT, TYPE=SPRING1, ELSET=S\n1, 2\n"
          "*SPRING, ELSET=S\n2\n200.\n*STEP" +
              std::string(nlgeom ? ", NLGEOM" : "") + "\n*STATIC\n*END STEP\n",
          [on_tie](Model& model) {
            model.constraints.followers.push_back(follow(1, 0, 0b111111));
            // The tie node's DOF 6 takes part when a *CLOAD names it (active_dofs.cpp).
            ConcentratedLoad load;
            load.resolved = {on_tie ? 1 : 0};
            load.dof = 6;
            model.history.steps.front().loads.push_back(load);
          });
      ASSERT_TRUE(a->system);
      ConnectorSystem& s = *a->system;
      const DofMap& dofs = a->plan->dofs;
      s.set_nlgeom(nlgeom);
      s.conditions().clear();
      for (int dof = 1; dof <= 5; ++dof) {
        if (dofs.equation(0, dof) >= 0) s.conditions().prescribe(dofs.equation(0, dof), 0.0);
      }
      const double moment = 0.4 * k * length * length;
      s.conditions().add_load(dofs.equation(on_tie ? 1 : 0, 6), moment);
      s.start_increment(0.0);
      const NewtonReport report = solve_tightly(s);
      ASSERT_TRUE(report.converged()) << report.message;
      // sin 2θ = 2M/(kL²) = 0.8 under NLGEOM; θ = M/(kL²) = 0.4 in small displacements.
      // Tolerance: Newton stops once the criteria hold, here with a last moment residual of
      // about 2e-7 against a rotational stiffness kL² cos 2θ = 270, an error of 1e-9 rad.
      const double theta = nlgeom ? std::asin(0.8) / 2 : 0.4;
      const double tolerance = 1e-8;
      EXPECT_NEAR(s.value(dofs.equation(0, 6)), theta, tolerance);
      if (on_tie) EXPECT_NEAR(s.value(dofs.equation(1, 6)), theta, tolerance);  // it turns too
      const double uy = nlgeom ? length * std::sin(theta) : length * theta;
      EXPECT_NEAR(s.value(dofs.equation(1, 2)), uy, length * tolerance);
      // The reaction is the spring's force (computed at the converged state: to round-off).
      EXPECT_NEAR(s.reaction(0, 2), k * s.value(dofs.equation(1, 2)), 1e-9);
      if (nlgeom) expect_quadratic_convergence(report, 1);
    }
  }
}

}  // namespace
}  // namespace clinch
