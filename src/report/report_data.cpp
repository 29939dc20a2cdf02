#include "src/report/report_data.hpp"

#include <cmath>

#include "src/output/abaqus_labels.hpp"

namespace clinch {
namespace {

// JSON has no NaN or infinity: those are written as the strings "nan", "inf" and "-inf", which
// report_page.py reads back as numbers (a history row of a run that diverged holds them).
nlohmann::json number(double value) {
  if (std::isfinite(value)) return value;
  if (std::isnan(value)) return "nan";
  return value > 0.0 ? "inf" : "-inf";
}

nlohmann::json table_json(const CsvTable& table) {
  nlohmann::json rows = nlohmann::json::array();
  for (const std::vector<double>& row : table.rows) {
    nlohmann::json values = nlohmann::json::array();
    for (double v : row) values.push_back(number(v));
    rows.push_back(std::move(values));
  }
  nlohmann::json labels = nlohmann::json::array();
  for (const std::string& name : table.columns) {
    const ColumnDescription d = describe_column(name);
    labels.push_back({{"variable", d.variable},
                      {"component", d.component},
                      {"derived", d.derived},
                      {"where", d.where},
                      {"abaqus", d.abaqus_name},
                      {"meaning", d.meaning},
                      {"quantity", quantity_name(d.quantity)}});
  }
  return {{"path", table.path},
          {"columns", table.columns},
          {"labels", std::move(labels)},
          {"rows", std::move(rows)}};
}

const char* verdict_text(ColumnVerdict verdict) {
  switch (verdict) {
    case ColumnVerdict::Pass:
      return "pass";
    case ColumnVerdict::Fail:
      return "fail";
    case ColumnVerdict::Missing:
      return "missing";
  }
  return "";
}

}  // namespace

nlohmann::json report_data(const ReportInputs& in) {
  nlohmann::json data;
  data["job"] = in.job;
  data["max_connectors"] = in.max_connectors;
  data["history"] = table_json(*in.history);
  data["choice"] = {{"elements", in.elements},
                    {"components", in.components},
                    {"variables", in.variables}};
  nlohmann::json attempts = nlohmann::json::array();
  if (in.status != nullptr) {
    for (const IncrementAttempt& a : in.status->attempts) {
      attempts.push_back({{"step", a.step},
                          {"increment", a.increment},
                          {"attempt", a.attempt},
                          {"cut_back", a.cut_back},
                          {"iterations", a.total_iterations},
                          {"total_time", number(a.total_time)},
                          {"time_increment", number(a.time_increment)}});
    }
    data["ending"] = in.status->ending;
    nlohmann::json names = nlohmann::json::object();
    for (const auto& [step, name] : in.status->step_names) names[std::to_string(step)] = name;
    data["step_names"] = std::move(names);
  }
  data["attempts"] = attempts;
  nlohmann::json iterations = nlohmann::json::array();
  if (in.iterations != nullptr) {
    for (const IterationRecord& r : *in.iterations) {
      iterations.push_back({{"step", r.step},
                            {"increment", r.increment},
                            {"attempt", r.attempt},
                            {"iteration", r.iteration},
                            {"residual", number(r.residual_norm)},
                            {"correction", number(r.correction_norm)},
                            {"constraint_violation", number(r.constraint_violation)}});
    }
  }
  data["iterations"] = iterations;
  if (in.golden != nullptr && in.comparison != nullptr) {
    nlohmann::json golden = table_json(*in.golden);
    golden["rtol"] = number(in.compare_options.rtol);
    golden["atol"] = number(in.compare_options.atol);
    nlohmann::json columns = nlohmann::json::array();
    for (const ColumnComparison& c : in.comparison->columns) {
      nlohmann::json column = {{"name", c.name},
                               {"verdict", verdict_text(c.verdict)},
                               {"failed_rows", c.failed_rows},
                               {"compared_rows", c.compared_rows}};
      if (c.has_worst) {
        column["worst"] = {{"total_time", number(c.total_time)},
                           {"result", number(c.result)},
                           {"golden", number(c.golden)},
                           {"difference", number(c.difference)},
                           {"allowed", number(c.allowed)}};
      }
      columns.push_back(column);
    }
    golden["comparison"] = columns;
    golden["problems"] = in.comparison->problems;
    data["golden"] = golden;
  }
  if (in.study_csv) data["study_csv"] = *in.study_csv;
  return data;
}

std::string report_data_text(const ReportInputs& inputs) {
  // Job, path and column names come from file names and decks in any encoding; the bytes that
  // are not UTF-8 become U+FFFD rather than make the writer throw.
  return report_data(inputs).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace clinch
