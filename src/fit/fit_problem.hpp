// The least-squares problem of a fit, solved by Ceres Solver (docs/fit.md, docs/decisions.md
// "clinch fit: Ceres Solver"): one residual block per measured point, all on the one parameter
// block of the varied values, so that a robust loss acts on each point; bounds on the values; a
// trust-region method (Levenberg–Marquardt, or dogleg) with the Jacobian of RunEvaluator. A
// point whose runs fail is an invalid step to Ceres, which shrinks its trust region and steps
// back.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "src/fit/run_evaluator.hpp"

namespace clinch {

enum class FitLoss { Squared, Huber, Cauchy, SoftL1 };
enum class FitMethod { LevenbergMarquardt, Dogleg };

struct FitSettings {
  FitLoss loss = FitLoss::Squared;
  double loss_scale = 1.0;  // in units of the scaled residual
  FitMethod method = FitMethod::LevenbergMarquardt;
  int max_iterations = 50;
  // Called after each iteration with its number, cost and whether the step was taken.
  std::function<void(int iteration, double cost, bool step_taken)> on_iteration;
  std::function<bool()> stopped;  // ends the fit (not converged) when it returns true
};

struct FitOutcome {
  std::vector<double> values;
  bool converged = false;
  std::string termination;  // Ceres's message
  int iterations = 0;
  double initial_cost = 0.0, final_cost = 0.0;  // ½Σρ(r²)
};

// The weight of each residual under the settings' loss at the optimum, ρ'(r²) (1 without a
// loss): the weights of the least-squares problem that has the same optimum, for the standard
// errors of a robust fit (docs/fit.md "Standard errors").
Eigen::VectorXd loss_weights(const FitSettings& settings, const Eigen::VectorXd& residuals);

// Minimises from `initial` within [lower, upper] (±inf where unbounded).
FitOutcome solve_fit(RunEvaluator& evaluator, const std::vector<double>& initial,
                     const std::vector<double>& lower, const std::vector<double>& upper,
                     const FitSettings& settings);

}  // namespace clinch
