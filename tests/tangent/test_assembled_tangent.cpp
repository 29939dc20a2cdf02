// The assembled system of `clinch run`: the tangent that ConnectorSystem scatters (kinematics,
// behaviour, geometric stiffness, multiplier rows) against central finite differences of its
// residual, for several connection types in both regimes, and Newton's quadratic convergence on a
// smooth NLGEOM problem (ARCHITECTURE.md testing habits 1 and 3).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "parser/deck_reader.hpp"
#include "src/assembly/analysis_plan.hpp"
#include "src/assembly/connector_system.hpp"
#include "src/linalg/linear_solver.hpp"
#include "src/solver/newton.hpp"
#include "tests/unit/checked_deck.hpp"

namespace clinch {
namespace {

struct Analysis {
  CheckedDeck deck;
  std::optional<AnalysisPlan> plan;
  std::unique_ptr<ConnectorSystem> system;
};

std::unique_ptr<Analysis> analyse(const std::string& text) {
  auto a = std::make_unique<Analysis>();
  read_deck_text("deck.inp", text, a->deck.sources, a->deck.model, a->deck.sink);
  EXPECT_FALSE(a->deck.sink.has_errors()) << a->deck.dump();
  std::string error;
  a->plan = build_analysis_plan(a->deck.model, &error);
  EXPECT_TRUE(a->plan) << error;
  if (a->plan) a->system = std::make_unique<ConnectorSystem>(a->deck.model, *a->plan);
  return a;
}

double entry(const SparseMatrix& k, int row, int column) {
  if (row > column) std::swap(row, column);
  for (int p = k.col_ptr[static_cast<std::size_t>(column)];
       p < k.col_ptr[static_cast<std::size_t>(column) + 1]; ++p) {
    if (k.row_idx[static_cast<std::size_t>(p)] == row) return k.values[static_cast<std::size_t>(p)];
  }
  return 0.0;
}

// Two nodes, one connector of `type` (orientation at a, rotated off the global axes), an elastic
// behaviour on every available component, node 1 held. Every DOF of node 2 is free.
std::string connector_deck(const std::string& type, bool nlgeom) {
  return "*NODE\n1, 0., 0., 0.\n2, 0.8, 0.3, -0.2\n*ELEMENT, TYPE=CONN3D2, ELSET=C\n1, 1, 2\n"
         "*ORIENTATION, NAME=O\n0.9, 0.3, 0.1, -0.2, 0.8, 0.4\n"
         "*CONNECTOR SECTION, ELSET=C, BEHAVIOR=B\n" + type + ",\nO\n"
         "*CONNECTOR BEHAVIOR, NAME=B\n*CONNECTOR ELASTICITY\n"
         "1000., 100., 800., 50., 40., 900., 0., 0.\n0., 30., 0., 0., 0., 0., 20., 0.\n"
         "0., 0., 0., 5., 25.\n"
         "*BOUNDARY\n1, 1, 6\n*STEP" + std::string(nlgeom ? ", NLGEOM" : "") +
         "\n*STATIC\n*END STEP\n";
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
  s.clear_conditions();
  for (int dof = 1; dof <= 6; ++dof) {
    const int eq = a->plan->dofs.equation(0, dof);
    if (eq >= 0) s.prescribe(eq, 0.0);
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
    ASSERT_TRUE(s.update_stops());
  }
  SparseMatrix k = s.pattern();
  Eigen::VectorXd r(s.size()), plus(s.size()), minus(s.size());
  ASSERT_TRUE(s.evaluate(r, &k).ok);
  double largest = 0;
  for (double v : k.values) largest = std::max(largest, std::abs(v));
  Eigen::MatrixXd fd = Eigen::MatrixXd::Zero(s.size(), s.size());
  const double h = 1e-6;
  for (int j = 0; j < s.size(); ++j) {
    if (s.is_prescribed(j)) continue;
    Eigen::VectorXd step = Eigen::VectorXd::Zero(s.size());
    step[j] = h;
    s.apply_correction(step);
    ASSERT_TRUE(s.evaluate(plus, nullptr).ok);
    step[j] = -2 * h;
    s.apply_correction(step);
    ASSERT_TRUE(s.evaluate(minus, nullptr).ok);
    step[j] = h;
    s.apply_correction(step);
    fd.col(j) = (plus - minus) / (2 * h);
  }
  int checked = 0;
  for (int i = 0; i < s.size(); ++i) {
    for (int j = 0; j < s.size(); ++j) {
      if (s.is_prescribed(i) || s.is_prescribed(j)) continue;
      const double numeric = 0.5 * (fd(i, j) + fd(j, i));
      EXPECT_NEAR(entry(k, i, j), numeric, 1e-5 * largest)
          << type << (nlgeom ? " NLGEOM" : "") << " entry (" << i << ", " << j << ")";
      ++checked;
    }
  }
  EXPECT_GE(checked, 9);  // at least the 3 × 3 translational block of node 2
}

TEST(AssembledTangent, MatchesFiniteDifferencesForEveryFamily) {
  for (const char* type : {"AXIAL", "CARTESIAN", "SLOT", "CARDAN", "ROTATION", "HINGE", "BUSHING",
                           "WELD", "UJOINT"}) {
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
  const std::string deck =
      "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=CONN3D2, ELSET=C\n1, 1, 2\n"
      "*CONNECTOR SECTION, ELSET=C, BEHAVIOR=B\nCARTESIAN,\n*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n1000.\n*CONNECTOR ELASTICITY, COMPONENT=2\n500.\n"
      "*CONNECTOR ELASTICITY, COMPONENT=3\n800.\n*CONNECTOR STOP, COMPONENT=1\n0.99, 1.01\n"
      "*CONNECTOR STOP, COMPONENT=2\n-0.01, 0.01\n*BOUNDARY\n1, 1, 6\n*STEP, NLGEOM\n*STATIC\n"
      "*END STEP\n";
  for (bool nlgeom : {false, true}) {
    for (unsigned seed : {3u, 4u}) check_tangent_at_random_state("CARTESIAN", nlgeom, seed, deck, true);
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
  s.clear_conditions();
  for (int dof = 1; dof <= 3; ++dof) s.prescribe(dofs.equation(0, dof), 0.0);
  s.prescribe(dofs.equation(1, 3), 0.0);
  s.add_load(dofs.equation(1, 1), 100.0);
  s.add_load(dofs.equation(1, 2), 50.0);
  s.start_increment(0.0);
  Eigen::VectorXd guess = Eigen::VectorXd::Zero(s.size());
  guess[dofs.equation(1, 1)] = 0.05;  // a start with tension, so that the tangent is regular
  guess[dofs.equation(1, 2)] = 0.02;
  s.apply_correction(guess);
  Controls tight;
  tight.translation.residual = 1e-13;
  tight.translation.correction = 1e-13;
  ConvergenceCriteria criteria(tight);
  auto solver = make_linear_solver(SolverChoice::Automatic, true, true);
  std::string message;
  ASSERT_EQ(solver->analyze(s.pattern(), &message), LinearStatus::Ok) << message;
  const NewtonReport report = solve_increment(s, *solver, criteria, NewtonOptions{});
  ASSERT_TRUE(report.converged()) << report.message;
  std::vector<double> r;
  for (const IterationNorms& n : report.iterations) r.push_back(n.largest_residual[0]);
  ASSERT_GE(r.size(), 4u);
  int asserted = 0;
  for (std::size_t i = 1; i < r.size(); ++i) {
    if (r[i - 1] > 1.0 || r[i] < 1e-9) continue;  // pre-asymptotic, or at round-off
    EXPECT_LE(r[i], 1.0 * r[i - 1] * r[i - 1]) << "iteration " << i;
    ++asserted;
  }
  EXPECT_GE(asserted, 1);
  // The converged state: the spring along the load with |F| = k (l − 1).
  const double ux = s.value(dofs.equation(1, 1)), uy = s.value(dofs.equation(1, 2));
  const double l = std::hypot(1 + ux, uy);
  EXPECT_NEAR(1000 * (l - 1), std::hypot(100.0, 50.0), 1e-8);
  EXPECT_NEAR(uy / (1 + ux), 0.5, 1e-12);
}

}  // namespace
}  // namespace clinch
