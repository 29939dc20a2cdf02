// libFuzzer target: the page data of `clinch report` (src/report/report_data.*) on any byte
// string, split as
//   <job name>\n<how the run ended>\n<history table>\n%%\n<golden table>
// (an empty golden table: no golden comparison). The job name and the ending may hold any bytes,
// as a file name and a status file can. A crash, a sanitizer report or a hang is a bug, and so is
// data that is not valid JSON (UTF-8) or does not hold the history it was given: every finite
// number exactly, NaN and infinities as the strings "nan", "inf", "-inf".
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "src/output/csv_table.hpp"
#include "src/output/run_log.hpp"
#include "src/output/status_file_reader.hpp"
#include "src/output/table_comparison.hpp"
#include "src/report/report_data.hpp"

namespace {

bool holds(const nlohmann::json& value, double expected) {
  if (std::isnan(expected)) return value == "nan";
  if (std::isinf(expected)) return value == (expected > 0.0 ? "inf" : "-inf");
  return value.is_number() && value.get<double>() == expected;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::size_t job_end = text.find('\n');
  if (job_end == std::string_view::npos) return 0;
  const std::size_t ending_end = text.find('\n', job_end + 1);
  if (ending_end == std::string_view::npos) return 0;
  const std::size_t split = text.find("\n%%\n", ending_end);
  const std::string_view history_text =
      text.substr(ending_end + 1, split == std::string_view::npos ? std::string_view::npos
                                                                  : split - ending_end);
  const std::string_view golden_text =
      split == std::string_view::npos ? std::string_view() : text.substr(split + 4);

  std::string error;
  const std::optional<clinch::CsvTable> history =
      clinch::parse_csv_table("history.csv", history_text, &error);
  if (!history) return 0;
  clinch::ReportInputs inputs;
  inputs.job = std::string(text.substr(0, job_end));
  inputs.history = &*history;
  inputs.max_connectors = 20;
  inputs.study_csv = inputs.job + ".study.csv";
  // An attempt and an iteration per history row, with the row's values as times and norms, so
  // that non-finite numbers reach those fields too.
  clinch::StatusRecord status;
  status.ending = std::string(text.substr(job_end + 1, ending_end - job_end - 1));
  std::vector<clinch::IterationRecord> iterations;
  for (const std::vector<double>& row : history->rows) {
    clinch::IncrementAttempt attempt;
    attempt.total_time = row.front();
    attempt.time_increment = row.back();
    attempt.cut_back = row.size() % 2 == 0;
    status.attempts.push_back(attempt);
    clinch::IterationRecord iteration;
    iteration.residual_norm = row.back();
    iteration.correction_norm = row.front();
    iteration.constraint_violation = row[row.size() / 2];
    iterations.push_back(iteration);
  }
  inputs.status = &status;
  inputs.iterations = &iterations;
  std::optional<clinch::CsvTable> golden;
  std::optional<clinch::TableComparison> comparison;
  if (!golden_text.empty()) {
    golden = clinch::parse_csv_table("golden.csv", golden_text, &error);
    if (golden) comparison = clinch::compare_tables(*history, *golden, inputs.compare_options, &error);
    if (comparison) {
      inputs.golden = &*golden;
      inputs.comparison = &*comparison;
    }
  }

  const std::string json_text = clinch::report_data_text(inputs);
  const nlohmann::json parsed = nlohmann::json::parse(json_text, nullptr, false);
  if (parsed.is_discarded()) std::abort();  // not JSON, or not UTF-8
  const nlohmann::json& table = parsed["history"];
  if (table["columns"].size() != history->columns.size() ||
      table["rows"].size() != history->rows.size()) {
    std::abort();
  }
  for (std::size_t r = 0; r < history->rows.size(); ++r) {
    for (std::size_t c = 0; c < history->columns.size(); ++c) {
      if (!holds(table["rows"][r][c], history->rows[r][c])) std::abort();
    }
  }
  if (parsed["attempts"].size() != status.attempts.size() ||
      parsed["iterations"].size() != iterations.size() ||
      parsed.contains("golden") != (inputs.comparison != nullptr)) {
    std::abort();
  }
  return 0;
}
