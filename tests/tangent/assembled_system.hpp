// Test support for the assembled system of `clinch run`: a deck read and planned into a
// ConnectorSystem, its tangent against central differences of its residual, and Newton solved to
// round-off with a check of quadratic convergence (ARCHITECTURE.md testing habits 1 and 3).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "parser/deck_reader.hpp"
#include "src/assembly/analysis_plan.hpp"
#include "src/assembly/connector_system.hpp"
#include "src/linalg/linear_solver.hpp"
#include "src/solver/newton.hpp"
#include "src/solver/tangent_check.hpp"
#include "tests/unit/checked_deck.hpp"

namespace clinch {

struct Analysis {
  CheckedDeck deck;
  std::optional<AnalysisPlan> plan;
  std::unique_ptr<ConnectorSystem> system;
};

// `edit` changes the read model before it is planned (constraints a test builds by hand).
inline std::unique_ptr<Analysis> analyse(const std::string& text,
                                         const std::function<void(Model&)>& edit = {}) {
  auto a = std::make_unique<Analysis>();
  read_deck_text("deck.inp", text, a->deck.sources, a->deck.model, a->deck.sink);
  EXPECT_FALSE(a->deck.sink.has_errors()) << a->deck.dump();
  if (edit) edit(a->deck.model);
  std::string error;
  a->plan = build_analysis_plan(a->deck.model, &error);
  EXPECT_TRUE(a->plan) << error;
  if (a->plan) a->system = std::make_unique<ConnectorSystem>(a->deck.model, *a->plan);
  return a;
}

// The tangent at the current state against central differences of the residual, with step
// `step_of(j)` for equation j (prescribed equations are left out; the dependent ones are not
// solved for); `largest` receives the largest stored entry of the tangent.
inline JacobianReport tangent_against_differences(ConnectorSystem& s,
                                                  const std::function<double(int)>& step_of,
                                                  bool symmetric_part, double& largest) {
  SparseMatrix k = s.pattern();
  Eigen::VectorXd r(s.size());
  largest = 0;
  if (!s.evaluate(r, &k).ok) return {};
  for (double v : k.values) largest = std::max(largest, std::abs(v));
  Eigen::VectorXd steps = Eigen::VectorXd::Zero(s.size());
  for (int j = 0; j < s.size(); ++j) {
    const int equation = s.equation_of_solved(j);
    if (!s.is_prescribed(equation)) steps[j] = step_of(equation);
  }
  return check_assembled_tangent(s, k, steps, symmetric_part);
}

// A state of `size` values drawn uniformly from [−amplitude, amplitude] (the same for a seed).
inline Eigen::VectorXd random_state(int size, unsigned seed, double amplitude) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  Eigen::VectorXd state(size);
  for (int i = 0; i < size; ++i) state[i] = u(rng);
  return state;
}

// A dynamic increment of dt on `s` (full storage, node 0 held in translation): the step's start
// with its initial accelerations, then a random trial state of the free solved DOFs (values in
// ±0.05, the same for a seed), for the dynamic tangent checks.
inline void start_dynamic_trial(ConnectorSystem& s, const AnalysisPlan& plan, bool nlgeom,
                                const DynamicProcedure& procedure, double dt, unsigned seed) {
  s.set_nlgeom(nlgeom);
  s.use_storage(false);  // NLGEOM dynamic terms (dashpots, rigid arms) are unsymmetric
  for (int dof = 1; dof <= 3; ++dof) s.conditions().prescribe(plan.dofs.equation(0, dof), 0);
  s.start_dynamic_step(true);
  s.set_integration(&procedure, dt);
  s.start_increment(0.0);
  Eigen::VectorXd state = random_state(s.size(), seed, 0.05);
  for (int i = 0; i < s.size(); ++i) {
    if (s.is_prescribed(s.equation_of_solved(i))) state[i] = 0;
  }
  s.apply_correction(state);
}

// Newton on the current increment with tolerances far below the defaults, so that it iterates
// down to round-off.
inline NewtonReport solve_tightly(ConnectorSystem& s) {
  Controls tight;
  tight.translation.residual = 1e-13;
  tight.translation.correction = 1e-13;
  tight.rotation.residual = 1e-13;
  tight.rotation.correction = 1e-13;
  ConvergenceCriteria criteria(tight);
  auto solver = make_linear_solver(SolverChoice::Automatic, s.symmetric_storage(), true);
  std::string message;
  EXPECT_EQ(solver->analyze(s.pattern(), &message), LinearStatus::Ok) << message;
  return solve_increment(s, *solver, criteria, NewtonOptions{});
}

// Each residual is at most C times the square of the previous one once the iterates are close
// (C = 1 in the deck's units is generous), skipping the pre-asymptotic iterations (r > 1) and
// round-off (r < `round_off`). `field` 0: forces, 1: moments.
inline void expect_quadratic_convergence(const NewtonReport& report, int field,
                                         double round_off = 1e-9) {
  std::vector<double> r;
  for (const IterationNorms& n : report.iterations) r.push_back(n.largest_residual[field]);
  ASSERT_GE(r.size(), 3u);
  int asserted = 0;
  for (std::size_t i = 1; i < r.size(); ++i) {
    if (r[i - 1] > 1.0 || r[i] < round_off) continue;
    EXPECT_LE(r[i], 1.0 * r[i - 1] * r[i - 1]) << "iteration " << i;
    ++asserted;
  }
  EXPECT_GE(asserted, 1);
}

}  // namespace clinch
