#include "src/solver/frequency_eigensolver.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <Spectra/SymEigsSolver.h>
#include <algorithm>
#include <cmath>
#include <memory>
#include <string_view>

#include "src/linalg/petsc_plugin_loader.hpp"

namespace clinch {
namespace {

// y = C x = Fᵀ (K − σM)⁻¹ F x, for Spectra (its OpType: rows, cols, perform_op).
class ShiftInvertOperator {
 public:
  using Scalar = double;

  ShiftInvertOperator(const LumpedMass& mass, int n, LinearSolver& solver)
      : mass_(mass), n_(n), solver_(&solver) {}

  Eigen::Index rows() const { return static_cast<Eigen::Index>(mass_.factor.size()); }
  Eigen::Index cols() const { return rows(); }

  void perform_op(const double* x_in, double* y_out) const {
    const Eigen::VectorXd solved = solve(spread(x_in));
    for (Eigen::Index j = 0; j < rows(); ++j) {
      double y = 0.0;
      for (const auto& [eq, f] : mass_.factor[static_cast<std::size_t>(j)]) y += f * solved[eq];
      y_out[j] = y;
    }
  }

  // F x over the solved equations.
  Eigen::VectorXd spread(const double* x) const {
    Eigen::VectorXd b = Eigen::VectorXd::Zero(n_);
    for (Eigen::Index j = 0; j < rows(); ++j) {
      for (const auto& [eq, f] : mass_.factor[static_cast<std::size_t>(j)]) b[eq] += f * x[j];
    }
    return b;
  }

  Eigen::VectorXd solve(const Eigen::VectorXd& b) const {
    Eigen::VectorXd x(n_);
    std::string message;
    if (solver_->solve(b, x, &message) != LinearStatus::Ok) {
      // A factorization that succeeded solves; a backend that cannot leaves a NaN that Spectra
      // reports as a failure to converge.
      x.setConstant(std::numeric_limits<double>::quiet_NaN());
    }
    return x;
  }

 private:
  const LumpedMass& mass_;
  int n_;
  LinearSolver* solver_;
};

// The `wanted` eigenpairs of C of largest |ν|: Spectra's Lanczos while fewer than r are wanted,
// a dense eigensolve of C (built by r solves) otherwise.
bool largest_magnitude(const ShiftInvertOperator& op, int wanted, Eigen::VectorXd& nu,
                       Eigen::MatrixXd& z) {
  const auto r = static_cast<int>(op.rows());
  if (wanted < r) {
    const int ncv = std::min(r, std::max(2 * wanted + 1, wanted + 20));
    ShiftInvertOperator copy = op;
    Spectra::SymEigsSolver<ShiftInvertOperator> eigs(copy, wanted, ncv);
    eigs.init();
    eigs.compute(Spectra::SortRule::LargestMagn, 1000, 1e-12);
    if (eigs.info() != Spectra::CompInfo::Successful) return false;
    nu = eigs.eigenvalues();
    z = eigs.eigenvectors();
    return true;
  }
  Eigen::MatrixXd c(r, r);
  Eigen::VectorXd unit = Eigen::VectorXd::Zero(r);
  for (int j = 0; j < r; ++j) {
    unit[j] = 1.0;
    op.perform_op(unit.data(), c.col(j).data());
    unit[j] = 0.0;
  }
  if (!c.allFinite()) return false;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> dense(0.5 * (c + c.transpose()));
  if (dense.info() != Eigen::Success) return false;
  nu = dense.eigenvalues();
  z = dense.eigenvectors();
  return true;
}

// Spectra's side of NearestEigenpairs: λ = σ + 1/ν, φ = (K − σM)⁻¹ F z / ν.
class SpectraNearest final : public NearestEigenpairs {
 public:
  SpectraNearest(const ShiftInvertOperator& op, double shift) : op_(op), shift_(shift) {}
  std::string name() const override {
    return "Spectra Lanczos on the mass-carrying directions, shift-and-invert by the linear solver";
  }
  bool find(int wanted, std::string* error) override {
    if (!largest_magnitude(op_, wanted, nu_, z_)) {
      *error = fmt::format("the Lanczos iteration did not converge for {} eigenvalues", wanted);
      return false;
    }
    finite_.clear();
    // ν = 0 is a direction of C's null space: no finite eigenvalue.
    for (Eigen::Index i = 0; i < nu_.size(); ++i) {
      if (nu_[i] != 0.0) finite_.push_back(static_cast<int>(i));
    }
    return true;
  }
  int found() const override { return static_cast<int>(finite_.size()); }
  double eigenvalue(int i) const override { return shift_ + 1.0 / nu_[finite_[i]]; }
  Eigen::VectorXd vector(int i) const override {
    const Eigen::VectorXd zi = z_.col(finite_[i]);
    return op_.solve(op_.spread(zi.data())) / nu_[finite_[i]];
  }

 private:
  ShiftInvertOperator op_;
  double shift_;
  Eigen::VectorXd nu_;
  Eigen::MatrixXd z_;
  std::vector<int> finite_;
};

}  // namespace

Eigen::VectorXd mass_times(const LumpedMass& mass, const Eigen::VectorXd& x) {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(x.size());
  for (const MassEntry& e : mass.entries) {
    y[e.row] += e.value * x[e.column];
    if (e.row != e.column) y[e.column] += e.value * x[e.row];
  }
  return y;
}

EigenResult solve_frequency_eigenproblem(const SparseMatrix& k, const LumpedMass& mass,
                                         const EigenRequest& request, LinearSolver& solver) {
  EigenResult result;
  const auto r = static_cast<int>(mass.factor.size());
  result.available = r;
  if (r == 0) return result;

  // K − σM in the pattern of K: every entry of the lumped mass lies in a node's block, which the
  // elements on the node fill.
  SparseMatrix shifted = k;
  for (const MassEntry& e : mass.entries) {
    const int begin = shifted.col_ptr[static_cast<std::size_t>(e.column)];
    const int end = shifted.col_ptr[static_cast<std::size_t>(e.column) + 1];
    const auto first = shifted.row_idx.begin() + begin;
    const auto at = std::lower_bound(first, shifted.row_idx.begin() + end, e.row);
    if (at == shifted.row_idx.begin() + end || *at != e.row) {
      result.error = fmt::format("the mass of equation {} lies outside the stiffness pattern",
                                 e.column);
      return result;
    }
    shifted.values[static_cast<std::size_t>(at - shifted.row_idx.begin())] -=
        request.shift * e.value;
  }
  std::string message;
  // A named pivot is described by the caller in the deck's terms rather than the solver's.
  const auto singular = [&]() {
    result.failed_equation = solver.failed_pivot();
    result.error = fmt::format("K − σM cannot be factorized at the shift σ = {:.6g}{}",
                               request.shift,
                               result.failed_equation >= 0 ? "" : ": " + message);
    return result;
  };
  if (std::string_view(solver.name()) == "petsc") {
    if (std::unique_ptr<NearestEigenpairs> slepc = make_slepc_eigensolver(k, mass, request.shift)) {
      result.eigensolver = slepc->name();
      select_nearest(*slepc, request, result);
      // SLEPc's message for a singular K − σM is MUMPS's; the linear solver names the pivot.
      if (result.error.empty() || solver.factorize(shifted, &message) == LinearStatus::Ok) {
        return result;
      }
      return singular();
    }
  }
  if (solver.factorize(shifted, &message) != LinearStatus::Ok) return singular();

  SpectraNearest spectra(ShiftInvertOperator(mass, k.n, solver), request.shift);
  result.eigensolver = spectra.name();
  select_nearest(spectra, request, result);
  return result;
}

void select_nearest(NearestEigenpairs& eigensolver, const EigenRequest& request,
                    EigenResult& result) {
  const int r = result.available;
  int wanted = std::min(r, request.count ? std::max(*request.count, 1) + 2 : 8);
  for (;;) {
    if (std::string error; !eigensolver.find(wanted, &error)) {
      result.error = error;
      return;
    }
    // Every eigenvalue within `reach` of σ is among those found.
    std::vector<std::pair<double, int>> found;
    double reach = 0.0;
    for (int i = 0; i < eigensolver.found(); ++i) {
      const double lambda = eigensolver.eigenvalue(i);
      reach = std::max(reach, std::abs(lambda - request.shift));
      if (lambda >= request.lower && lambda <= request.upper) found.emplace_back(lambda, i);
    }
    std::sort(found.begin(), found.end());
    const bool all = wanted >= r;
    const bool lower_covered = request.shift - reach <= request.lower;
    const bool count_met = request.count && static_cast<int>(found.size()) >= *request.count &&
                           found[static_cast<std::size_t>(*request.count - 1)].first <=
                               request.shift + reach;
    const bool upper_covered = request.shift + reach >= request.upper;
    if (all || (lower_covered && (count_met || upper_covered))) {
      if (request.count && static_cast<int>(found.size()) > *request.count) {
        found.resize(static_cast<std::size_t>(*request.count));
      }
      for (const auto& [lambda, i] : found) result.pairs.push_back({lambda, eigensolver.vector(i)});
      return;
    }
    wanted = std::min(r, 2 * wanted);
  }
}

}  // namespace clinch
