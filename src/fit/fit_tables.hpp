// The tables a fit writes into its work directory (docs/fit.md "What a fit writes"):
// <job>.fit.csv, one row per varied parameter (initial and fitted value, standard error, bounds,
// whether the data determine it, and its correlation with each parameter), and
// <job>.fit-curves.csv, one row per measured point with the model's value before and after the
// fit, which `clinch report --fit` draws.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "src/fit/fit_statistics.hpp"
#include "src/fit/measured_curves.hpp"

namespace clinch {

struct FittedParameter {
  std::string name;
  double initial = 0.0, fitted = 0.0, lower = 0.0, upper = 0.0;
};

bool write_parameter_table(const std::string& path, const std::vector<FittedParameter>& parameters,
                           const FitStatistics& statistics, std::string* error);

// The model's values at a data file's points (as model_values gives them) before and after.
struct CurvePair {
  const MeasuredCurves* data = nullptr;
  std::vector<double> initial, fitted;  // empty when the run failed
};

// The header of <job>.fit-curves.csv, by which `clinch report --fit` knows one.
inline constexpr const char* kFitCurvesHeader = "data,column,abscissa,x,measured,initial,fitted";

bool write_curves_table(const std::string& path, const std::vector<CurvePair>& curves,
                        std::string* error);

}  // namespace clinch
