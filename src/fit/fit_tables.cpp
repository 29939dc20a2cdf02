#include "src/fit/fit_tables.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "src/output/csv_table.hpp"

namespace clinch {
namespace {

// Shortest round trip; an empty field where there is no number (no bound, no standard error).
std::string number_field(double value) {
  return std::isfinite(value) ? fmt::format("{}", value) : std::string();
}

bool finish(std::ofstream& out, const std::string& path, std::string* error) {
  out.close();
  if (!out) *error = fmt::format("cannot write '{}'", path);
  return static_cast<bool>(out);
}

}  // namespace

bool write_parameter_table(const std::string& path, const std::vector<FittedParameter>& parameters,
                           const FitStatistics& statistics, std::string* error) {
  std::ofstream out(path);
  out << "parameter,initial,fitted,standard_error,lower,upper,determined";
  for (const FittedParameter& p : parameters) out << "," << csv_field("correlation_" + p.name);
  out << "\n";
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const FittedParameter& p = parameters[i];
    const bool determined =
        std::find(statistics.undetermined.begin(), statistics.undetermined.end(), i) ==
        statistics.undetermined.end();
    out << csv_field(p.name) << "," << number_field(p.initial) << "," << number_field(p.fitted)
        << "," << number_field(statistics.standard_errors[i]) << "," << number_field(p.lower) << ","
        << number_field(p.upper) << "," << (determined ? 1 : 0);
    for (std::size_t j = 0; j < parameters.size(); ++j) {
      out << ","
          << number_field(statistics.correlation(static_cast<Eigen::Index>(i),
                                                 static_cast<Eigen::Index>(j)));
    }
    out << "\n";
  }
  return finish(out, path, error);
}

bool write_curves_table(const std::string& path, const std::vector<CurvePair>& curves,
                        std::string* error) {
  std::ofstream out(path);
  out << kFitCurvesHeader << "\n";
  for (const CurvePair& c : curves) {
    const CsvTable& t = c.data->table;
    std::size_t i = 0;
    for (const std::vector<double>& row : t.rows) {
      for (const MeasuredColumn& column : c.data->columns) {
        out << csv_field(t.path) << "," << csv_field(t.columns[column.index]) << ","
            << csv_field(t.columns[c.data->abscissa]) << "," << number_field(row[c.data->abscissa])
            << "," << number_field(row[column.index]) << ","
            << (c.initial.empty() ? std::string() : number_field(c.initial[i])) << ","
            << (c.fitted.empty() ? std::string() : number_field(c.fitted[i])) << "\n";
        ++i;
      }
    }
  }
  return finish(out, path, error);
}

}  // namespace clinch
