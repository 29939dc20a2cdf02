#include "src/solver/frequency_step.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace clinch {
namespace {

double eigenvalue_of(double cycles) {
  const double omega = 2.0 * std::numbers::pi * cycles;
  return omega * omega;
}

// The largest K_ii/M_ii over the equations with mass: the size of the spectrum (1 when the
// stiffness there is zero, a free mass).
double spectrum_scale(const SparseMatrix& k, const LumpedMass& mass) {
  double scale = 0.0;
  for (const MassEntry& e : mass.entries) {
    if (e.row == e.column && e.value > 0) {
      scale = std::max(scale, std::abs(entry(k, e.row, e.row)) / e.value);
    }
  }
  return scale > 0 ? scale : 1.0;
}

// NORMALIZATION=DISPLACEMENT: the largest nodal component is 1; MASS: φᵀMφ = 1. Either way the
// largest nodal component is positive, so that the sign of a mode does not depend on the solver.
void normalize(const FrequencyProcedure& procedure, const LumpedMass& mass,
               const std::vector<std::string>& dof_names, Eigen::VectorXd& phi) {
  Eigen::Index largest = 0;
  for (Eigen::Index i = 0; i < phi.size(); ++i) {
    if (!dof_names[static_cast<std::size_t>(i)].empty() &&
        std::abs(phi[i]) > std::abs(phi[largest])) {
      largest = i;
    }
  }
  double scale = phi[largest] != 0.0 ? 1.0 / phi[largest] : 1.0;
  if (procedure.normalization == FrequencyProcedure::Normalization::Mass) {
    const double generalized = phi.dot(mass_times(mass, phi));
    scale = std::copysign(1.0 / std::sqrt(generalized), scale);
  }
  phi *= scale;
}

}  // namespace

EigenRequest eigen_request(const FrequencyProcedure& procedure, double scale) {
  EigenRequest request;
  const double automatic = -1e-6 * scale;
  request.shift = procedure.shift           ? 4.0 * std::numbers::pi * std::numbers::pi *
                                                  *procedure.shift
                  : procedure.min_frequency ? eigenvalue_of(*procedure.min_frequency)
                                            : automatic;
  request.lower = procedure.min_frequency ? eigenvalue_of(*procedure.min_frequency)
                                          : std::min(automatic, request.shift);
  if (procedure.max_frequency) request.upper = eigenvalue_of(*procedure.max_frequency);
  request.count = procedure.eigenvalues;
  return request;
}

FrequencyStepResult solve_frequency_step(const FrequencyProcedure& procedure,
                                         NonlinearProblem& problem, const FrequencyModel& model,
                                         LinearSolver& solver) {
  FrequencyStepResult result;
  SparseMatrix k = problem.pattern();
  Eigen::VectorXd residual(problem.size());
  if (const EvalStatus status = problem.evaluate(residual, &k); !status.ok) {
    result.error = status.message;
    return result;
  }
  const EigenRequest request = eigen_request(procedure, spectrum_scale(k, model.mass));
  EigenResult eigen = solve_frequency_eigenproblem(k, model.mass, request, solver);
  if (!eigen.error.empty()) {
    result.error = std::move(eigen.error);
    result.failed_equation = eigen.failed_equation;
    return result;
  }
  result.notes.push_back(fmt::format("eigenvalues nearest the shift σ = {:.6g}{}", request.shift,
                                     eigen.eigensolver.empty() ? "" : " by " + eigen.eigensolver));
  int number = 0;
  for (EigenPair& pair : eigen.pairs) {
    normalize(procedure, model.mass, model.dof_names, pair.vector);
    const double generalized = pair.vector.dot(mass_times(model.mass, pair.vector));
    result.modes.push_back({++number, pair.eigenvalue, generalized, std::move(pair.vector)});
  }
  if (eigen.available == 0) {
    result.notes.push_back("no free DOF carries inertia (*MASS, *ROTARY INERTIA): there is no "
                           "mode to extract");
  } else if (procedure.eigenvalues && number < *procedure.eigenvalues) {
    result.notes.push_back(fmt::format(
        "{} eigenvalues requested, {} extracted: {}", *procedure.eigenvalues, number,
        number < eigen.available ? "the others lie outside the frequency range"
                                 : fmt::format("the model has {} directions with inertia",
                                               eigen.available)));
  }
  const auto negative = std::count_if(result.modes.begin(), result.modes.end(),
                                      [&](const ModeRecord& m) { return m.eigenvalue < 0; });
  if (negative > 0) {
    result.notes.push_back(fmt::format(
        "{} negative eigenvalue{} (reported with frequency 0): the base state is unstable or "
        "has a mechanism whose eigenvalue is zero to round-off",
        negative, negative == 1 ? "" : "s"));
  }
  return result;
}

}  // namespace clinch
