#include "src/fit/fit_problem.hpp"

#include <ceres/ceres.h>

#include <cmath>
#include <memory>

namespace clinch {
namespace {

// The residual of one measured point; the runs behind it are shared through the evaluator. Ceres
// sees each parameter divided by its typical size, so that values of 1e5 and of 0.3 are alike to
// its step and gradient tolerances, which are absolute.
class PointResidual final : public ceres::CostFunction {
 public:
  PointResidual(RunEvaluator& evaluator, Eigen::Index point, const std::vector<double>& typical)
      : evaluator_(evaluator), point_(point), typical_(typical) {
    set_num_residuals(1);
    mutable_parameter_block_sizes()->push_back(static_cast<int>(typical.size()));
  }

  bool Evaluate(double const* const* values, double* residual, double** jacobians) const override {
    std::vector<double> x(typical_.size());
    for (std::size_t k = 0; k < x.size(); ++k) x[k] = values[0][k] * typical_[k];
    // The Jacobian first: its batch runs the point together with the difference steps.
    if (jacobians != nullptr && jacobians[0] != nullptr) {
      const Eigen::MatrixXd* j = evaluator_.jacobian(x);
      if (j == nullptr) return false;
      for (std::size_t k = 0; k < x.size(); ++k) {
        jacobians[0][k] = (*j)(point_, static_cast<Eigen::Index>(k)) * typical_[k];
      }
    }
    const Eigen::VectorXd* r = evaluator_.residuals(x);
    if (r == nullptr) return false;
    residual[0] = (*r)(point_);
    return true;
  }

 private:
  RunEvaluator& evaluator_;
  Eigen::Index point_;
  const std::vector<double>& typical_;
};

class IterationReport final : public ceres::IterationCallback {
 public:
  explicit IterationReport(const FitSettings& settings) : settings_(settings) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    if (settings_.on_iteration) {
      settings_.on_iteration(summary.iteration, summary.cost, summary.step_is_successful);
    }
    return settings_.stopped && settings_.stopped() ? ceres::SOLVER_ABORT : ceres::SOLVER_CONTINUE;
  }

 private:
  const FitSettings& settings_;
};

std::unique_ptr<ceres::LossFunction> make_loss(FitLoss loss, double scale) {
  switch (loss) {
    case FitLoss::Huber:
      return std::make_unique<ceres::HuberLoss>(scale);
    case FitLoss::Cauchy:
      return std::make_unique<ceres::CauchyLoss>(scale);
    case FitLoss::SoftL1:
      return std::make_unique<ceres::SoftLOneLoss>(scale);
    case FitLoss::Squared:
      break;
  }
  return nullptr;
}

}  // namespace

Eigen::VectorXd loss_weights(const FitSettings& settings, const Eigen::VectorXd& residuals) {
  Eigen::VectorXd weights = Eigen::VectorXd::Ones(residuals.size());
  const std::unique_ptr<ceres::LossFunction> loss = make_loss(settings.loss, settings.loss_scale);
  if (!loss) return weights;
  for (Eigen::Index i = 0; i < residuals.size(); ++i) {
    double rho[3];
    loss->Evaluate(residuals(i) * residuals(i), rho);
    weights(i) = rho[1];
  }
  return weights;
}

FitOutcome solve_fit(RunEvaluator& evaluator, const std::vector<double>& initial,
                     const std::vector<double>& lower, const std::vector<double>& upper,
                     const FitSettings& settings) {
  FitOutcome outcome;
  const std::vector<double>& typical = evaluator.typical();
  const int n = static_cast<int>(initial.size());
  std::vector<double> scaled(initial.size());
  for (int j = 0; j < n; ++j) scaled[j] = initial[j] / typical[j];
  ceres::Problem::Options problem_options;
  // One loss object serves every block.
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  const std::unique_ptr<ceres::LossFunction> loss = make_loss(settings.loss, settings.loss_scale);
  const auto m = static_cast<Eigen::Index>(evaluator.residual_count());
  for (Eigen::Index i = 0; i < m; ++i) {
    problem.AddResidualBlock(new PointResidual(evaluator, i, typical), loss.get(), scaled.data());
  }
  for (int j = 0; j < n; ++j) {
    if (std::isfinite(lower[j])) {
      problem.SetParameterLowerBound(scaled.data(), j, lower[j] / typical[j]);
    }
    if (std::isfinite(upper[j])) {
      problem.SetParameterUpperBound(scaled.data(), j, upper[j] / typical[j]);
    }
  }
  ceres::Solver::Options options;
  options.minimizer_type = ceres::TRUST_REGION;
  options.trust_region_strategy_type =
      settings.method == FitMethod::Dogleg ? ceres::DOGLEG : ceres::LEVENBERG_MARQUARDT;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = settings.max_iterations;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  options.num_threads = 1;  // the runs are what is parallel, in the evaluator
  IterationReport report(settings);
  options.callbacks.push_back(&report);
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  outcome.values.resize(initial.size());
  for (int j = 0; j < n; ++j) outcome.values[j] = scaled[j] * typical[j];
  outcome.converged = summary.termination_type == ceres::CONVERGENCE;
  outcome.termination = summary.message;
  outcome.iterations = static_cast<int>(summary.iterations.size()) - 1;
  outcome.initial_cost = summary.initial_cost;
  outcome.final_cost = summary.final_cost;
  return outcome;
}

}  // namespace clinch
