#include "src/cli/report_command.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <set>

#include "src/fit/fit_tables.hpp"
#include "src/output/abaqus_labels.hpp"
#include "src/output/csv_table.hpp"
#include "src/output/iteration_log_reader.hpp"
#include "src/output/status_file_reader.hpp"
#include "src/report/plot_script.hpp"
#include "src/report/report_data.hpp"

namespace clinch {
namespace {

namespace fs = std::filesystem;

constexpr int kExitWritten = 0, kExitUsage = 3;
constexpr std::string_view kHistorySuffix = ".history.csv";

// Whether the first line of the table at `path` is one `accepts`; says why not on stderr.
bool has_header(const std::string& path, std::string_view what, std::string_view kind,
                const std::function<bool(const std::string&)>& accepts) {
  std::ifstream probe(path);
  std::string header;
  if (!probe || !std::getline(probe, header)) {
    std::cerr << fmt::format("clinch: error: cannot read {} '{}'\n", what, path);
    return false;
  }
  if (!accepts(header)) {
    std::cerr << fmt::format("clinch: error: {}:1: not a {}\n", path, kind);
    return false;
  }
  return true;
}

// The job whose history table RUN_DIR holds, when there is exactly one.
std::optional<std::string> only_job(const fs::path& dir, std::string* error) {
  std::vector<std::string> jobs;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.size() > kHistorySuffix.size() && name.ends_with(kHistorySuffix)) {
      jobs.push_back(name.substr(0, name.size() - kHistorySuffix.size()));
    }
  }
  if (ec) {
    *error = fmt::format("cannot read the run directory '{}': {}", dir.string(), ec.message());
    return std::nullopt;
  }
  if (jobs.size() != 1) {
    *error = jobs.empty() ? fmt::format(
                                "'{}' holds no <job>.history.csv: is it a `clinch run --out` "
                                "directory?",
                                dir.string())
                          : fmt::format("'{}' holds {} history tables: choose one with --job",
                                        dir.string(), jobs.size());
    return std::nullopt;
  }
  return jobs.front();
}

}  // namespace

int run_report(const ReportOptions& options) {
  std::string error;
  const fs::path dir(options.run_dir);
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    std::cerr << fmt::format("clinch: error: '{}' is not a directory\n", options.run_dir);
    return kExitUsage;
  }
  std::optional<std::string> job = options.job ? options.job : only_job(dir, &error);
  if (!job) {
    std::cerr << "clinch: error: " << error << "\n";
    return kExitUsage;
  }
  const fs::path base = dir / *job;
  const std::optional<CsvTable> history = read_csv_table(base.string() + ".history.csv", &error);
  if (!history) {
    std::cerr << "clinch: error: " << error << "\n";
    return kExitUsage;
  }
  // The status file and the log make the convergence plot; a page without it is still useful.
  const std::optional<StatusRecord> status = read_status_file(base.string() + ".sta", &error);
  if (!status) std::cerr << "clinch: warning: " << error << "; no cutbacks shown\n";
  const std::optional<std::vector<IterationRecord>> iterations =
      read_iteration_log(base.string() + ".log", &error);
  if (!iterations) std::cerr << "clinch: warning: " << error << "; no convergence plot\n";

  // What --elements and --variables name must be in the history: a misspelt label would
  // otherwise give a page without the plot the user asked for, and no word why.
  {
    std::set<std::string> wheres, variables;
    for (const std::string& name : history->columns) {
      const ColumnDescription d = describe_column(name);
      wheres.insert(d.where);
      variables.insert(d.variable);
    }
    for (const std::string& where : options.elements) {
      if (!wheres.contains(where)) {
        std::cerr << fmt::format(
            "clinch: error: --elements: no history column is at '{}' (columns are named "
            "<VAR>@<where>, e.g. CTF1@{})\n",
            where, history->columns.size() > 4 ? describe_column(history->columns[4]).where : "7");
        return kExitUsage;
      }
    }
    for (const std::string& variable : options.variables) {
      if (!variables.contains(canonical_variable(variable))) {
        std::cerr << fmt::format("clinch: error: --variables: the history has no {} column\n",
                                 variable);
        return kExitUsage;
      }
    }
  }

  ReportInputs inputs;
  inputs.job = *job;
  inputs.max_connectors = options.max_connectors;
  inputs.elements = options.elements;
  inputs.components = options.components;
  for (const std::string& v : options.variables) inputs.variables.push_back(canonical_variable(v));
  inputs.history = &*history;
  inputs.status = status ? &*status : nullptr;
  inputs.iterations = iterations ? &*iterations : nullptr;
  inputs.compare_options.rtol = options.rtol;
  inputs.compare_options.atol = options.atol;
  std::optional<CsvTable> golden;
  std::optional<TableComparison> comparison;
  if (options.golden) {
    golden = read_csv_table(*options.golden, &error);
    if (golden) comparison = compare_tables(*history, *golden, inputs.compare_options, &error);
    if (!golden || !comparison) {
      std::cerr << "clinch: error: " << error << "\n";
      return kExitUsage;
    }
    inputs.golden = &*golden;
    inputs.comparison = &*comparison;
  }
  // A study's or a fit's table is known by its header; the script reads the rest.
  if (options.study &&
      !has_header(*options.study, "the study table", "<job>.study.csv of `clinch study`",
                  [](const std::string& h) { return h.rfind("setting,scale,state,", 0) == 0; })) {
    return kExitUsage;
  }
  if (options.study) inputs.study_csv = fs::absolute(*options.study).string();
  if (options.fit &&
      !has_header(*options.fit, "the fit curves", "<job>.fit-curves.csv of `clinch fit`",
                  [](const std::string& h) { return h == kFitCurvesHeader; })) {
    return kExitUsage;
  }
  const std::string page = options.output.value_or((dir / (*job + ".report.html")).string());
  const std::string data_path = page + ".json";
  {
    std::ofstream out(data_path);
    out << report_data_text(inputs);
    out.close();
    if (!out) {
      std::cerr << fmt::format("clinch: error: cannot write '{}'\n", data_path);
      return kExitUsage;
    }
  }
  std::vector<std::string> script_args = {data_path, page};
  if (options.quiet) script_args.push_back("--quiet");
  if (inputs.study_csv) {
    script_args.push_back("--study");
    script_args.push_back(*inputs.study_csv);
  }
  if (options.fit) {
    script_args.push_back("--fit");
    script_args.push_back(fs::absolute(*options.fit).string());
  }
  const bool drawn = run_plot_script("report_page.py", script_args, &error);
  fs::remove(data_path, ec);
  if (!drawn) {
    std::cerr << "clinch: error: " << error << "\n";
    return kExitUsage;
  }
  if (!options.quiet) std::cout << "wrote " << page << "\n";
  return kExitWritten;
}

}  // namespace clinch
