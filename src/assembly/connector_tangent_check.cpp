#include "src/assembly/connector_tangent_check.hpp"

#include <fmt/format.h>

#include <cmath>

#include "src/solver/tangent_check.hpp"

namespace clinch {
namespace {

constexpr int kMaxEquations = 3000;  // O(n) residual evaluations: small decks only
constexpr int kReported = 5;
// u_s of behaviors.md §1.4 without a yield force: the check does not look into the behaviours.
constexpr double kMotionScale = 1e-3;

}  // namespace

std::string check_tangent(ConnectorSystem& system, int step, int increment) {
  const int n = system.size();
  if (n > kMaxEquations) {
    return fmt::format("tangent check skipped at step {} increment {}: {} equations (limit {})",
                       step, increment, n, kMaxEquations);
  }
  // The whole matrix, prescribed DOFs included: without the increment's conditions a prescribed
  // row and column hold the elements' stiffness instead of the identity (loads are constant and
  // do not change the Jacobian). A deck driven by prescribed motions is then checked too.
  const ConnectorSystem::Snapshot before = system.snapshot();
  system.conditions().clear();
  SparseMatrix k = system.pattern();
  Eigen::VectorXd r0(n);
  JacobianReport report;
  const bool evaluated = system.evaluate(r0, &k).ok;
  if (evaluated) {
    // Central differences with a step relative to each DOF's magnitude (behaviors.md §1.4).
    Eigen::VectorXd steps(n);
    for (int j = 0; j < n; ++j) {
      steps[j] = tangent_check_step(std::abs(system.value(system.equation_of_solved(j))),
                                    kMotionScale);
    }
    report = check_assembled_tangent(system, k, steps);
  }
  // The differences moved the state and cleared the conditions (the prescribed predictor with
  // them): the increment goes on from exactly where it was.
  system.restore(before);
  if (!evaluated) return "tangent check skipped: the state cannot be evaluated";
  if (!report.evaluated()) {
    return fmt::format("tangent check at step {} increment {}: {}", step, increment,
                       report.summary());
  }
  const std::size_t dependent = system.plan().dependents.dofs.size();
  return fmt::format(
             "tangent check at step {} increment {}: {} equations{}, {} entries compared, "
             "largest entry {:.6g}, {} storage",
             step, increment, n,
             dependent ? fmt::format(" (and {} eliminated by constraints)", dependent)
                       : std::string(),
             report.compared, report.largest_analytic,
             k.symmetric_upper ? "symmetric-upper" : "full") +
         report.table(kReported, "K");
}

}  // namespace clinch
