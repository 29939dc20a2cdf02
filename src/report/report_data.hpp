// The data of a `clinch report` page as one JSON document for report_page.py: the history table,
// the increment attempts of the status file, the Newton iterations of the log, and the golden
// table with the comparison of each of its columns (tolerance and worst deviation, computed by
// the same code as `clinch compare`). A study table is passed to report_page.py by its path on
// the command line, which keeps a file name that is not UTF-8 exact.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "src/output/csv_table.hpp"
#include "src/output/run_log.hpp"
#include "src/output/status_file_reader.hpp"
#include "src/output/table_comparison.hpp"

namespace clinch {

struct ReportInputs {
  std::string job;
  const CsvTable* history = nullptr;
  const StatusRecord* status = nullptr;                      // null when the run left no .sta
  const std::vector<IterationRecord>* iterations = nullptr;  // null when it left no .log
  const CsvTable* golden = nullptr;
  const TableComparison* comparison = nullptr;  // with golden
  CompareOptions compare_options;
  std::optional<std::string> study_csv;
  int max_connectors = 0;  // connectors (and nodes) drawn when none is chosen
  // --elements, --components, --variables: what the user chose to see (empty: the default).
  std::vector<std::string> elements, variables;
  std::vector<int> components;
};

// Every history column is described (src/output/abaqus_labels.hpp: its Abaqus name, meaning and
// quantity), so that the page names columns as Abaqus/Viewer does without a table of its own.
// Numbers that are not finite are the strings "nan", "inf" and "-inf".
nlohmann::json report_data(const ReportInputs& inputs);

// report_data() as JSON text, valid UTF-8 whatever the names hold: bytes that are not UTF-8 are
// replaced by U+FFFD.
std::string report_data_text(const ReportInputs& inputs);

}  // namespace clinch
