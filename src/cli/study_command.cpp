#include "src/cli/study_command.hpp"

#include <fmt/format.h>
#include <re2/re2.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>

#include "parser/deck_reader.hpp"
#include "parser/diagnostic_render.hpp"
#include "src/check/check.hpp"
#include "src/cli/stop_signals.hpp"
#include "src/output/csv_table.hpp"
#include "src/output/progress.hpp"
#include "src/output/table_comparison.hpp"
#include "src/report/plot_script.hpp"
#include "src/study/scaled_deck.hpp"
#include "src/study/study_table.hpp"

namespace clinch {
namespace {

namespace fs = std::filesystem;

// An interrupted study exits like one with too few settings: it did not finish (2).
constexpr int kExitStudied = 0, kExitDeckErrors = 1, kExitTooFewRuns = 2, kExitUsage = 3;
// --ratio's range: below 1.01 successive settings hardly differ, and above 1000 the third setting
// already takes 10^6 times the deck's increments.
constexpr double kMinimumRatio = 1.01, kMaximumRatio = 1000.0;

// Stop/lock and stick/slip status columns hold codes, not quantities that converge with the
// increment size: a status that switches one increment later would read as a 100 % error. They
// are left out unless --columns asks for them.
bool is_status_column(const std::string& name) {
  return name.rfind("CSLST", 0) == 0 || name.rfind("CSLIPST", 0) == 0;
}

std::string progress_text(const std::vector<SettingOutcome>& outcomes,
                          const std::vector<LadderSetting>& settings, double seconds) {
  std::size_t done = 0;
  std::vector<std::string> running;
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    if (outcomes[i].state == SettingState::Completed || outcomes[i].state == SettingState::Failed) {
      ++done;
    }
    if (outcomes[i].state == SettingState::Running)
      running.push_back(scale_text(settings[i].scale));
  }
  std::string text = fmt::format("study: {} of {} settings done", done, outcomes.size());
  if (!running.empty()) {
    text += fmt::format(", running scale {}", running.front());
    for (std::size_t i = 1; i < running.size(); ++i) text += ", " + running[i];
  }
  return text + fmt::format("  {:.1f} s", seconds);
}

// Writes the scaled decks: the deck's own increments, then each setting `ratio` times finer.
std::optional<std::vector<LadderSetting>> write_ladder(const ScaledDeck& scaled,
                                                       const fs::path& work, const std::string& job,
                                                       int levels, double ratio,
                                                       std::string* error) {
  std::vector<LadderSetting> ladder;
  double scale = 1.0;
  for (int level = 0; level < levels; ++level, scale /= ratio) {
    const fs::path dir = work / fmt::format("setting-{}", level + 1);
    std::error_code ec;
    fs::create_directories(dir, ec);
    const fs::path deck = dir / (job + ".inp");
    std::ofstream out(deck);
    out << scaled.text(scale);
    out.close();
    if (ec || !out) {
      *error = fmt::format("cannot write the scaled deck '{}'", deck.string());
      return std::nullopt;
    }
    ladder.push_back({scale, deck.string(), dir.string(), job});
  }
  return ladder;
}

// Each setting with how its run went and what its status file says; the history tables of the
// completed ones go to `tables`, coarsest first. False when a completed run's table cannot be
// read.
bool collect_settings(const std::vector<LadderSetting>& ladder,
                      const std::vector<SettingOutcome>& outcomes, const std::string& job,
                      StudyResult& result, std::vector<CsvTable>& tables, std::string* error) {
  for (std::size_t i = 0; i < ladder.size(); ++i) {
    StudySetting s;
    s.scale = ladder[i].scale;
    s.deck = ladder[i].deck;
    s.outcome = outcomes[i];
    const fs::path base = fs::path(ladder[i].out_dir) / job;
    s.history = base.string() + ".history.csv";
    if (s.outcome.state == SettingState::Completed || s.outcome.state == SettingState::Failed) {
      std::string status_error;  // a run that could not even write its .sta shows its exit code
      s.status = read_status_file(base.string() + ".sta", &status_error);
    }
    if (s.outcome.state == SettingState::Completed) {
      std::optional<CsvTable> table = read_csv_table(s.history, error);
      if (!table) return false;
      s.run = static_cast<int>(tables.size());
      tables.push_back(std::move(*table));
    }
    result.settings.push_back(std::move(s));
  }
  return true;
}

// The history columns the study estimates: those `pattern` matches, or all but the status codes.
std::vector<std::string> estimated_columns(const CsvTable& table, const re2::RE2* pattern) {
  std::vector<std::string> names;
  for (std::size_t c = 4; c < table.columns.size(); ++c) {
    const std::string& name = table.columns[c];
    if (pattern != nullptr ? re2::RE2::FullMatch(name, *pattern) : !is_status_column(name)) {
      names.push_back(name);
    }
  }
  return names;
}

// The value of `text` when all of it is a finite number.
std::optional<double> finite_number(const std::string& text) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

}  // namespace

std::string check_ratio(const std::string& text) {
  const std::optional<double> value = finite_number(text);
  if (!value || *value < kMinimumRatio || *value > kMaximumRatio) {
    return fmt::format("'{}' is not a ratio: a finite number from {:g} to {:g} is needed", text,
                       kMinimumRatio, kMaximumRatio);
  }
  return {};
}

std::string check_positive(const std::string& text) {
  const std::optional<double> value = finite_number(text);
  if (!value || *value <= 0.0) {
    return fmt::format("'{}' is not a finite number > 0", text);
  }
  return {};
}

int run_study(const StudyOptions& options) {
  SourceManager sources;
  DiagnosticSink sink;
  Model model;
  std::string error;
  if (read_deck_file(options.deck, sources, model, sink, &error) == ReadStatus::IoError) {
    std::cerr << "clinch: error: " << error << "\n";
    return kExitUsage;
  }
  report_run_refusals(model, sink);
  sink.sort_by_location();
  for (const Diagnostic& d : sink.diagnostics()) std::cerr << render_text(d, sources);
  const std::string& deck_name = sources.file(0).display_name;
  if (sink.has_errors()) {
    std::cerr << fmt::format("{}: {} error{}; nothing was run\n", deck_name, sink.error_count(),
                             sink.error_count() == 1 ? "" : "s");
    return kExitDeckErrors;
  }
  std::optional<ScaledDeck> scaled = ScaledDeck::prepare(model, sources, &error);
  if (!scaled) {
    std::cerr << error << "\n";
    return kExitDeckErrors;
  }
  std::shared_ptr<const re2::RE2> pattern;
  if (options.columns) {
    pattern = compile_column_pattern(*options.columns, &error);
    if (!pattern) {
      std::cerr << fmt::format(
          "clinch: error: --columns '{}' is not a valid regular "
          "expression: {}\n",
          *options.columns, error);
      return kExitUsage;
    }
  }
  const std::string job =
      options.deck == "-" ? std::string("stdin") : fs::path(options.deck).stem().string();
  const fs::path work = options.work_dir ? fs::path(*options.work_dir) : fs::path(job + ".study");
  std::error_code ec;
  fs::create_directories(work, ec);
  if (ec) {
    std::cerr << fmt::format("clinch: error: cannot create the work directory '{}': {}\n",
                             work.string(), ec.message());
    return kExitUsage;
  }

  const std::optional<std::vector<LadderSetting>> ladder =
      write_ladder(*scaled, work, job, options.levels, options.ratio, &error);
  if (!ladder) {
    std::cerr << "clinch: error: " << error << "\n";
    return kExitUsage;
  }

  LadderOptions run_options;
  run_options.clinch = current_executable();
  run_options.jobs = options.jobs > 0
                         ? options.jobs
                         : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  run_options.budget_seconds = options.budget_seconds;
  run_options.cost_ratio = options.ratio;
  Progress progress = Progress::for_stderr(options.quiet);
  const auto start = std::chrono::steady_clock::now();
  if (progress.enabled()) {
    run_options.on_progress = [&](const std::vector<SettingOutcome>& outcomes) {
      progress.show(progress_text(
          outcomes, *ladder,
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()));
    };
  }
  // SIGINT and SIGTERM while the settings run stop them cleanly (ladder_runner.hpp) and the
  // study reports what completed; before and after, they have their default effect.
  catch_stop_signals();
  run_options.stop_signal = stop_signal_number;
  const std::vector<SettingOutcome> outcomes = run_ladder(*ladder, run_options);
  const char* const stopped_by = stop_signal_name();
  release_stop_signals();
  progress.clear();

  StudyResult result;
  result.rtol = options.rtol;
  std::vector<CsvTable> tables;
  if (!collect_settings(*ladder, outcomes, job, result, tables, &error)) {
    std::cerr << "clinch: error: " << error << "\n";
    return kExitUsage;
  }
  if (!tables.empty()) {
    const std::vector<std::string> names = estimated_columns(tables.back(), pattern.get());
    if (names.empty()) {
      std::cerr << fmt::format("clinch: error: --columns '{}' matches no history column\n",
                               options.columns.value_or(""));
      return kExitUsage;
    }
    std::vector<const CsvTable*> pointers;
    std::vector<double> scales;
    for (const StudySetting& s : result.settings) {
      if (s.run >= 0) scales.push_back(s.scale);
    }
    for (const CsvTable& t : tables) pointers.push_back(&t);
    // Columns the user chose with --columns are estimated even when they are zero to round-off.
    result.estimate =
        estimate_errors(pointers, scales, options.ratio, names, pattern != nullptr, &error);
    if (!result.estimate) {
      std::cerr << fmt::format("clinch: error: {}\n", error);
      return kExitUsage;
    }
  }
  if (options.rtol) result.chosen = cheapest_setting(result, *options.rtol);

  if (!options.quiet) {
    std::cout << fmt::format(
                     "{}: {} settings, increments scaled from 1 down to {} (ratio {:g}); "
                     "runs in {}\n",
                     deck_name, ladder->size(), scale_text(ladder->back().scale), options.ratio,
                     work.string())
              << render_study_table(result);
  }
  const std::string settings_csv = (work / (job + ".study.csv")).string();
  if (!write_settings_csv(result, settings_csv, &error) ||
      !write_columns_csv(result, (work / (job + ".study-columns.csv")).string(), &error)) {
    std::cerr << "clinch: error: " << error << "\n";
    return kExitUsage;
  }
  // An interrupted study is left as soon as what it has is written: no plot.
  const bool plotted = options.plot && tables.size() >= 2 && stopped_by == nullptr;
  const std::string svg = (work / (job + ".study.svg")).string();
  if (plotted && !run_plot_script("work_precision_plot.py", {settings_csv, svg}, &error)) {
    std::cerr << "clinch: error: " << error << " (--no-plot skips the plot)\n";
    return kExitUsage;
  }
  if (!options.quiet) {
    std::cout << fmt::format("wrote {}{}\n", settings_csv, plotted ? ", " + svg : "");
  }
  if (stopped_by != nullptr) {
    std::cerr << fmt::format("clinch: error: interrupted by {}: {} of {} settings completed\n",
                             stopped_by, tables.size(), ladder->size());
    return kExitTooFewRuns;
  }
  if (tables.size() < 2) {
    std::cerr << fmt::format("clinch: error: {} of {} settings completed: no error estimate\n",
                             tables.size(), ladder->size());
    return kExitTooFewRuns;
  }
  return kExitStudied;
}

}  // namespace clinch
