// Newton on a problem of one unknown, for the tests of Newton's own strategies (line search,
// cycles): residual and correction tolerances of 1e-12 against q̄ = 1 (ε_l too, so that the
// linear-increment test does not accept a residual of 1e-8), a dense solver, and room
// for 30 iterations without the divergence check, so that only the strategy decides.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "src/linalg/linear_solver.hpp"
#include "src/solver/newton.hpp"

namespace clinch {

// A NonlinearProblem of one unknown: its 1×1 pattern (the tangent is values[0]).
class OneUnknownProblem : public NonlinearProblem {
 public:
  OneUnknownProblem() {
    pattern_.n = 1;
    pattern_.col_ptr = {0, 1};
    pattern_.row_idx = {0};
    pattern_.values = {0.0};
    pattern_.symmetric_upper = true;
  }
  int size() const override { return 1; }
  const SparseMatrix& pattern() const override { return pattern_; }

 private:
  SparseMatrix pattern_;
};

inline NewtonReport solve_one_unknown(NonlinearProblem& p, NewtonOptions options) {
  Controls controls;
  controls.translation.residual = 1e-12;
  controls.translation.correction = 1e-12;
  controls.translation.linear_residual = 1e-12;
  ConvergenceCriteria criteria(controls);
  auto solver = make_linear_solver(SolverChoice::Dense, true, false);
  std::string message;
  EXPECT_EQ(solver->analyze(p.pattern(), &message), LinearStatus::Ok) << message;
  options.max_iterations = 30;
  options.divergence_check_from = 30;
  return solve_increment(p, *solver, criteria, options);
}

}  // namespace clinch
