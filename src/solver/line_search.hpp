// The line search of *CONTROLS, PARAMETERS=LINE SEARCH (keywords.md §16): scales a Newton
// correction d by s so that the residual projected on it, g(s) = dᵀR(x + s d), falls to
// η_ls·|g(0)| or below. Off by default (N_ls = 0); it helps where the residual has kinks that make
// full Newton steps cycle (corners of yield surfaces, stick–slip).
#pragma once

#include <Eigen/Core>

#include "src/solver/nonlinear_problem.hpp"

namespace clinch {

struct LineSearchOptions {
  int max_iterations = 0;  // N_ls; 0: no line search
  double s_max = 1.0, s_min = 1e-4, f_s = 0.25, eta = 0.10;
};

struct LineSearchResult {
  double step = 1.0;    // s of the returned state
  int evaluations = 0;  // residual evaluations made
  EvalStatus status;
};

// Called with the full step applied (the problem at x + d) and `residual` = R(x + d); `g0` =
// dᵀR(x). Each iteration takes the zero of the secant of g through (0, g0) and (s, g(s)),
// kept within [f_s·s, s_max] and above s_min, and moves the problem there. The problem is left
// at x + s d with `residual` = R there.
LineSearchResult search_line(NonlinearProblem& problem, const Eigen::VectorXd& direction,
                             double g0, Eigen::VectorXd& residual,
                             const LineSearchOptions& options);

}  // namespace clinch
