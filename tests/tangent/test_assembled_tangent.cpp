// The assembled system of `clinch run`: the tangent that ConnectorSystem scatters (kinematics,
// behaviour, geometric stiffness, multiplier rows) against central finite differences of its
// residual, for several connection types in both regimes, and Newton's quadratic convergence on
// smooth problems: an NLGEOM spring and load-controlled coupled plasticity (ARCHITECTURE.md
// testing habits 1 and 3).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <random>
#include <vector>

#include "parser/deck_reader.hpp"
#include "src/assembly/analysis_plan.hpp"
#include "src/assembly/connector_system.hpp"
#include "src/linalg/linear_solver.hpp"
#include "src/solver/newton.hpp"
#include "src/solver/tangent_check.hpp"
#include "tests/tangent/contract_test_laws.hpp"
#include "tests/tangent/assembled_system.hpp"
#include "tests/unit/checked_deck.hpp"

namespace clinch {
namespace {

// Two nodes, one connector of `type` (orientation at a, rotated off the global axes), an elastic
// behaviour on every available component, node 1 held. Every DOF of node 2 is free.
std::string connector_deck(const std::string& type, bool nlgeom) {
  return "*NODE\n1, 0., 0., 0.\n2, 0.8, 0.3, -0.2\n*ELEMENT, TYPE=CONN3D2, ELSET=C\n1, 1, 2\n"
         "*ORIENTATION, NAME=O\n0.9, 0.3, 0.1, -0.2, 0.8, 0.4\n"
         "*CONNECTOR SECTION, ELSET=C, BEHAVIOR=B\n" +
         type +
         ",\nO\n"
         "*CONNECTOR BEHAVIOR, NAME=B\n*CONNECTOR ELASTICITY\n"
         "1000., 100., 800., 50., 40., 900., 0., 0.\n0., 30., 0., 0., 0., 0., 20., 0.\n"
         "0., 0., 0., 5., 25.\n"
         "*BOUNDARY\n1, 1, 6\n*STEP" +
         std::string(nlgeom ? ", NLGEOM" : "") + "\n*STATIC\n*END STEP\n";
}

// At a random state (displacements, finite rotations, multipliers), the assembled tangent equals
// the symmetric part of the finite-difference Jacobian of the residual. Only the symmetric part:
// under the multiplicative rotation update the exact Jacobian adds −½ skew(moment) on each
// node's rotation block (connection-types.md §3.7), which clinch v1 leaves out. Tolerance:
// central differences with h = 1e-6 have truncation error O(h²·|K'''|) and rounding
// O(ε·|r|/h) ≈ 1e-10·|r|; 1e-5 of the largest entry covers both with margin (behaviors.md §1.4).
void check_tangent_at_random_state(const std::string& type, bool nlgeom, unsigned seed,
                                   const std::string& deck = "", bool settle_stops = false) {
  auto a = analyse(deck.empty() ? connector_deck(type, nlgeom) : deck);
  ASSERT_TRUE(a->system);
  ConnectorSystem& s = *a->system;
  s.set_nlgeom(nlgeom);
  s.conditions().clear();
  for (int dof = 1; dof <= 6; ++dof) {
    const int eq = a->plan->dofs.equation(0, dof);
    if (eq >= 0) s.conditions().prescribe(eq, 0.0);
  }
  s.start_increment(0.0);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  Eigen::VectorXd state = Eigen::VectorXd::Zero(s.size());
  for (int i = 0; i < s.size(); ++i) {
    if (!s.is_prescribed(i)) state[i] = u(rng) * (i >= a->plan->dofs.node_equations() ? 100 : 1);
  }
  s.apply_correction(state);
  if (settle_stops) {
    // Activate the stops the random state violates, then solve the multipliers once.
    ASSERT_TRUE(s.update_active_set());
  }
  double largest = 0;
  const JacobianReport report =
      tangent_against_differences(s, [](int) { return 1e-6; }, true, largest);
  ASSERT_GT(largest, 0);
  ASSERT_TRUE(report.evaluated()) << report;
  EXPECT_LE(report.max_error, 1e-5 * largest) << type << (nlgeom ? " NLGEOM" : "") << "\n"
                                              << report;
  EXPECT_GE(report.compared, 9);  // at least the 3 × 3 translational block of node 2
}

TEST(AssembledTangent, MatchesFiniteDifferencesForEveryFamily) {
  for (const char* type :
       {"AXIAL", "CARTESIAN", "SLOT", "CARDAN", "ROTATION", "HINGE", "BUSHING", "WELD", "UJOINT"}) {
    for (bool nlgeom : {false, true}) {
      for (unsigned seed : {1u, 2u}) check_tangent_at_random_state(type, nlgeom, seed);
    }
  }
}

// At an active stop (behaviors.md §5.4): the stop's multiplier row and the free components'
// stiffness, with the active set frozen. A CARTESIAN connector whose components 1 and 2 carry
// stops that the random state (|u| up to 0.2) violates by construction (limits ±0.01 about the
// initial position x0 = e·d0).
TEST(AssembledTangent, MatchesFiniteDifferencesAtActiveStops) {
  for (bool nlgeom : {false, true}) {
    const std::string deck =
        "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=CONN3D2, ELSET=C\n1, 1, 2\n"
        "*CONNECTOR SECTION, ELSET=C, BEHAVIOR=B\nCARTESIAN,\n*CONNECTOR BEHAVIOR, NAME=B\n"
        "*CONNECTOR ELASTICITY, COMPONENT=1\n1000.\n*CONNECTOR ELASTICITY, COMPONENT=2\n500.\n"
        "*CONNECTOR ELASTICITY, COMPONENT=3\n800.\n*CONNECTOR STOP, COMPONENT=1\n0.99, 1.01\n"
        "*CONNECTOR STOP, COMPONENT=2\n-0.01, 0.01\n*BOUNDARY\n1, 1, 6\n*STEP" +
        std::string(nlgeom ? ", NLGEOM" : "") + "\n*STATIC\n*END STEP\n";
    for (unsigned seed : {3u, 4u})
      check_tangent_at_random_state("CARTESIAN", nlgeom, seed, deck, true);
  }
}

// Dashpots (behaviors.md §8: v = ΔΔ/Δt): DASHPOTA beside a SPRINGA between free nodes 2 and 3
// (NLGEOM: the force turns with the line), DASHPOT1 with a NONLINEAR table and DASHPOT2, at a
// random trial state away from the converged one (x_n = 0), Δt = 0.1. The random state stays
// inside the table's segments away from its breakpoints for these seeds (|v| ≤ 2 lands in the
// middle segments or beyond the ends, where the force is constant), so central differences see
// a smooth function; same tolerance as the connector families above.
TEST(AssembledTangent, DashpotsMatchFiniteDifferences) {
  const std::string deck_text =
      "*NODE\n1, 0., 0., 0.\n2, 0.6, 0.8, 0.\n3, 1.5, 1.1, 0.3\n4, 2., 0., 0.\n"
      "*ELEMENT, TYPE=DASHPOTA, ELSET=DA\n1, 2, 3\n*ELEMENT, TYPE=SPRINGA, ELSET=SA\n2, 2, 3\n"
      "*ELEMENT, TYPE=DASHPOT1, ELSET=D1\n3, 2\n*ELEMENT, TYPE=DASHPOT2, ELSET=D2\n4, 3, 4\n"
      "*DASHPOT, ELSET=DA\n\n30.\n*SPRING, ELSET=SA\n\n100.\n"
      "*DASHPOT, ELSET=D1, NONLINEAR\n2\n-8., -3.\n0., 0.\n2., 0.7\n5., 3.\n"
      "*DASHPOT, ELSET=D2\n1, 2\n20.\n*BOUNDARY\n1, 1, 3\n4, 1, 3\n*STEP";
  for (bool nlgeom : {false, true}) {
    auto a = analyse(deck_text + (nlgeom ? ", NLGEOM" : "") + "\n*STATIC\n*END STEP\n");
    ASSERT_TRUE(a->system);
    ConnectorSystem& s = *a->system;
    s.set_nlgeom(nlgeom);
    s.set_time(0.1, 0.1);
    s.start_increment(0.0);
    for (unsigned seed : {5u, 6u}) {
      const Eigen::VectorXd state = random_state(s.size(), seed, 0.2);
      s.apply_correction(state);
      double largest = 0;
      const JacobianReport report =
          tangent_against_differences(s, [](int) { return 1e-6; }, true, largest);
      ASSERT_TRUE(report.evaluated()) << report;
      EXPECT_GT(largest, 30.0 / 0.1);  // the dashpots' c/Δt is in the tangent
      EXPECT_LE(report.max_error, 1e-5 * largest) << (nlgeom ? "NLGEOM" : "") << "\n" << report;
      EXPECT_GE(report.compared, 36);  // nodes 2 and 3, translations
      s.apply_correction(-state);
    }
  }
}

// A pretensioned AXIAL spring (k = 1000, l0 = 1) whose free end is loaded by (100, 50) under
// NLGEOM: the spring must turn to carry the load, a smooth problem with exact solution
// |F| = k(l − 1) along the load. Newton on the full tangent (with the geometric term f/l)
// converges quadratically: each residual is at most C times the square of the previous one once
// the iterates are close (C = 1 in these units is generous: observed ≈ 1e-3).
TEST(AssembledTangent, NewtonConvergesQuadraticallyOnASmoothNlgeomProblem) {
  auto a = analyse(
      "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=CONN3D2, ELSET=C\n1, 1, 2\n"
      "*CONNECTOR SECTION, ELSET=C, BEHAVIOR=B\nAXIAL,\n*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n1000.\n*BOUNDARY\n1, 1, 3\n2, 3, 3\n"
      "*STEP, NLGEOM\n*STATIC\n*END STEP\n");
  ASSERT_TRUE(a->system);
  ConnectorSystem& s = *a->system;
  const DofMap& dofs = a->plan->dofs;
  s.set_nlgeom(true);
  s.conditions().clear();
  for (int dof = 1; dof <= 3; ++dof) s.conditions().prescribe(dofs.equation(0, dof), 0.0);
  s.conditions().prescribe(dofs.equation(1, 3), 0.0);
  s.conditions().add_load(dofs.equation(1, 1), 100.0);
  s.conditions().add_load(dofs.equation(1, 2), 50.0);
  s.start_increment(0.0);
  Eigen::VectorXd guess = Eigen::VectorXd::Zero(s.size());
  guess[dofs.equation(1, 1)] = 0.05;  // a start with tension, so that the tangent is regular
  guess[dofs.equation(1, 2)] = 0.02;
  s.apply_correction(guess);
  const NewtonReport report = solve_tightly(s);
  ASSERT_TRUE(report.converged()) << report.message;
  expect_quadratic_convergence(report, 0);
  // The converged state: the spring along the load with |F| = k (l − 1).
  const double ux = s.value(dofs.equation(1, 1)), uy = s.value(dofs.equation(1, 2));
  const double l = std::hypot(1 + ux, uy);
  EXPECT_NEAR(1000 * (l - 1), std::hypot(100.0, 50.0), 1e-8);
  EXPECT_NEAR(uy / (1 + ux), 0.5, 1e-12);
}

// A prescribed increment enters the first correction through the tangent at the start of the
// increment (docs/decisions.md "Prescribed increments"): two AXIAL connectors under NLGEOM, node 2
// free along x between node 1 (held) and node 3, which is moved by 0.1 along y. From the
// undeformed state (no force, so no geometric stiffness) the x row of node 2 reads
// (k + k/2)·Δu₂ = (k/2)·Δv₃ (bar 2–3 along (1, 1)/√2), so the first correction is exactly
// Δu₂ = Δv₃/3; a first iterate that jumped to the target would linearise about the stretched
// bar instead. Newton then converges on the NLGEOM answer.
TEST(AssembledTangent, FirstCorrectionIsTheLinearPredictorOfAPrescribedIncrement) {
  auto a = analyse(
      "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n3, 2., 1., 0.\n*ELEMENT, TYPE=CONN3D2, ELSET=C\n"
      "1, 1, 2\n2, 2, 3\n*CONNECTOR SECTION, ELSET=C, BEHAVIOR=B\nAXIAL,\n"
      "*CONNECTOR BEHAVIOR, NAME=B\n*CONNECTOR ELASTICITY, COMPONENT=1\n1000.\n"
      "*BOUNDARY\n1, 1, 3\n2, 2, 3\n3, 1, 3\n*STEP, NLGEOM\n*STATIC\n*END STEP\n");
  ASSERT_TRUE(a->system);
  ConnectorSystem& s = *a->system;
  const DofMap& dofs = a->plan->dofs;
  s.set_nlgeom(true);
  s.conditions().clear();
  for (int dof = 1; dof <= 3; ++dof) {
    s.conditions().prescribe(dofs.equation(0, dof), 0.0);
    s.conditions().prescribe(dofs.equation(2, dof), dof == 2 ? 0.1 : 0.0);
  }
  s.conditions().prescribe(dofs.equation(1, 2), 0.0);
  s.conditions().prescribe(dofs.equation(1, 3), 0.0);
  s.start_increment(0.0);
  const int u2 = dofs.equation(1, 1), v3 = dofs.equation(2, 2);
  EXPECT_TRUE(s.moving_prescribed());
  EXPECT_EQ(s.value(v3), 0.0);  // not moved before the first correction

  Eigen::VectorXd residual(s.size()), correction(s.size());
  SparseMatrix tangent = s.pattern();
  ASSERT_TRUE(s.evaluate(residual, &tangent).ok);
  auto solver = make_linear_solver(SolverChoice::Dense, true, true);
  std::string message;
  ASSERT_EQ(solver->analyze(tangent, &message), LinearStatus::Ok) << message;
  ASSERT_EQ(solver->factorize(tangent, &message), LinearStatus::Ok) << message;
  ASSERT_EQ(solver->solve(-residual, correction, &message), LinearStatus::Ok) << message;
  s.apply_correction(correction);
  EXPECT_FALSE(s.moving_prescribed());
  EXPECT_EQ(s.value(v3), 0.1);  // on the target exactly
  EXPECT_NEAR(s.value(u2), 0.1 / 3.0, 1e-15);

  const NewtonReport report = solve_tightly(s);
  ASSERT_TRUE(report.converged()) << report.message;
  // NLGEOM equilibrium of node 2 along x: bar 1 pulls with k(l₁ − 1), bar 2 (from node 2 to
  // node 3 = (2, 1.1)) with k(l₂ − √2)·(1 − u₂)/l₂.
  const double u = s.value(u2);
  const double l1 = 1 + u, l2 = std::hypot(1 - u, 1.1);
  EXPECT_NEAR(1000 * (l1 - 1), 1000 * (l2 - std::sqrt(2.0)) * (1 - u) / l2, 1e-9);
  EXPECT_GT(std::abs(u - 0.1 / 3.0), 1e-4);  // the NLGEOM answer is not the linear one

  // The next increment of a steady ramp, extrapolated: the prescribed DOF moves with the free
  // ones and lands on its target, so nothing is left for a predictor.
  s.commit();
  s.conditions().prescribe(v3, 0.2);
  s.start_increment(1.0);
  EXPECT_FALSE(s.moving_prescribed());
  EXPECT_EQ(s.value(v3), 0.2);
  EXPECT_NEAR(s.value(u2), 2 * u, 1e-15);
}

// One load-controlled increment from the virgin state, solved tightly: node 1 held in its six
// DOFs (a CARTESIAN or BUSHING connector activates the rotations of node a, connection-types.md
// §1.1), node 2 loaded by `load` on its DOFs 1, 2, …
NewtonReport solve_loaded(Analysis& a, const std::vector<double>& load) {
  ConnectorSystem& s = *a.system;
  const DofMap& dofs = a.plan->dofs;
  s.conditions().clear();
  for (int dof = 1; dof <= 6; ++dof) s.conditions().prescribe(dofs.equation(0, dof), 0.0);
  for (std::size_t i = 0; i < load.size(); ++i) {
    s.conditions().add_load(dofs.equation(1, static_cast<int>(i) + 1), load[i]);
  }
  s.start_increment(0.0);
  return solve_tightly(s);
}

// Load-controlled coupled plasticity from the virgin state in one increment: the connector of
// behaviors.md §6.7 E11b (CARTESIAN, k = 1000, P = sqrt(f1² + (f2/2)²), F_y = 100 + 200 ū) with
// node 2 loaded by (120, 150, 0), a non-radial return. With the consistent tangent of §6.4 the
// global Newton converges quadratically; the converged force equals the load and lies on the
// hardened surface P(F) = F_y(ū) with ū = (P − 100)/200.
TEST(AssembledTangent, NewtonConvergesQuadraticallyOnLoadControlledCoupledPlasticity) {
  auto a = analyse(
      "*NODE\n1, 0., 0., 0.\n2, 0., 0., 0.\n*ELEMENT, TYPE=CONN3D2, ELSET=C\n1, 1, 2\n"
      "*CONNECTOR SECTION, ELSET=C, BEHAVIOR=B\nCARTESIAN,\n*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n1000.\n*CONNECTOR ELASTICITY, COMPONENT=2\n1000.\n"
      "*CONNECTOR ELASTICITY, COMPONENT=3\n1000.\n*CONNECTOR PLASTICITY\n"
      "*CONNECTOR HARDENING, TYPE=ISOTROPIC\n100., 0.\n300., 1.\n"
      "*CONNECTOR POTENTIAL\n1, 1.\n2, 2.\n*BOUNDARY\n1, 1, 6\n"
      "*STEP\n*STATIC\n*END STEP\n");
  ASSERT_TRUE(a->system);
  const NewtonReport report = solve_loaded(*a, {120.0, 150.0});
  ASSERT_TRUE(report.converged()) << report.message;
  expect_quadratic_convergence(report, 0);
  const ConnectorOutput out = a->system->connector_output(0);
  EXPECT_NEAR(out.total[0], 120.0, 1e-9);
  EXPECT_NEAR(out.total[1], 150.0, 1e-9);
  const double p = std::hypot(120.0, 75.0);
  EXPECT_NEAR(out.history_value("CUPEQC", 0), (p - 100.0) / 200.0, 1e-12);
}

// `welds` spot welds (derived-components-and-potentials.md §3, β = 1.5) on BUSHING, weld k
// between nodes 2k + 1 and 2k + 2 (coincident), all with the one behaviour `weld`.
std::string spot_weld_deck(int welds) {
  std::string nodes = "*NODE\n", elements = "*ELEMENT, TYPE=CONN3D2, ELSET=C\n";
  for (int k = 0; k < welds; ++k) {
    const std::string x = std::to_string(k) + ".";
    nodes += std::to_string(2 * k + 1) + ", " + x + ", 0., 0.\n" + std::to_string(2 * k + 2) +
             ", " + x + ", 0., 0.\n";
    elements += std::to_string(k + 1) + ", " + std::to_string(2 * k + 1) + ", " +
                std::to_string(2 * k + 2) + "\n";
  }
  return "*PARAMETER\nr_n = sqrt(30.68/19.63)\nor_n = 1.0/r_n\nor_s = 0.5/r_n\n" + nodes +
         elements +
         "*ORIENTATION, NAME=G\n1., 0., 0., 0., 1., 0.\n"
         "*CONNECTOR SECTION, ELSET=C, BEHAVIOR=weld\nBUSHING,\nG\n"
         "*CONNECTOR BEHAVIOR, NAME=weld\n"
         "*CONNECTOR ELASTICITY, COMPONENT=1\n1.0e5\n*CONNECTOR ELASTICITY, COMPONENT=2\n1.0e5\n"
         "*CONNECTOR ELASTICITY, COMPONENT=3\n2.0e5\n*CONNECTOR ELASTICITY, COMPONENT=4\n1.0e6\n"
         "*CONNECTOR ELASTICITY, COMPONENT=5\n1.0e6\n*CONNECTOR ELASTICITY, COMPONENT=6\n5.0e5\n"
         "*CONNECTOR PLASTICITY\n*CONNECTOR HARDENING\n40000., 0.\n50000., 0.001\n"
         "*CONNECTOR POTENTIAL, EXPONENT=1.5\nnormal, 0.02, , MACAULEY, ,\nshear, 0.05, , ABS, ,\n"
         "*CONNECTOR DERIVED COMPONENT, NAME=normal, OPERATOR=MACAULEY SUM\n3\n1.0\n"
         "*CONNECTOR DERIVED COMPONENT, NAME=normal\n4, 5\n<or_n>, <or_n>\n"
         "*CONNECTOR DERIVED COMPONENT, NAME=shear\n6\n<or_s>\n"
         "*CONNECTOR DERIVED COMPONENT, NAME=shear\n1, 2\n1.0, 1.0\n"
         "*STEP\n*STATIC\n*END STEP\n";
}

// The spot weld on BUSHING under a load with all six components non-zero, so that no
// contribution or derived-component term is near a kink: a smooth problem, and Newton converges
// quadratically in forces and in moments.
TEST(AssembledTangent, NewtonConvergesQuadraticallyOnLoadControlledSpotWeld) {
  auto a = analyse(spot_weld_deck(1));
  ASSERT_TRUE(a->system);
  const std::vector<double> load = {300.0, -400.0, 500.0, 200.0, 150.0, 800.0};  // P ≈ 4.2e4
  const NewtonReport report = solve_loaded(*a, load);
  ASSERT_TRUE(report.converged()) << report.message;
  expect_quadratic_convergence(report, 0);
  expect_quadratic_convergence(report, 1);
  const ConnectorOutput out = a->system->connector_output(0);
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(out.total[i], load[static_cast<std::size_t>(i)], 1e-8 * 800.0) << i;
  }
  EXPECT_GT(out.history_value("CUPEQC", 0), 0.0);
}

// 37 welds sharing one behaviour instance. Each weld carries its own load (the one above scaled
// by 0.85 to 1.15, below the plateau of the hardening; some elastic, most plastic, signs varied
// so that f3 is compressive on some);
// every weld ends in equilibrium with its load, and its state equals that of the same weld
// solved alone: ū to 1e-9, motions to 1e-7 (below). The assembled tangent of the 37 welds
// matches finite differences at a random state.
TEST(AssembledTangent, WeldsSharingABehaviourEachMatchTheWeldAlone) {
  constexpr int kWelds = 37;
  auto a = analyse(spot_weld_deck(kWelds));
  ASSERT_TRUE(a->system);
  ConnectorSystem& s = *a->system;
  const DofMap& dofs = a->plan->dofs;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const std::vector<double> base = {300.0, -400.0, 500.0, 200.0, 150.0, 800.0};
  std::vector<std::vector<double>> loads;
  s.conditions().clear();
  for (int k = 0; k < kWelds; ++k) {
    std::vector<double> load = base;
    const double scale = 0.85 + 0.3 * unit(rng);  // P in 3.6e4–4.9e4: yield at 4e4, plateau 5e4
    for (double& f : load) f *= scale * (unit(rng) < 0.2 ? -1.0 : 1.0);
    for (int dof = 1; dof <= 6; ++dof) {
      s.conditions().prescribe(dofs.equation(2 * k, dof), 0.0);
      s.conditions().add_load(dofs.equation(2 * k + 1, dof), load[static_cast<std::size_t>(dof - 1)]);
    }
    loads.push_back(load);
  }
  s.start_increment(0.0);
  const NewtonReport report = solve_tightly(s);
  ASSERT_TRUE(report.converged()) << report.message;
  int plastic = 0;
  for (int k = 0; k < kWelds; ++k) {
    const ConnectorOutput out = s.connector_output(static_cast<std::size_t>(k));
    for (int i = 0; i < 6; ++i) {
      EXPECT_NEAR(out.total[i], loads[k][static_cast<std::size_t>(i)], 1e-8 * 1200.0) << k;
    }
    auto alone = analyse(spot_weld_deck(1));
    ASSERT_TRUE(solve_loaded(*alone, loads[k]).converged());
    const ConnectorOutput single = alone->system->connector_output(0);
    EXPECT_NEAR(out.history_value("CUPEQC", 0), single.history_value("CUPEQC", 0),
                1e-9)
        << k;
    // Motions to 1e-7: the tight solve stops on the residual (1e-13 of the forces), and along
    // the flow the weld's tangent is down to ~1e-4 of its elastic stiffness.
    EXPECT_LE((out.constitutive - single.constitutive).norm(), 1e-7 * single.constitutive.norm())
        << k;
    plastic += out.history_value("CUPEQC", 0) > 0;
  }
  EXPECT_GE(plastic, 15);
  EXPECT_LE(plastic, kWelds - 3);
  check_tangent_at_random_state("", false, 3, spot_weld_deck(kWelds));
}

// A SLOT connector (component 1 free, 2 and 3 constrained) whose law on component 1 reads the
// constraint force of component 2 (ContactStiffenedSpring, f₁ = k u₁ + c λ₂ u₁³), node 1 held,
// node 2 loaded by (P₁, P₂, 0). The deck's elasticity is replaced by the test law.
constexpr double kSpringK = 1000.0, kContactC = 2e5, kLoad1 = 200.0, kLoad2 = 50.0;
std::unique_ptr<Analysis> contact_stiffened_slot(const ContactStiffenedSpring& law) {
  auto a = std::make_unique<Analysis>();
  read_deck_text("deck.inp",
                 "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=CONN3D2, ELSET=C\n1, 1, 2\n"
                 "*CONNECTOR SECTION, ELSET=C\nSLOT,\n*BOUNDARY\n1, 1, 6\n"
                 "*STEP\n*STATIC\n*END STEP\n",
                 a->deck.sources, a->deck.model, a->deck.sink);
  EXPECT_FALSE(a->deck.sink.has_errors()) << a->deck.dump();
  std::string error;
  a->plan = build_analysis_plan(a->deck.model, &error);
  EXPECT_TRUE(a->plan) << error;
  if (!a->plan) return a;
  a->plan->add_law(0, law);
  a->system = std::make_unique<ConnectorSystem>(a->deck.model, *a->plan);
  a->system->use_storage(a->plan->laws_symmetric());
  ConnectorSystem& s = *a->system;
  s.conditions().clear();
  for (int dof = 1; dof <= 6; ++dof) {
    const int eq = a->plan->dofs.equation(0, dof);  // SLOT: node a's rotations are active
    if (eq >= 0) s.conditions().prescribe(eq, 0.0);
  }
  s.conditions().add_load(a->plan->dofs.equation(1, 1), kLoad1);
  s.conditions().add_load(a->plan->dofs.equation(1, 2), kLoad2);
  s.start_increment(0.0);
  return a;
}

// The element's full tangent, including the column of the SLOT multiplier λ₂ (∂f₁/∂λ₂ = c u₁³
// in the u₁ row, which the transposed entry does not have), against central differences of the
// residual at random states. Full storage: every entry is compared, not the symmetric part.
// Tolerance as in check_tangent_at_random_state: 1e-5 of the largest entry (behaviors.md §1.4).
TEST(AssembledTangent, LawThatReadsAMultiplierHasItsBlockInTheFullTangent) {
  const ContactStiffenedSpring law(kSpringK, kContactC);
  auto a = contact_stiffened_slot(law);
  ASSERT_TRUE(a->system);
  ConnectorSystem& s = *a->system;
  ASSERT_FALSE(s.symmetric_storage());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 3; ++trial) {
    // A new random state: displacements of 0.05, multipliers of 80.
    Eigen::VectorXd move = Eigen::VectorXd::Zero(s.size());
    for (int i = 0; i < s.size(); ++i) {
      if (s.is_prescribed(i)) continue;
      move[i] = (i >= a->plan->dofs.node_equations() ? 80.0 : 0.05) * unit(rng) - s.value(i);
    }
    s.apply_correction(move);
    SparseMatrix k = s.pattern();
    Eigen::VectorXd r(s.size());
    ASSERT_TRUE(s.evaluate(r, &k).ok);
    ASSERT_FALSE(k.symmetric_upper);
    double largest = 0;
    for (double v : k.values) largest = std::max(largest, std::abs(v));
    Eigen::VectorXd steps = Eigen::VectorXd::Zero(s.size());
    for (int j = 0; j < s.size(); ++j) {
      if (!s.is_prescribed(j)) steps[j] = 1e-6;
    }
    const JacobianReport report = check_assembled_tangent(s, k, steps);
    ASSERT_TRUE(report.evaluated()) << report;
    EXPECT_LE(report.max_error, 1e-5 * largest) << report;
    // The block against the multiplier is there and is what the law says: ∂r(u₁)/∂λ₂ = c u₁³.
    const int u1 = a->plan->dofs.equation(1, 1);
    const ConnectorRecord& slot = a->plan->connectors[0];
    ASSERT_EQ(slot.multiplier_components[0], 2);
    const int lambda2 = slot.local.equation[static_cast<std::size_t>(slot.column_count)];
    const double u = s.value(u1);
    EXPECT_NEAR(entry(k, u1, lambda2), kContactC * u * u * u, 1e-12 * largest);
    EXPECT_NE(entry(k, u1, lambda2), entry(k, lambda2, u1));
  }
}

// Newton on the same connector under load converges quadratically (the residual at most
// 1·r² once r < 1, expect_quadratic_convergence) to the root of k u + c P₂ u³ = P₁ (λ₂ = P₂),
// which bisection finds independently to 1e-15.
TEST(AssembledTangent, NewtonConvergesQuadraticallyWithALawThatReadsAMultiplier) {
  const ContactStiffenedSpring law(kSpringK, kContactC);
  auto a = contact_stiffened_slot(law);
  ASSERT_TRUE(a->system);
  ConnectorSystem& s = *a->system;
  const NewtonReport report = solve_tightly(s);
  ASSERT_TRUE(report.converged()) << report.message;
  EXPECT_GE(report.iterations.size(), 5u);  // nonlinear enough to show the rate
  expect_quadratic_convergence(report, 0);
  double lo = 0, hi = kLoad1 / kSpringK;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (kSpringK * mid + kContactC * kLoad2 * mid * mid * mid < kLoad1 ? lo : hi) = mid;
  }
  EXPECT_NEAR(s.value(a->plan->dofs.equation(1, 1)), 0.5 * (lo + hi), 1e-12);
  const ConnectorOutput out = s.connector_output(0);
  EXPECT_NEAR(out.multiplier[1], kLoad2, 1e-9);
  EXPECT_NEAR(out.total[0], kLoad1, 1e-9);
}

// A SLIDE-PLANE with predefined friction (friction.md §2.3: J = {2, 3}, F_N = |λ1|, the
// multiplier of the constrained normal): the element's full tangent, with the friction rows'
// entries in the column of λ1 (∂f^fr/∂λ1, which the transposed entry does not have), against
// central differences of the residual, sticking (motions of 1e-4: trial 1 < F_lim) and slipping
// (motions of 0.05: trial ≈ 500 > F_lim ≤ 24). Tolerance as in check_tangent_at_random_state.
TEST(AssembledTangent, FrictionElementTangentWithTheMultiplierColumn) {
  auto a = analyse(
      "*NODE\n1, 0., 0., 0.\n2, 0., 0., 0.\n*ELEMENT, TYPE=CONN3D2, ELSET=C\n1, 1, 2\n"
      "*ORIENTATION, NAME=O\n0.9, 0.3, 0.1, -0.2, 0.8, 0.4\n"
      "*CONNECTOR SECTION, ELSET=C, BEHAVIOR=B\nSLIDE-PLANE,\nO\n*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR FRICTION, PREDEFINED, STICK STIFFNESS=1.0e4\n*FRICTION\n0.3\n"
      "*BOUNDARY\n1, 1, 6\n*STEP\n*STATIC\n*END STEP\n");
  ASSERT_TRUE(a->system);
  ConnectorSystem& s = *a->system;
  ASSERT_FALSE(a->plan->laws_symmetric());
  s.use_storage(false);  // as the step driver chooses for an unsymmetric law
  s.conditions().clear();
  for (int dof = 1; dof <= 6; ++dof) {
    const int eq = a->plan->dofs.equation(0, dof);
    if (eq >= 0) s.conditions().prescribe(eq, 0.0);
  }
  s.start_increment(0.0);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (double size : {1e-4, 0.05, 0.05}) {
    Eigen::VectorXd move = Eigen::VectorXd::Zero(s.size());
    for (int i = 0; i < s.size(); ++i) {
      if (s.is_prescribed(i)) continue;
      const bool multiplier = i >= a->plan->dofs.node_equations();
      move[i] = (multiplier ? 80.0 * (unit(rng) > 0 ? 1 : -1) : size * unit(rng)) - s.value(i);
    }
    s.apply_correction(move);
    double largest = 0;
    const int nodal = a->plan->dofs.node_equations();
    const JacobianReport report = tangent_against_differences(
        s, [nodal](int j) { return j >= nodal ? 1e-4 : 1e-8; }, false, largest);
    ASSERT_GT(largest, 0);
    ASSERT_TRUE(report.evaluated()) << report;
    EXPECT_LE(report.max_error, 1e-5 * largest) << "motions of " << size << "\n" << report;
    const ConnectorOutput out = s.connector_output(0);
    const double capacity = 0.3 * std::abs(out.multiplier[0]);
    EXPECT_LE(std::hypot(out.friction[1], out.friction[2]), capacity * (1 + 1e-12) + 1e-12);
    if (size > 1e-3) EXPECT_NEAR(std::hypot(out.friction[1], out.friction[2]), capacity, 1e-9);
  }
}

// Load-controlled slip from the virgin state in one increment: CARTESIAN with elasticity on
// every component (k1 = 1e4 gives the contact force, k2 = k3 = 1000 in parallel with the
// friction), friction through the elliptic potential P = sqrt(f2² + (f3/2)²) with
// F_N = |CEF1| (CONTACT FORCE=1) and the static–kinetic decay μ = 0.1 + 0.2·exp(−0.5 γ̇) at
// Δt = 0.1 (the capacity is a smooth function of the slip), loads (−500, 400, 300): the
// connector slips to equilibrium. The return is nonlinear and the friction rows depend on u1
// through the contact force (an unsymmetric tangent, UMFPACK); Newton converges quadratically
// (expect_quadratic_convergence) to CTF = load with F_N = 500. The first iterate (u = 0) has
// F_N = 0 and so no capacity: its friction tangent is 0 (friction.md §4.1 step 5), and Newton
// needs four iterations (residuals 500, 87.5, 1.9, 5e-4, 1e-10). Round-off of the residual is
// near 500·ε ≈ 1e-13, so the last two are both above it and show the quadratic rate.
TEST(AssembledTangent, NewtonConvergesQuadraticallyOnLoadControlledCoupledFriction) {
  auto a = analyse(
      "*NODE\n1, 0., 0., 0.\n2, 0., 0., 0.\n*ELEMENT, TYPE=CONN3D2, ELSET=C\n1, 1, 2\n"
      "*CONNECTOR SECTION, ELSET=C, BEHAVIOR=B\nCARTESIAN,\n*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n1.0e4\n*CONNECTOR ELASTICITY, COMPONENT=2\n1000.\n"
      "*CONNECTOR ELASTICITY, COMPONENT=3\n1000.\n"
      "*CONNECTOR FRICTION, CONTACT FORCE=1, STICK STIFFNESS=1.0e4\n*CONNECTOR POTENTIAL\n"
      "2, 1.\n3, 2.\n*FRICTION, EXPONENTIAL DECAY\n0.3, 0.1, 0.5\n*BOUNDARY\n1, 1, 6\n*STEP\n*STATIC\n*END STEP\n");
  ASSERT_TRUE(a->system);
  ASSERT_FALSE(a->plan->laws_symmetric());
  a->system->use_storage(false);
  a->system->set_time(0.1, 0.1);
  const NewtonReport report = solve_loaded(*a, {-500.0, 400.0, 300.0});
  ASSERT_TRUE(report.converged()) << report.message;
  expect_quadratic_convergence(report, 0, 1e-12);
  const ConnectorOutput out = a->system->connector_output(0);
  // Newton stops once its criteria hold (observed residual 1e-10 after four iterations):
  // equilibrium to 1e-5.
  EXPECT_NEAR(out.total[0], -500.0, 1e-5);
  EXPECT_NEAR(out.total[1], 400.0, 1e-5);
  EXPECT_NEAR(out.total[2], 300.0, 1e-5);
  EXPECT_NEAR(out.history_value("CNFC", 0), 500.0, 1e-9);
  EXPECT_GT(out.history_value("CASUC", 0), 0.0);
}

}  // namespace
}  // namespace clinch
