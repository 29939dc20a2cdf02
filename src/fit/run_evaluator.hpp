// The residuals of a fit as functions of the varied parameters (docs/fit.md "How a fit runs"):
// each evaluation writes a deck copy per rig with the parameter values and runs it as a child
// `clinch run` (src/study/ladder_runner.hpp), several at once; the Jacobian comes from forward
// differences over whole runs, the perturbed points run together with the point itself (with
// more than one job, also for a point whose residuals alone are asked for). Results are kept per
// point, so that the many residual blocks of one Ceres evaluation cost one batch of runs, and a
// point that failed is not run again.
#pragma once

#include <Eigen/Dense>
#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "src/fit/measured_curves.hpp"
#include "src/fit/parameter_deck.hpp"
#include "src/output/csv_table.hpp"

namespace clinch {

// One test rig: a deck and the measured curves its run is compared with.
struct FitRig {
  std::string deck_name;  // as given, for messages
  std::string job;        // the deck's stem: the run's job name and its directory
  ParameterDeck deck;
  std::vector<const MeasuredCurves*> data;
};

// A point where a run did not complete, for the report.
struct RunFailure {
  std::vector<double> values;
  std::string rig;
  std::string reason;
};

// The relative forward-difference step: small against the parameters' effect, large against the
// round-off of a converged run (about 1e-10 relative), which it turns into a derivative error of
// about 1e-6 relative.
inline constexpr double kDifferenceStep = 1e-4;

class RunEvaluator {
 public:
  struct Options {
    std::string clinch;  // the executable
    std::string work_dir;
    int jobs = 1;
    std::function<int()> stop_signal;  // as LadderOptions::stop_signal
  };

  // `typical` gives each parameter's size (> 0), for the difference step where its value is 0
  // and for the scaling of the problem; lower/upper keep the perturbed points inside the bounds.
  RunEvaluator(std::vector<FitRig> rigs, Options options, std::vector<double> typical,
               std::vector<double> lower, std::vector<double> upper);

  // The scaled residuals at x, or null when a run failed there.
  const Eigen::VectorXd* residuals(const std::vector<double>& x);
  // The Jacobian of the residuals at x (m×n), or null when the runs at x or beside it failed.
  const Eigen::MatrixXd* jacobian(const std::vector<double>& x);

  // Runs every rig at x into <work>/<label>/<job>/ and returns their history tables (nullopt for
  // a rig whose run failed, the reason in failures()).
  std::vector<std::optional<CsvTable>> run_tables(const std::vector<double>& x,
                                                  const std::string& label);

  std::size_t residual_count() const;
  const std::vector<double>& typical() const { return typical_; }
  const std::vector<FitRig>& rigs() const { return rigs_; }
  int run_count() const { return runs_; }
  const std::vector<RunFailure>& failures() const { return failures_; }
  bool stopped() const { return stopped_; }
  // Set when a completed run's table could not be compared with the data (a column missing, a
  // measured point outside the run): not a failure of the parameters but of the input.
  const std::string& input_error() const { return input_error_; }

 private:
  // Runs the rigs at each point (into <work>/<labels[p]>) and returns the residuals per point.
  std::vector<std::optional<Eigen::VectorXd>> evaluate(
      const std::vector<std::vector<double>>& points, const std::vector<std::string>& labels,
      std::vector<std::vector<std::optional<CsvTable>>>* tables = nullptr);

  std::vector<FitRig> rigs_;
  Options options_;
  std::vector<double> typical_, lower_, upper_;
  std::map<std::vector<double>, std::optional<Eigen::VectorXd>> residuals_;
  std::map<std::vector<double>, std::optional<Eigen::MatrixXd>> jacobians_;
  std::vector<RunFailure> failures_;
  int runs_ = 0;
  bool stopped_ = false;
  std::string input_error_;
};

}  // namespace clinch
