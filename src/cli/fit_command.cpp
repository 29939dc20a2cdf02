#include "src/cli/fit_command.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <thread>

#include "parser/deck_reader.hpp"
#include "parser/diagnostic_render.hpp"
#include "src/check/check.hpp"
#include "src/cli/stop_signals.hpp"
#include "src/fit/fit_problem.hpp"
#include "src/fit/fit_statistics.hpp"
#include "src/fit/fit_tables.hpp"
#include "src/output/abaqus_labels.hpp"
#include "src/study/ladder_runner.hpp"

namespace clinch {
namespace {

namespace fs = std::filesystem;

constexpr int kExitFitted = 0, kExitDeckErrors = 1, kExitNotFitted = 2, kExitUsage = 3;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct VarySpec {
  std::string name;
  double lower = -kInfinity, upper = kInfinity;
};

std::optional<double> parse_number(std::string_view text) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

// NAME or NAME=LO:HI (LO or HI may be empty: no bound on that side).
std::optional<VarySpec> parse_vary(const std::string& text, std::string* error) {
  VarySpec spec;
  const std::size_t eq = text.find('=');
  spec.name = text.substr(0, eq);
  if (spec.name.empty()) {
    *error = fmt::format("--vary '{}': a parameter name is needed (NAME or NAME=LO:HI)", text);
    return std::nullopt;
  }
  if (eq == std::string::npos) return spec;
  const std::string bounds = text.substr(eq + 1);
  const std::size_t colon = bounds.find(':');
  if (colon == std::string::npos) {
    *error = fmt::format("--vary '{}': the bounds are written LO:HI (either may be empty)", text);
    return std::nullopt;
  }
  const std::string lo = bounds.substr(0, colon), hi = bounds.substr(colon + 1);
  if (!lo.empty()) {
    const std::optional<double> v = parse_number(lo);
    if (!v) {
      *error = fmt::format("--vary '{}': the lower bound '{}' is not a finite number", text, lo);
      return std::nullopt;
    }
    spec.lower = *v;
  }
  if (!hi.empty()) {
    const std::optional<double> v = parse_number(hi);
    if (!v) {
      *error = fmt::format("--vary '{}': the upper bound '{}' is not a finite number", text, hi);
      return std::nullopt;
    }
    spec.upper = *v;
  }
  if (!(spec.lower < spec.upper)) {
    *error = fmt::format("--vary '{}': the lower bound {} is not below the upper bound {}", text,
                         spec.lower, spec.upper);
    return std::nullopt;
  }
  return spec;
}

std::optional<std::pair<FitLoss, double>> parse_loss(const std::string& text) {
  const std::size_t colon = text.find(':');
  const std::string kind = text.substr(0, colon);
  double scale = 1.0;
  if (colon != std::string::npos) {
    const std::optional<double> v = parse_number(std::string_view(text).substr(colon + 1));
    if (!v || *v <= 0.0) return std::nullopt;
    scale = *v;
  }
  if (kind == "none" && colon == std::string::npos) return std::pair{FitLoss::Squared, 1.0};
  if (kind == "huber") return std::pair{FitLoss::Huber, scale};
  if (kind == "cauchy") return std::pair{FitLoss::Cauchy, scale};
  if (kind == "soft_l1") return std::pair{FitLoss::SoftL1, scale};
  return std::nullopt;
}

// Reads and checks a deck as `clinch run` would; the exit status (diagnostics printed) when it
// cannot be run, nothing when it can.
std::optional<int> check_deck(const std::string& path) {
  SourceManager sources;
  DiagnosticSink sink;
  Model model;
  std::string error;
  if (read_deck_file(path, sources, model, sink, &error) == ReadStatus::IoError) {
    std::cerr << "clinch: error: " << error << "\n";
    return kExitUsage;
  }
  report_run_refusals(model, sink);
  sink.sort_by_location();
  for (const Diagnostic& d : sink.diagnostics()) std::cerr << render_text(d, sources);
  if (sink.has_errors()) {
    std::cerr << fmt::format("{}: {} error{}; nothing was run\n", sources.file(0).display_name,
                             sink.error_count(), sink.error_count() == 1 ? "" : "s");
    return kExitDeckErrors;
  }
  return std::nullopt;
}

double root_mean_square(const std::vector<double>& model, const MeasuredCurves& data) {
  std::vector<double> r;
  append_residuals(data, model, r);
  double sum = 0.0;
  for (double v : r) sum += v * v;
  return std::sqrt(sum / static_cast<double>(r.size()));
}

std::string value_text(double v) { return std::isfinite(v) ? fmt::format("{:.6g}", v) : "-"; }

std::string bounds_text(double lower, double upper) {
  return fmt::format("[{}, {}]", std::isfinite(lower) ? fmt::format("{:g}", lower) : "-inf",
                     std::isfinite(upper) ? fmt::format("{:g}", upper) : "inf");
}

}  // namespace

int run_fit(const FitOptions& options) {
  std::string error;
  const auto usage = [](const std::string& message) {
    std::cerr << (message.find(": error: ") != std::string::npos ? message
                                                                 : "clinch: error: " + message)
              << "\n";
    return kExitUsage;
  };
  // The command line first: nothing is read or run when it is wrong.
  std::vector<VarySpec> vary;
  std::set<std::string> seen;
  for (const std::string& text : options.vary) {
    std::optional<VarySpec> spec = parse_vary(text, &error);
    if (!spec) return usage(error);
    if (!seen.insert(spec->name).second) {
      return usage(fmt::format("--vary names '{}' twice", spec->name));
    }
    vary.push_back(*spec);
  }
  if (vary.empty()) return usage("--vary names no parameter");
  if (options.decks.size() > 1 && options.data.size() != options.decks.size()) {
    return usage(
        fmt::format("{} decks and {} data files: with several decks, give one --data per "
                    "deck, in the same order",
                    options.decks.size(), options.data.size()));
  }
  const std::optional<std::pair<FitLoss, double>> loss = parse_loss(options.loss);
  if (!loss) {
    return usage(
        fmt::format("--loss '{}': none, huber, cauchy or soft_l1, the last three with an "
                    "optional :S (a scale > 0 of the scaled residual)",
                    options.loss));
  }
  std::map<std::string, double> scales;
  for (const std::string& text : options.scales) {
    const std::size_t eq = text.rfind('=');
    const std::optional<double> s = eq == std::string::npos
                                        ? std::nullopt
                                        : parse_number(std::string_view(text).substr(eq + 1));
    if (!s || *s <= 0.0) {
      return usage(fmt::format("--scale '{}': COLUMN=S with S a finite number > 0", text));
    }
    scales[text.substr(0, eq)] = *s;
  }

  for (const std::string& deck : options.decks) {
    if (deck == "-") {
      return usage("a fit reads its decks as files: standard input cannot be read again for "
                   "each copy");
    }
  }
  for (const std::string& deck : options.decks) {
    if (const std::optional<int> status = check_deck(deck)) return *status;
  }
  std::vector<std::string> names;
  for (const VarySpec& v : vary) names.push_back(v.name);
  std::vector<FitRig> rigs;
  std::set<std::string> jobs;
  for (const std::string& deck : options.decks) {
    std::optional<ParameterDeck> parameters = ParameterDeck::prepare(deck, names, &error);
    if (!parameters) return usage(error);
    FitRig rig{deck, fs::path(deck).stem().string(), std::move(*parameters), {}};
    if (!jobs.insert(rig.job).second) {
      return usage(
          fmt::format("two decks are named '{}': rename one, their runs would share a "
                      "directory",
                      rig.job));
    }
    rigs.push_back(std::move(rig));
  }
  // The first deck's values are the start; every rig must agree on them.
  const std::vector<double> initial = rigs.front().deck.values();
  for (std::size_t j = 0; j < vary.size(); ++j) {
    for (const FitRig& rig : rigs) {
      if (rig.deck.values()[j] != initial[j]) {
        return usage(
            fmt::format("{}: error: --vary {}: this deck starts at {}, {} at {}: one "
                        "parameter set serves every rig",
                        rig.deck.positions()[j], names[j], rig.deck.values()[j],
                        rigs.front().deck_name, initial[j]));
      }
    }
    if (initial[j] < vary[j].lower || initial[j] > vary[j].upper) {
      return usage(
          fmt::format("{}: error: --vary {}: the deck's value {} lies outside the bounds "
                      "{}",
                      rigs.front().deck.positions()[j], names[j], initial[j],
                      bounds_text(vary[j].lower, vary[j].upper)));
    }
  }
  std::vector<MeasuredCurves> data;
  data.reserve(options.data.size());
  for (const std::string& path : options.data) {
    std::optional<MeasuredCurves> curves =
        read_measured_curves(path, options.abscissa, scales, &error);
    if (!curves) return usage(error);
    data.push_back(std::move(*curves));
  }
  for (const auto& [name, scale] : scales) {
    bool found = false;
    for (const MeasuredCurves& d : data) {
      for (const MeasuredColumn& c : d.columns) {
        found =
            found || canonical_column_name(d.table.columns[c.index]) == canonical_column_name(name);
      }
    }
    if (!found) return usage(fmt::format("--scale {}: no data file measures '{}'", name, name));
  }
  for (std::size_t k = 0; k < data.size(); ++k) {
    rigs[rigs.size() == 1 ? 0 : k].data.push_back(&data[k]);
  }

  const std::string job = rigs.front().job;
  const fs::path work = options.work_dir ? fs::path(*options.work_dir) : fs::path(job + ".fit");
  std::error_code ec;
  fs::create_directories(work, ec);
  if (ec) {
    return usage(
        fmt::format("cannot create the work directory '{}': {}", work.string(), ec.message()));
  }
  std::vector<double> lower, upper, typical;
  for (std::size_t j = 0; j < vary.size(); ++j) {
    lower.push_back(vary[j].lower);
    upper.push_back(vary[j].upper);
    // The size of the difference step where the value is 0: the bounds' width, else 1.
    const double width = vary[j].upper - vary[j].lower;
    typical.push_back(initial[j] != 0.0      ? std::abs(initial[j])
                      : std::isfinite(width) ? width
                                             : 1.0);
  }
  RunEvaluator::Options run_options;
  run_options.clinch = current_executable();
  run_options.work_dir = work.string();
  run_options.jobs = options.jobs > 0
                         ? options.jobs
                         : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  run_options.stop_signal = stop_signal_number;
  RunEvaluator evaluator(std::move(rigs), run_options, typical, lower, upper);
  const std::vector<FitRig>& fit_rigs = evaluator.rigs();

  const auto start = std::chrono::steady_clock::now();
  const auto seconds = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  catch_stop_signals();
  // The deck's own values: their runs show a data column the run does not write, and give the
  // "before" curves.
  std::vector<std::optional<CsvTable>> initial_tables = evaluator.run_tables(initial, "initial");
  std::vector<CurvePair> curves;
  for (std::size_t r = 0; r < fit_rigs.size(); ++r) {
    for (const MeasuredCurves* d : fit_rigs[r].data) {
      CurvePair pair;
      pair.data = d;
      if (initial_tables[r]) {
        if (!check_columns_written(*d, *initial_tables[r], fit_rigs[r].deck_name, &error)) {
          release_stop_signals();
          return usage(error);
        }
        std::optional<std::vector<double>> model = model_values(*d, *initial_tables[r], &error);
        if (!model) {
          release_stop_signals();
          return usage(
              fmt::format("{} (the run of {} at the deck's values)", error, fit_rigs[r].deck_name));
        }
        pair.initial = std::move(*model);
      }
      curves.push_back(std::move(pair));
    }
  }
  for (std::size_t r = 0; r < fit_rigs.size(); ++r) {
    if (!initial_tables[r]) {
      release_stop_signals();
      std::cerr << fmt::format("clinch: error: the run of {} at the deck's own values failed: {}\n",
                               fit_rigs[r].deck_name,
                               evaluator.failures().empty() ? std::string("stopped")
                                                            : evaluator.failures().back().reason);
      return kExitNotFitted;
    }
  }

  const std::size_t m = evaluator.residual_count();
  if (!options.quiet) {
    std::cout << fmt::format(
        "{}: fit of {} parameter{} to {} data file{} ({} points), {} "
        "(Ceres Solver), runs in {}\n",
        fit_rigs.front().deck_name, names.size(), names.size() == 1 ? "" : "s", data.size(),
        data.size() == 1 ? "" : "s", m,
        options.method == "dogleg" ? "dogleg" : "Levenberg-Marquardt", work.string());
  }
  FitSettings settings;
  settings.loss = loss->first;
  settings.loss_scale = loss->second;
  settings.method = options.method == "dogleg" ? FitMethod::Dogleg : FitMethod::LevenbergMarquardt;
  settings.max_iterations = options.max_iterations;
  settings.stopped = [] { return stop_signal_number() != 0; };
  if (!options.quiet) {
    settings.on_iteration = [&](int iteration, double cost, bool taken) {
      std::cout << fmt::format("  iteration {:>3}: cost {:.6e}{}  runs {}  {:.1f} s\n", iteration,
                               cost, taken || iteration == 0 ? "" : " (step not taken)",
                               evaluator.run_count(), seconds());
    };
  }
  const FitOutcome outcome = solve_fit(evaluator, initial, lower, upper, settings);
  if (!evaluator.input_error().empty()) {
    release_stop_signals();
    return usage(evaluator.input_error());
  }

  // The statistics at the optimum, and the runs there for the "after" curves.
  const Eigen::MatrixXd* jacobian = evaluator.jacobian(outcome.values);
  const Eigen::VectorXd* residuals = evaluator.residuals(outcome.values);
  std::vector<std::optional<CsvTable>> fitted_tables =
      evaluator.run_tables(outcome.values, "fitted");
  const char* const stopped_by = stop_signal_name();
  release_stop_signals();
  // Without the runs at and beside the fitted values there is no Jacobian, and no errors.
  const bool have_statistics = jacobian != nullptr && residuals != nullptr;
  FitStatistics statistics;
  if (have_statistics) {
    // A robust loss: the rows weighted by ρ'(r²), as in the least-squares problem whose
    // optimum is the same (iteratively reweighted least squares).
    const Eigen::VectorXd root_weights = loss_weights(settings, *residuals).cwiseSqrt();
    statistics = fit_statistics(root_weights.asDiagonal() * *jacobian,
                                root_weights.cwiseProduct(*residuals));
  } else {
    const auto n = static_cast<Eigen::Index>(names.size());
    statistics.standard_errors.assign(names.size(), std::numeric_limits<double>::quiet_NaN());
    statistics.correlation =
        Eigen::MatrixXd::Constant(n, n, std::numeric_limits<double>::quiet_NaN());
  }
  {
    std::size_t k = 0;
    for (std::size_t r = 0; r < fit_rigs.size(); ++r) {
      for (const MeasuredCurves* d : fit_rigs[r].data) {
        if (fitted_tables[r]) {
          std::optional<std::vector<double>> model = model_values(*d, *fitted_tables[r], &error);
          if (model) curves[k].fitted = std::move(*model);
        }
        ++k;
      }
    }
  }

  std::vector<FittedParameter> fitted;
  for (std::size_t j = 0; j < names.size(); ++j) {
    fitted.push_back({names[j], initial[j], outcome.values[j], lower[j], upper[j]});
  }
  const std::string fit_csv = (work / (job + ".fit.csv")).string();
  const std::string curves_csv = (work / (job + ".fit-curves.csv")).string();
  if (!write_parameter_table(fit_csv, fitted, statistics, &error) ||
      !write_curves_table(curves_csv, curves, &error)) {
    return usage(error);
  }
  std::vector<std::string> written_decks;
  for (const FitRig& rig : fit_rigs) {
    const fs::path deck(rig.deck_name);
    const fs::path path = deck.parent_path() / (deck.stem().string() + ".fitted.inp");
    std::ofstream out(path);
    out << rig.deck.text(outcome.values);
    out.close();
    if (!out) return usage(fmt::format("cannot write '{}'", path.string()));
    written_decks.push_back(path.string());
  }

  std::size_t width = 9;
  for (const std::string& n : names) width = std::max(width, n.size());
  std::string text = fmt::format("{:<{}}  {:>12}  {:>12}  {:>12}  {}\n", "parameter", width,
                                 "initial", "fitted", "std. error", "bounds");
  for (std::size_t j = 0; j < names.size(); ++j) {
    text += fmt::format("{:<{}}  {:>12}  {:>12}  {:>12}  {}\n", names[j], width,
                        value_text(initial[j]), value_text(outcome.values[j]),
                        value_text(statistics.standard_errors[j]), bounds_text(lower[j], upper[j]));
  }
  if (have_statistics && statistics.identifiable() && names.size() > 1) {
    text += "correlation\n";
    for (std::size_t i = 0; i < names.size(); ++i) {
      text += fmt::format("  {:<{}}", names[i], width);
      for (std::size_t j = 0; j < names.size(); ++j) {
        text += fmt::format("  {:>6.3f}", statistics.correlation(static_cast<Eigen::Index>(i),
                                                                 static_cast<Eigen::Index>(j)));
      }
      text += "\n";
    }
  }
  text += "residual per data file (RMS of (model - measured) / scale, before -> after):\n";
  for (const CurvePair& c : curves) {
    std::string columns;
    for (const MeasuredColumn& col : c.data->columns) {
      columns += (columns.empty() ? "" : ", ") + c.data->table.columns[col.index];
    }
    text += fmt::format("  {}  ({} against {}, {} points): {} -> {}\n", c.data->table.path, columns,
                        c.data->table.columns[c.data->abscissa], c.data->point_count(),
                        value_text(root_mean_square(c.initial, *c.data)),
                        c.fitted.empty() ? "-" : value_text(root_mean_square(c.fitted, *c.data)));
  }
  const std::size_t failed = evaluator.failures().size();
  text += fmt::format("runs: {} ({} failed), {:.2f} s, {} iterations: {}\n", evaluator.run_count(),
                      failed, seconds(), outcome.iterations,
                      outcome.converged ? "converged" : "NOT CONVERGED");
  text += fmt::format("Ceres: {}\n", outcome.termination);
  for (std::size_t k = 0; k < failed && k < 5; ++k) {
    const RunFailure& f = evaluator.failures()[k];
    std::string at;
    for (std::size_t j = 0; j < names.size(); ++j) {
      at += fmt::format("{}{}={}", j ? ", " : "", names[j], value_text(f.values[j]));
    }
    text += fmt::format("  run failed at {} ({}): {}\n", at, f.rig, f.reason);
  }
  if (failed > 5) text += fmt::format("  and {} more failed runs\n", failed - 5);
  if (!statistics.identifiable()) {
    std::string which, direction;
    for (std::size_t j : statistics.undetermined) {
      which += (which.empty() ? "" : ", ") + names[j];
      if (statistics.null_direction.size() > 0) {
        direction += fmt::format("{}{} {:+.3f}", direction.empty() ? "" : ", ", names[j],
                                 statistics.null_direction(static_cast<Eigen::Index>(j)));
      }
    }
    text += fmt::format(
        "NOT DETERMINED by the data: {}{}\n", which,
        direction.empty()
            ? " (the measured curves do not depend on it)"
            : fmt::format(" (only a combination of them enters: the curves do not change along "
                          "{}, in units of each one's effect; smallest singular value {:.2e} of "
                          "the column-scaled Jacobian)",
                          direction, statistics.smallest_singular_value));
  }
  if (!have_statistics) {
    text += "no standard errors: the runs at or beside the fitted values failed\n";
  }
  std::cout << text;
  if (!options.quiet) {
    std::cout << fmt::format("wrote {}, {}, {}\n", fmt::join(written_decks, ", "), fit_csv,
                             curves_csv);
  }
  if (stopped_by != nullptr) {
    std::cerr << fmt::format("clinch: error: interrupted by {}\n", stopped_by);
    return kExitNotFitted;
  }
  if (!outcome.converged) {
    std::cerr << "clinch: error: the fit did not converge: " << outcome.termination << "\n";
    return kExitNotFitted;
  }
  if (!statistics.identifiable()) {
    std::cerr << "clinch: error: the data do not determine every varied parameter\n";
    return kExitNotFitted;
  }
  if (!have_statistics) {
    std::cerr << "clinch: error: no standard errors at the fitted values\n";
    return kExitNotFitted;
  }
  return kExitFitted;
}

}  // namespace clinch
