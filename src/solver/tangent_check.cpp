#include "src/solver/tangent_check.hpp"

#include <fmt/format.h>

#include <cmath>

namespace clinch {
namespace {

constexpr int kMaxEquations = 3000;  // O(n) residual evaluations: small decks only
constexpr int kReported = 5;
constexpr double kMotionScale = 1e-3;  // u_s of behaviors.md §1.4 when a deck gives none

}  // namespace

PerturbedFunction residual_perturbation(NonlinearProblem& problem) {
  return [&problem](int column, double step, Eigen::VectorXd& residual) {
    Eigen::VectorXd move = Eigen::VectorXd::Zero(problem.size());
    move[column] = step;
    problem.apply_correction(move);
    residual.resize(problem.size());
    const bool ok = problem.evaluate(residual, nullptr).ok;
    move[column] = -step;
    problem.apply_correction(move);
    return ok;
  };
}

std::string check_tangent(ConnectorSystem& system, int step, int increment) {
  const int n = system.size();
  if (n > kMaxEquations) {
    return fmt::format("tangent check skipped at step {} increment {}: {} equations (limit {})",
                       step, increment, n, kMaxEquations);
  }
  SparseMatrix k = system.pattern();
  Eigen::VectorXd r0(n);
  if (!system.evaluate(r0, &k).ok) return "tangent check skipped: the state cannot be evaluated";
  // Central differences with a step relative to each free DOF's magnitude (behaviors.md §1.4).
  Eigen::VectorXd steps = Eigen::VectorXd::Zero(n);
  for (int j = 0; j < n; ++j) {
    if (!system.is_prescribed(j))
      steps[j] = tangent_check_step(std::abs(system.value(j)), kMotionScale);
  }
  JacobianCheckOptions options;
  options.compare_row = [&system](int i) { return !system.is_prescribed(i); };
  const JacobianReport report = check_jacobian(
      residual_perturbation(system), n, steps,
      [&k](int row, int column) { return entry(k, row, column); }, options);
  system.evaluate(r0, nullptr);
  if (!report.evaluated()) {
    return fmt::format("tangent check at step {} increment {}: {}", step, increment,
                       report.summary());
  }
  return fmt::format(
             "tangent check at step {} increment {}: {} equations, largest entry {:.6g}, {} "
             "storage",
             step, increment, n, report.largest_analytic,
             k.symmetric_upper ? "symmetric-upper" : "full") +
         report.table(kReported, "K");
}

}  // namespace clinch
