// Central-difference check of an analytic Jacobian, entry by entry (ARCHITECTURE.md testing
// habits 1 and 2, modelled on Ceres' gradient_checker): every tangent test and
// `clinch run --check-tangent` difference their functions here and read the same report.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace clinch {

// Evaluates the function at the point moved by `step` along coordinate `column` into `value`
// (resized by the callee); false when it cannot be evaluated there. Each call starts from the
// unperturbed point and leaves it as it found it, so that the caller may perturb in its own way
// (the assembled system moves through apply_correction, rotations multiplicatively).
using PerturbedFunction = std::function<bool(int column, double step, Eigen::VectorXd& value)>;

// A plain function of a vector: evaluates at `x` into `value`; false when it cannot.
using VectorFunction = std::function<bool(const Eigen::VectorXd& x, Eigen::VectorXd& value)>;

// Entry (row, column) of the analytic Jacobian, for storage that is not a dense matrix.
using AnalyticEntry = std::function<double(int row, int column)>;

// Additive perturbation of `f` about `x`: the point x + step·e_column.
PerturbedFunction perturb_additively(VectorFunction f, Eigen::VectorXd x);

// behaviors.md §1.4: h = 1e-6·max(|u|, u_s), |u| the motion's magnitude and u_s its scale.
double tangent_check_step(double magnitude, double motion_scale);

struct JacobianCheckOptions {
  // Rows compared; unset: every row.
  std::function<bool(int row)> compare_row;
  // Compare with the symmetric part ½(J + Jᵀ) of the finite-difference Jacobian J (square
  // functions only; a row is then compared only where its column is differenced).
  bool symmetric_part = false;
};

struct JacobianEntry {
  int row = 0, column = 0;
  double analytic = 0, numeric = 0;
  double error = 0;  // |analytic − numeric|; +∞ when either is NaN
};

struct JacobianReport {
  int rows = 0, columns = 0;
  int compared = 0;        // entries compared, including those where both sides are 0
  int failed_column = -1;  // ≥ 0: the function could not be evaluated along this column
  double failed_step = 0;  // and at this step
  double max_error = 0;    // max |D − D_fd| over the compared entries
  double largest_analytic = 0, largest_numeric = 0;  // max |D| and max |D_fd| over them
  // The compared entries where D or D_fd is non-zero (the rest agree exactly), worst first.
  std::vector<JacobianEntry> entries;

  bool evaluated() const { return failed_column < 0; }
  // max|D − D_fd| ≤ rel_tol·max|D| + abs_tol, and every evaluation succeeded.
  bool passes(double rel_tol, double abs_tol) const;
  // The rule of behaviors.md §1.4: rel_tol 1e-5, abs_tol 1e-8·k_s (k_s the largest elastic
  // stiffness).
  bool meets_tangent_rule(double k_s) const;
  // One line: the largest error and where, max|D|, max|D_fd|, the count compared.
  std::string summary() const;
  // The worst `max_entries` entries with a non-zero error, one line each, each line starting
  // with a newline: "  D[i,j] = a, finite difference n, |difference| e (r of the largest entry)"
  // with `name` for D.
  std::string table(int max_entries, std::string_view name = "D") const;
};

// Summary and the worst 40 entries (a 6 × 6 in full), for test failure messages.
std::ostream& operator<<(std::ostream& os, const JacobianReport& report);

// Central differences D_fd[:, j] = (f(x + h_j e_j) − f(x − h_j e_j))/(2 h_j) for every column j
// with h_j = steps[j] ≠ 0 (a zero step leaves the column out), compared with `analytic`, a
// `rows` × steps.size() matrix. Stops at the first evaluation that fails.
JacobianReport check_jacobian(const PerturbedFunction& f, int rows, const Eigen::VectorXd& steps,
                              const AnalyticEntry& analytic,
                              const JacobianCheckOptions& options = {});
JacobianReport check_jacobian(const PerturbedFunction& f, const Eigen::VectorXd& steps,
                              const Eigen::Ref<const Eigen::MatrixXd>& analytic,
                              const JacobianCheckOptions& options = {});

}  // namespace clinch
