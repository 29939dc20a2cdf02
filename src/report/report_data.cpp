#include "src/report/report_data.hpp"

namespace clinch {
namespace {

nlohmann::json table_json(const CsvTable& table) {
  return {{"path", table.path}, {"columns", table.columns}, {"rows", table.rows}};
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
  nlohmann::json attempts = nlohmann::json::array();
  if (in.status != nullptr) {
    for (const IncrementAttempt& a : in.status->attempts) {
      attempts.push_back({{"step", a.step},
                          {"increment", a.increment},
                          {"attempt", a.attempt},
                          {"cut_back", a.cut_back},
                          {"iterations", a.total_iterations},
                          {"total_time", a.total_time},
                          {"time_increment", a.time_increment}});
    }
    data["ending"] = in.status->ending;
  }
  data["attempts"] = attempts;
  nlohmann::json iterations = nlohmann::json::array();
  if (in.iterations != nullptr) {
    for (const IterationRecord& r : *in.iterations) {
      iterations.push_back({{"step", r.step},
                            {"increment", r.increment},
                            {"attempt", r.attempt},
                            {"iteration", r.iteration},
                            {"residual", r.residual_norm},
                            {"correction", r.correction_norm},
                            {"constraint_violation", r.constraint_violation}});
    }
  }
  data["iterations"] = iterations;
  if (in.golden != nullptr && in.comparison != nullptr) {
    nlohmann::json golden = table_json(*in.golden);
    golden["rtol"] = in.compare_options.rtol;
    golden["atol"] = in.compare_options.atol;
    nlohmann::json columns = nlohmann::json::array();
    for (const ColumnComparison& c : in.comparison->columns) {
      nlohmann::json column = {{"name", c.name},
                               {"verdict", verdict_text(c.verdict)},
                               {"failed_rows", c.failed_rows},
                               {"compared_rows", c.compared_rows}};
      if (c.has_worst) {
        column["worst"] = {{"total_time", c.total_time},
                           {"result", c.result},
                           {"golden", c.golden},
                           {"difference", c.difference},
                           {"allowed", c.allowed}};
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

}  // namespace clinch
