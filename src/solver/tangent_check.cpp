#include "src/solver/tangent_check.hpp"

#include <fmt/format.h>

#include <cmath>

namespace clinch {
namespace {

constexpr int kMaxEquations = 3000;  // O(n) residual evaluations: small decks only
constexpr int kReported = 5;
// u_s of behaviors.md §1.4 without a yield force: the check does not look into the behaviours.
constexpr double kMotionScale = 1e-3;

}  // namespace

JacobianReport check_assembled_tangent(NonlinearProblem& problem, const SparseMatrix& k,
                                       const Eigen::VectorXd& steps, bool symmetric_part) {
  const auto residual = [&problem](int column, double step, Eigen::VectorXd& value) {
    Eigen::VectorXd move = Eigen::VectorXd::Zero(problem.size());
    move[column] = step;
    problem.apply_correction(move);
    value.resize(problem.size());
    const bool ok = problem.evaluate(value, nullptr).ok;
    move[column] = -step;
    problem.apply_correction(move);
    return ok;
  };
  JacobianCheckOptions options;
  options.compare_row = [&steps](int i) { return steps[i] != 0; };
  options.symmetric_part = symmetric_part;
  return check_jacobian(
      residual, problem.size(), steps, [&k](int row, int column) { return entry(k, row, column); },
      options);
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
    if (!system.is_prescribed(j)) {
      steps[j] = tangent_check_step(std::abs(system.value(j)), kMotionScale);
    }
  }
  const JacobianReport report = check_assembled_tangent(system, k, steps);
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
