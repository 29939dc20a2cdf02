#include "src/solver/newton.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "src/solver/forcing_term.hpp"

namespace clinch {
namespace {

// I₀ rule of keywords.md §16: two consecutive increases of the residual from iteration I₀ on.
bool diverging(const std::vector<IterationNorms>& history, int check_from) {
  const std::size_t n = history.size();
  if (static_cast<int>(n) <= check_from || n < 3) return false;
  const auto r = [&](std::size_t i) {
    return std::max(history[i].largest_residual[0], history[i].largest_residual[1]);
  };
  return r(n - 1) > r(n - 2) && r(n - 2) > r(n - 3);
}

// A NaN passes every "r > tolerance" test and an overflow can pass "r ≤ ε·q̄" against an infinite
// flux, so a value that is not finite ends the attempt before the convergence tests see it
// (ARCHITECTURE.md principle 8). Returns false and fills `report` for the entry to blame: the
// first overflow, else the first NaN (often 0·∞ in the substitutions, far from the overflow).
// Over the owned entries of every process of a problem shared by rows, which all agree on it.
bool finite(const NonlinearProblem& problem, const Eigen::VectorXd& values, const char* what,
            NewtonReport& report) {
  const Eigen::Index count = problem.owned_size();
  if (problem.max_over_ranks(values.head(count).allFinite() ? 0.0 : 1.0) == 0.0) return true;
  const double* begin = values.data();
  const double* end = begin + count;
  // The first entry of each kind, by global equation (the largest double when none).
  constexpr double kNone = std::numeric_limits<double>::max();
  const auto first = [&](auto is_kind) {
    const double* at = std::find_if(begin, end, is_kind);
    const double mine =
        at == end ? kNone
                  : static_cast<double>(problem.global_equation(static_cast<int>(at - begin)));
    return -problem.max_over_ranks(-mine);
  };
  const double overflow =
      first([](double v) { return v == std::numeric_limits<double>::infinity(); });
  const double underflow =
      first([](double v) { return v == -std::numeric_limits<double>::infinity(); });
  const double nan = first([](double v) { return std::isnan(v); });
  const double blamed = std::min(overflow, underflow) < kNone ? std::min(overflow, underflow) : nan;
  const double value = blamed == overflow    ? std::numeric_limits<double>::infinity()
                       : blamed == underflow ? -std::numeric_limits<double>::infinity()
                                             : std::numeric_limits<double>::quiet_NaN();
  report.outcome = NewtonOutcome::NonFinite;
  report.failed_equation = static_cast<int>(blamed);
  report.message = fmt::format("the {} is {}", what, value);
  return false;
}

// Newton is back at a state it has visited: the last iteration's residual and correction norms
// equal an earlier one's to round-off. It would cycle for good, as it does between stick and slip
// across a stick band narrower than its steps.
bool revisited(const std::vector<IterationNorms>& history) {
  const auto same = [](double a, double b) { return std::abs(a - b) <= 1e-12 * std::abs(b); };
  const IterationNorms& last = history.back();
  if (!(last.residual_norm > 0 && last.correction_norm > 0)) return false;
  return std::any_of(history.begin(), history.end() - 1, [&](const IterationNorms& earlier) {
    return same(last.residual_norm, earlier.residual_norm) &&
           same(last.correction_norm, earlier.correction_norm);
  });
}

}  // namespace

NewtonReport solve_increment(NonlinearProblem& problem, LinearSolver& solver,
                             const ConvergenceCriteria& criteria, const NewtonOptions& options) {
  NewtonReport report;
  Eigen::VectorXd residual(problem.size()), correction(problem.size());
  SparseMatrix tangent = problem.pattern();
  const Eigen::VectorXd* last_correction = nullptr;
  ForcingTerm forcing;  // how accurately an iterative solver solves each correction
  for (int iteration = 0;; ++iteration) {
    const EvalStatus status = problem.evaluate(residual, &tangent);
    if (!status.ok) {
      report.outcome = NewtonOutcome::EvaluationFailed;
      report.message = status.message;
      return report;
    }
    if (!finite(problem, residual, "residual", report)) return report;
    IterationNorms& norms = report.iterations.emplace_back();
    problem.measure(residual, last_correction, norms);
    const bool predictor = problem.moving_prescribed();
    if (!predictor && criteria.converged(norms, iteration)) {
      report.outcome = NewtonOutcome::Converged;
      return report;
    }
    if (iteration >= options.max_iterations ||
        diverging(report.iterations, options.divergence_check_from)) {
      report.outcome = iteration >= options.max_iterations ? NewtonOutcome::TooManyIterations
                                                           : NewtonOutcome::Diverged;
      if (options.accept_unconverged) report.outcome = NewtonOutcome::Converged;
      report.message = iteration >= options.max_iterations
                           ? fmt::format("no convergence in {} iterations", iteration)
                           : "the residual diverges";
      return report;
    }
    // A factorization of a large model can take long: a stop asked from outside is honoured
    // before it rather than after the whole increment.
    if (options.stop_requested != nullptr && options.stop_requested() != nullptr) {
      report.outcome = NewtonOutcome::Interrupted;
      report.message = "interrupted";
      return report;
    }
    std::string message;
    const auto start = std::chrono::steady_clock::now();
    solver.set_relative_tolerance(forcing.next(iteration, norms.residual_norm));
    LinearStatus linear = solver.factorize(tangent, &message);
    if (linear == LinearStatus::Ok) linear = solver.solve(-residual, correction, &message);
    report.linear_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ++report.factorizations;
    if (linear != LinearStatus::Ok) {
      report.outcome = NewtonOutcome::SolverFailed;
      report.failed_equation = solver.failed_pivot();
      report.message = message;
      return report;
    }
    if (!finite(problem, correction, "correction", report)) return report;
    if (options.break_cycles && revisited(report.iterations)) correction *= 0.5;
    problem.apply_correction(correction);
    if (options.line_search.max_iterations > 0 && !predictor) {
      const EvalStatus searched = search_line(problem, correction, residual, options.line_search);
      if (!searched.ok) {
        report.outcome = NewtonOutcome::EvaluationFailed;
        report.message = searched.message;
        return report;
      }
    }
    last_correction = &correction;
  }
}

}  // namespace clinch
