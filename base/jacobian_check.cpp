#include "base/jacobian_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <utility>

namespace clinch {
namespace {

constexpr int kPrintedEntries = 40;

// NaN on either side counts as an infinite error, so that it fails every tolerance and sorts
// first.
double entry_error(double analytic, double numeric) {
  const double error = std::abs(analytic - numeric);
  return std::isnan(error) ? std::numeric_limits<double>::infinity() : error;
}

void compare_column(int column, const Eigen::VectorXd& numeric, const AnalyticEntry& analytic,
                    const std::function<bool(int)>& row_compared, JacobianReport& report) {
  for (int i = 0; i < numeric.size(); ++i) {
    if (!row_compared(i)) continue;
    const double a = analytic(i, column);
    const double n = numeric[i];
    const double error = entry_error(a, n);
    ++report.compared;
    report.max_error = std::max(report.max_error, error);
    report.largest_analytic = std::max(report.largest_analytic, std::abs(a));
    report.largest_numeric = std::max(report.largest_numeric, std::abs(n));
    if (a != 0 || n != 0) report.entries.push_back({i, column, a, n, error});
  }
}

}  // namespace

PerturbedFunction perturb_additively(VectorFunction f, Eigen::VectorXd x) {
  return [f = std::move(f), x = std::move(x)](int column, double step, Eigen::VectorXd& value) {
    Eigen::VectorXd moved = x;
    moved[column] += step;
    return f(moved, value);
  };
}

double tangent_check_step(double magnitude, double motion_scale) {
  return 1e-6 * std::max(magnitude, motion_scale);
}

bool JacobianReport::passes(double rel_tol, double abs_tol) const {
  return evaluated() && max_error <= rel_tol * largest_analytic + abs_tol;
}

bool JacobianReport::meets_tangent_rule(double k_s) const { return passes(1e-5, 1e-8 * k_s); }

std::string JacobianReport::summary() const {
  if (!evaluated()) {
    return fmt::format("the function could not be evaluated at step {:.3g} along column {}",
                       failed_step, failed_column);
  }
  std::string where;
  if (!entries.empty() && entries.front().error > 0) {
    where = fmt::format(" at [{},{}]", entries.front().row, entries.front().column);
  }
  return fmt::format(
      "{} x {} Jacobian, {} entries compared: max |D - D_fd| = {:.3g}{}, max |D| = {:.6g}, "
      "max |D_fd| = {:.6g}",
      rows, columns, compared, max_error, where, largest_analytic, largest_numeric);
}

std::string JacobianReport::table(int max_entries, std::string_view name) const {
  std::string out;
  for (const JacobianEntry& e : entries) {
    if (max_entries-- <= 0 || e.error == 0) break;
    out += fmt::format(
        "\n  {}[{},{}] = {:.9g}, finite difference {:.9g}, |difference| {:.3g} ({:.3g} of the "
        "largest entry)",
        name, e.row, e.column, e.analytic, e.numeric, e.error,
        largest_analytic > 0 ? e.error / largest_analytic : 0.0);
  }
  return out;
}

std::ostream& operator<<(std::ostream& os, const JacobianReport& report) {
  return os << report.summary() << report.table(kPrintedEntries);
}

JacobianReport check_jacobian(const PerturbedFunction& f, int rows, const Eigen::VectorXd& steps,
                              const AnalyticEntry& analytic, const JacobianCheckOptions& options) {
  JacobianReport report;
  report.rows = rows;
  report.columns = static_cast<int>(steps.size());
  if (options.symmetric_part && rows != report.columns) {
    throw std::invalid_argument(
        fmt::format("symmetric part of a {} x {} Jacobian", rows, report.columns));
  }
  const auto row_compared = [&](int i) {
    if (options.compare_row && !options.compare_row(i)) return false;
    return !options.symmetric_part || steps[i] != 0;
  };
  Eigen::MatrixXd differenced;  // the whole of D_fd, for its symmetric part
  if (options.symmetric_part) differenced.setZero(rows, report.columns);
  Eigen::VectorXd plus, minus, numeric;
  for (int j = 0; j < report.columns; ++j) {
    const double h = steps[j];
    if (h == 0) continue;
    for (auto [step, value] : {std::pair{h, &plus}, std::pair{-h, &minus}}) {
      if (!f(j, step, *value)) {
        report.failed_column = j;
        report.failed_step = step;
        return report;
      }
      if (value->size() != rows) {
        throw std::invalid_argument(
            fmt::format("the function returned {} values, {} expected", value->size(), rows));
      }
    }
    numeric = (plus - minus) / (2 * h);
    if (options.symmetric_part) {
      differenced.col(j) = numeric;
    } else {
      compare_column(j, numeric, analytic, row_compared, report);
    }
  }
  if (options.symmetric_part) {
    for (int j = 0; j < report.columns; ++j) {
      if (steps[j] == 0) continue;
      numeric = 0.5 * (differenced.col(j) + differenced.row(j).transpose());
      compare_column(j, numeric, analytic, row_compared, report);
    }
  }
  std::sort(report.entries.begin(), report.entries.end(),
            [](const JacobianEntry& a, const JacobianEntry& b) {
              if (a.error != b.error) return a.error > b.error;
              return std::pair(a.column, a.row) < std::pair(b.column, b.row);
            });
  return report;
}

JacobianReport check_jacobian(const PerturbedFunction& f, const Eigen::VectorXd& steps,
                              const Eigen::Ref<const Eigen::MatrixXd>& analytic,
                              const JacobianCheckOptions& options) {
  if (analytic.cols() != steps.size()) {
    throw std::invalid_argument(
        fmt::format("{} steps for a Jacobian of {} columns", steps.size(), analytic.cols()));
  }
  return check_jacobian(
      f, static_cast<int>(analytic.rows()), steps,
      [&analytic](int row, int column) { return analytic(row, column); }, options);
}

}  // namespace clinch
