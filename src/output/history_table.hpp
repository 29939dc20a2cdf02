// The history table `<job>.history.csv` (cli-contract.md "History table"): one header row, then
// one row per converged increment, written and flushed as the step driver reports it so that a
// run that stops early keeps every converged increment.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "src/output/output_file.hpp"

namespace clinch {

class HistoryTable {
 public:
  // The four key columns that open every history table (cli-contract.md).
  static constexpr const char* kKeyColumns[] = {"step", "increment", "step_time", "total_time"};

  // Creates (truncates) `path` and writes the header: the key columns, then `columns`. On failure
  // returns false and sets `error` (an I/O error: the caller exits with 3).
  bool open(const std::filesystem::path& path, std::vector<std::string> columns,
            std::string* error);

  // Appends one row; `values` holds one value per column given to open(). Numbers are written in
  // shortest round-trip form. Returns false if it could not be written whole (disk full, ...):
  // file().error() says why.
  bool write_row(int step, int increment, double step_time, double total_time,
                 std::span<const double> values);

  // The file underneath, which keeps the first write failure.
  const OutputFile& file() const { return file_; }
  bool sync() { return file_.sync(); }

 private:
  OutputFile file_;
  std::vector<std::string> columns_;
  std::string line_;  // reused row buffer
};

}  // namespace clinch
