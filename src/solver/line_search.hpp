// The line search of *CONTROLS, PARAMETERS=LINE SEARCH (keywords.md §16): scales a Newton
// correction d by s so that the residual projected on it, g(s) = dᵀR(x + s d), falls to
// η_ls·|g(0)| or below. Off by default (N_ls = 0); it helps where the residual has kinks that make
// full Newton steps cycle (corners of yield surfaces, stick–slip).
#pragma once

#include <Eigen/Core>

#include "src/model/history_model.hpp"
#include "src/solver/nonlinear_problem.hpp"

namespace clinch {

// Called with the full step applied (the problem at x + d); `residual` holds R(x). Evaluates
// R(x + d) and, while |g(s)| > η_ls·|g(0)|, moves s to the zero of the secant of g, at most N_ls
// times: through (0, g(0)) and (s, g(s)) until a step overshoots (g(s) > 0), then inside the
// bracket where g changes sign (regula falsi, Illinois variant); s is kept within
// [max(f_s·s, s_min), s_max]. The problem is left at the evaluated s with the smallest |g|,
// `residual` = R there, and `direction` is scaled to s·d (the correction the convergence tests
// see).
EvalStatus search_line(NonlinearProblem& problem, Eigen::VectorXd& direction,
                       Eigen::VectorXd& residual, const LineSearchControls& controls);

}  // namespace clinch
