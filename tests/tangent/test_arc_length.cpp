// The Riks system (src/solver/arc_length_problem.hpp, docs/riks.md) on the von Mises truss under
// NLGEOM: its bordered Jacobian [K, ∂r/∂λ; ∂g/∂q, ∂g/∂λ] against central differences of the
// bordered residual (r, g) through the shared checker, at states off the path; and Newton on it
// through BorderedSolver converging quadratically onto the path, whose closed form it meets.
#include <gtest/gtest.h>

#include <cmath>

#include "src/assembly/connector_step_problem.hpp"
#include "src/solver/arc_length_problem.hpp"
#include "src/solver/bordered_solver.hpp"
#include "tests/tangent/assembled_system.hpp"

namespace clinch {
namespace {

// Two SPRINGA (k = 1000) from (±1, 0) to the apex (0, 0.5), which is pushed down by 100 λ.
constexpr const char* kTruss =
    "*NODE\n1, -1., 0., 0.\n2, 1., 0., 0.\n3, 0., 0.5, 0.\n"
    "*ELEMENT, TYPE=SPRINGA, ELSET=BARS\n1, 1, 3\n2, 2, 3\n*SPRING, ELSET=BARS\n\n1000.\n"
    "*BOUNDARY\n1, 1, 3\n2, 1, 3\n3, 1, 1\n3, 3, 3\n"
    "*STEP, NLGEOM=YES\n*STATIC, RIKS\n0.1, 1.\n*CLOAD\n3, 2, -100.\n*END STEP\n";

// The load 100 λ that holds the apex at its descent w: P = 2k(L₀ − L)(0.5 − w)/L.
double path_load(double w) {
  const double length0 = std::sqrt(1.25), length = std::sqrt(1.0 + (0.5 - w) * (0.5 - w));
  return 2 * 1000.0 * (length0 - length) * (0.5 - w) / length;
}

// The truss at the start of a Riks increment of arc length `arc`, with its bordered solver.
struct RiksSystem {
  std::unique_ptr<Analysis> analysis;
  std::unique_ptr<ConnectorStepProblem> step;
  std::unique_ptr<ArcLengthProblem> path;
  std::unique_ptr<LinearSolver> solver;
  std::unique_ptr<BorderedSolver> bordered;
  SparseMatrix k;
  Eigen::VectorXd residual, correction;

  // Evaluates the bordered residual and K at the current point.
  void evaluate() { ASSERT_TRUE(path->evaluate(residual, &k).ok); }
  // `count` Newton iterations from the current point.
  void iterate(int count) {
    for (int i = 0; i < count; ++i) {
      evaluate();
      correct();
    }
  }
  // One Newton iteration from the point evaluate() last saw.
  void correct() {
    std::string message;
    ASSERT_EQ(bordered->factorize(k, &message), LinearStatus::Ok) << message;
    ASSERT_EQ(bordered->solve(-residual, correction, &message), LinearStatus::Ok) << message;
    path->apply_correction(correction);
  }
};

RiksSystem riks_truss(double arc) {
  RiksSystem r;
  r.analysis = analyse(kTruss);
  ConnectorSystem& s = *r.analysis->system;
  r.step = std::make_unique<ConnectorStepProblem>(r.analysis->deck.model, s);
  r.step->begin_step(0, true);
  r.step->use_storage(true);
  r.step->begin_increment(0.0, arc, arc, 0.0);
  r.path = std::make_unique<ArcLengthProblem>(s, *r.step);
  r.path->begin_step();
  r.path->begin_increment(arc);
  r.solver = make_linear_solver(SolverChoice::Automatic, true, true);
  r.bordered = std::make_unique<BorderedSolver>(*r.solver, *r.path);
  std::string message;
  EXPECT_EQ(r.bordered->analyze(r.path->pattern(), &message), LinearStatus::Ok) << message;
  r.k = r.path->pattern();
  r.residual.resize(r.path->size());
  r.correction.resize(r.path->size());
  return r;
}

// From the point reached, a random move of the free DOFs and of λ of size `size` (the prescribed
// ones stay on their targets, as in a run), then the bordered Jacobian there against central
// differences with h = 1e-6. Tolerance as for the connector families
// (test_assembled_tangent.cpp): 1e-5 of the largest entry.
void expect_bordered_jacobian_matches(RiksSystem& r, double size, unsigned seed) {
  ArcLengthProblem& path = *r.path;
  const ConnectorSystem& s = *r.analysis->system;
  const int n = path.size() - 1;
  Eigen::VectorXd steps = Eigen::VectorXd::Constant(path.size(), 1e-6);
  for (int j = 0; j < n; ++j) {
    if (s.is_prescribed(s.equation_of_solved(j))) steps[j] = 0.0;
  }
  Eigen::VectorXd move = size * random_state(path.size(), seed, 1.0);
  for (int j = 0; j < n; ++j) {
    if (steps[j] == 0.0) move[j] = 0.0;
  }
  path.apply_correction(move);
  r.evaluate();
  const Eigen::VectorXd rate = path.load_rate();
  const auto analytic = [&](int row, int column) {
    if (row < n) return column < n ? entry(r.k, row, column) : rate[row];
    return path.constraint_gradient(column);
  };
  const auto perturbed = [&path](int column, double step, Eigen::VectorXd& value) {
    Eigen::VectorXd move = Eigen::VectorXd::Zero(path.size());
    move[column] = step;
    path.apply_correction(move);
    const bool ok = path.evaluate(value, nullptr).ok;
    move[column] = -step;
    path.apply_correction(move);
    return ok;
  };
  JacobianCheckOptions options;
  options.compare_row = [&](int i) { return i == n || steps[i] != 0; };
  const JacobianReport report = check_jacobian(perturbed, path.size(), steps, analytic, options);
  ASSERT_TRUE(report.evaluated()) << report;
  EXPECT_LE(report.max_error, 1e-5 * report.largest_analytic) << report;
  EXPECT_GE(report.compared, 4);
}

// Off the path (a predictor and one correction of an increment of Δl = 0.3, then a random
// move): the bordered Jacobian against central differences.
TEST(ArcLength, BorderedJacobianMatchesFiniteDifferences) {
  RiksSystem r = riks_truss(0.3);
  r.iterate(2);  // the predictor, then one corrector
  expect_bordered_jacobian_matches(r, 0.02, 3u);
}

// Newton on the bordered system from the predictor of an increment that starts at the unloaded
// arch (Δl = 0.3): the iterates converge quadratically in the error
// e = max(r/100, |g|/Δl²) once it is below 1e-2 (each e at most 10 e² of the one before, until
// round-off at 1e-12), and the converged point satisfies the closed form to 1e-10 of the load.
TEST(ArcLength, NewtonConvergesQuadraticallyOntoThePath) {
  const double arc = 0.3;
  RiksSystem r = riks_truss(arc);
  ArcLengthProblem& path = *r.path;
  const int n = path.size() - 1;
  std::vector<double> errors;
  for (int iteration = 0; iteration < 12; ++iteration) {
    r.evaluate();
    IterationNorms norms;
    path.measure(r.residual, nullptr, norms);
    if (iteration > 0) {
      errors.push_back(
          std::max(norms.largest_residual[0] / 100.0, std::abs(r.residual[n]) / (arc * arc)));
      if (errors.back() < 1e-13) break;
    }
    r.correct();
  }
  int asserted = 0;
  for (std::size_t i = 1; i < errors.size(); ++i) {
    if (errors[i - 1] > 1e-2 || errors[i] < 1e-12) continue;
    EXPECT_LE(errors[i], 10.0 * errors[i - 1] * errors[i - 1]) << "iteration " << i;
    ++asserted;
  }
  EXPECT_GE(asserted, 1);
  const ConnectorSystem& s = *r.analysis->system;
  const double w = -s.nodal_value(2, 2);
  EXPECT_GT(path.load_factor(), 0.1);  // it moved along the path
  EXPECT_NEAR(100.0 * path.load_factor(), path_load(w), 1e-10 * 100.0);
}

// The held attempt (docs/riks.md "At a kink") after a converged increment of the truss and two
// failed attempts from it: the only free equation (the apex) is held, the bordered Jacobian
// with the held row matches central differences (as above), and Newton converges onto the path.
TEST(ArcLength, HeldAttemptMatchesFiniteDifferencesAndMeetsThePath) {
  const double arc = 0.1;
  RiksSystem r = riks_truss(arc);
  ArcLengthProblem& path = *r.path;
  const auto converge = [&] {
    for (int iteration = 0; iteration < 12; ++iteration) {
      r.evaluate();
      IterationNorms norms;
      path.measure(r.residual, nullptr, norms);
      if (iteration > 0 && norms.largest_residual[0] < 1e-10 * 100.0 &&
          norms.constraint_violation <= 1.0) {
        return true;
      }
      r.correct();
    }
    return false;
  };
  ASSERT_TRUE(converge());
  r.step->commit();
  path.commit();
  const auto restart = [&] {
    r.step->revert();
    path.begin_increment(arc);
  };
  path.begin_increment(arc);
  r.iterate(3);  // a secant attempt stopped after its predictor and two corrections
  ASSERT_TRUE(path.attempt_failed());  // tried again reversed
  restart();
  EXPECT_TRUE(path.reversing());
  r.iterate(1);
  ASSERT_TRUE(path.attempt_failed());  // tried again held
  restart();
  ASSERT_TRUE(path.holding());
  r.iterate(2);
  expect_bordered_jacobian_matches(r, 0.01, 5u);
  ASSERT_TRUE(converge());
  const double w = -r.analysis->system->nodal_value(2, 2);
  EXPECT_GT(w, 0.0);
  EXPECT_NEAR(100.0 * path.load_factor(), path_load(w), 1e-10 * 100.0);
}

}  // namespace
}  // namespace clinch
