#include "src/solver/tangent_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace clinch {
namespace {

constexpr int kMaxEquations = 3000;  // O(n) residual evaluations: small decks only
constexpr int kReported = 5;

struct Entry {
  int row, column;
  double analytic, numeric, error;
};

double stored_entry(const SparseMatrix& k, int row, int column) {
  if (row > column) std::swap(row, column);
  for (int p = k.col_ptr[static_cast<std::size_t>(column)];
       p < k.col_ptr[static_cast<std::size_t>(column) + 1]; ++p) {
    if (k.row_idx[static_cast<std::size_t>(p)] == row) return k.values[static_cast<std::size_t>(p)];
  }
  return 0.0;
}

}  // namespace

std::string check_tangent(ConnectorSystem& system, int step, int increment) {
  const int n = system.size();
  if (n > kMaxEquations) {
    return fmt::format("tangent check skipped at step {} increment {}: {} equations (limit {})",
                       step, increment, n, kMaxEquations);
  }
  SparseMatrix k = system.pattern();
  Eigen::VectorXd r0(n), plus(n), minus(n), step_vector = Eigen::VectorXd::Zero(n);
  if (!system.evaluate(r0, &k).ok) return "tangent check skipped: the state cannot be evaluated";
  std::vector<Entry> entries;
  double largest = 0;
  for (int j = 0; j < n; ++j) {
    if (system.is_prescribed(j)) continue;
    // Central differences with a step relative to the DOF's magnitude (behaviors.md §1.4).
    const double h = 1e-6 * std::max(1e-3, std::abs(system.value(j)));
    step_vector[j] = h;
    system.apply_correction(step_vector);
    system.evaluate(plus, nullptr);
    step_vector[j] = -2 * h;
    system.apply_correction(step_vector);
    system.evaluate(minus, nullptr);
    step_vector[j] = h;
    system.apply_correction(step_vector);
    step_vector[j] = 0;
    for (int i = 0; i < n; ++i) {
      if (system.is_prescribed(i)) continue;
      const double numeric = (plus[i] - minus[i]) / (2 * h);
      const double analytic = stored_entry(k, i, j);
      largest = std::max(largest, std::abs(analytic));
      const double error = std::abs(analytic - numeric);
      if (error > 0) entries.push_back({i, j, analytic, numeric, error});
    }
  }
  system.evaluate(r0, nullptr);
  std::sort(entries.begin(), entries.end(),
            [](const Entry& a, const Entry& b) { return a.error > b.error; });
  std::string report = fmt::format(
      "tangent check at step {} increment {}: {} equations, largest entry {:.6g}", step, increment,
      n, largest);
  for (int e = 0; e < std::min<int>(kReported, static_cast<int>(entries.size())); ++e) {
    const Entry& x = entries[static_cast<std::size_t>(e)];
    report += fmt::format("\n  K[{},{}] = {:.9g}, finite difference {:.9g}, |difference| {:.3g} ({:.3g} "
                          "of the largest entry)",
                          x.row, x.column, x.analytic, x.numeric, x.error,
                          largest > 0 ? x.error / largest : 0.0);
  }
  return report;
}

}  // namespace clinch
