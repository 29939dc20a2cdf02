#include "src/cli/run_command.hpp"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <iostream>

#include "parser/deck_reader.hpp"
#include "parser/diagnostic_render.hpp"
#include "src/assembly/analysis_plan.hpp"
#include "src/assembly/connector_step_problem.hpp"
#include "src/assembly/connector_system.hpp"
#include "src/assembly/whole_tangent_need.hpp"
#include "src/check/check.hpp"
#include "src/cli/blas_threads.hpp"
#include "src/cli/stop_signals.hpp"
#include "src/model/default_stick_stiffness.hpp"
#include "src/output/history_columns.hpp"
#include "src/output/run_log.hpp"
#include "src/output/status_file.hpp"
#include "src/parallel/communicator.hpp"
#include "src/solver/step_driver.hpp"

namespace clinch {
namespace {

constexpr int kExitCompleted = 0, kExitDeckErrors = 1, kExitStopped = 2, kExitUsage = 3;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string count_of(std::size_t n, const char* what) {
  return fmt::format("{} {}{}", n, what, n == 1 ? "" : "s");
}

// A --job value must be a file name, not a path: the outputs land in the output directory and
// nowhere else. Returns the message, or an empty string when it is one.
std::string check_job_name(const std::string& job) {
  if (job.empty() || job == "." || job == ".." || job.find('/') != std::string::npos) {
    return fmt::format(
        "--job '{}' is not a job name: a file name (not empty, '.' or '..', no "
        "'/') is needed",
        job);
  }
  return {};
}

// A distributed run's ranks (docs/parallel.md), for the stop test below; null in a serial run.
Communicator* world = nullptr;

// The stop test of a distributed run: a signal that reached any rank stops every rank at the same
// point, since each rank asks at the same points of the same analysis.
const char* stop_signal_of_any_rank() {
  const char* mine = stop_signal_name();
  const int first = world->first(mine != nullptr);
  if (first == world->size()) return nullptr;
  static std::string name;
  name = world->broadcast(mine ? mine : "", first);
  return name.c_str();
}

// A signal that arrived before the analysis (while reading or planning): the run ends as a signal
// during the analysis ends it (exit 2, cli-contract.md), with a status file that says where it
// stopped. Returns false when no signal arrived.
bool stopped_before_analysis(const char* stage, const std::string& status_path, RunLog& log) {
  const char* signal = world ? stop_signal_of_any_rank() : stop_signal_name();
  if (signal == nullptr) return false;
  const std::string reason =
      fmt::format("interrupted by {} {}, before the first increment", signal, stage);
  StatusFile status;
  std::string error;
  if (!status.open(status_path, &error))
    log.error(error);
  else
    status.write_failed(reason, 1, 0, 0.0);
  log.error(fmt::format("analysis stopped: {} (step 1, increment 0, time 0)", reason));
  return true;
}

// The history header in the naming --labels chose (a copy only when it differs from clinch's).
std::vector<std::string> column_names(const HistoryColumns& columns, LabelStyle style) {
  if (style == LabelStyle::Clinch) return columns.names();
  std::vector<std::string> names;
  names.reserve(columns.names().size());
  for (const std::string& name : columns.names()) names.push_back(column_name_in(name, style));
  return names;
}

}  // namespace

int run_deck(const RunCommandOptions& options) {
  namespace fs = std::filesystem;
  stop_idle_blas_threads();  // until the first factorization

  if (options.job) {
    if (const std::string message = check_job_name(*options.job); !message.empty()) {
      std::cerr << "clinch: error: " << message << "\n";
      return kExitUsage;
    }
  }
  // Under `mpirun -n P`, P > 1: every rank runs the analysis on its share of the elements, and
  // rank 0 alone writes the outputs and prints (docs/parallel.md).
  std::unique_ptr<Communicator> communicator;
  if (launched_on_several_ranks()) {
    std::string error;
    communicator = make_world_communicator(&error);
    if (!communicator) {
      std::cerr << "clinch: error: " << error << "\n";
      return kExitUsage;
    }
    world = communicator.get();
    if (options.check_tangent) {
      if (world->rank() == 0) {
        std::cerr << "clinch: error: --check-tangent runs on one process, not under mpirun\n";
      }
      return kExitUsage;
    }
  }
  const bool writer = !communicator || communicator->rank() == 0;
  // From here a signal stops the run cleanly, at the next point that asks for it: after reading,
  // after planning, or in the analysis (src/cli/stop_signals.hpp).
  catch_stop_signals();
  const auto start = std::chrono::steady_clock::now();
  SourceManager sources;
  DiagnosticSink sink;
  Model model;
  std::string io_error;
  if (read_deck_file(options.deck, sources, model, sink, &io_error) == ReadStatus::IoError) {
    if (writer) std::cerr << "clinch: error: " << io_error << "\n";
    return kExitUsage;
  }
  report_run_refusals(model, sink);
  // The deck is the first file registered: its name as diagnostics show it ("<stdin>" for -).
  const std::string& deck_name = sources.file(0).display_name;
  // Standard input has no file name to take the job name from.
  const std::string job = options.job.value_or(
      options.deck == "-" ? std::string("stdin") : fs::path(options.deck).stem().string());
  std::error_code ec;
  fs::create_directories(options.out_dir, ec);
  if (ec) {
    if (writer)
      std::cerr << fmt::format("clinch: error: cannot create output directory '{}': {}\n",
                               options.out_dir, ec.message());
    return kExitUsage;
  }
  const fs::path base = fs::path(options.out_dir) / job;
  // The other ranks of a distributed run write nowhere.
  const auto output_path = [&](const char* extension) {
    return writer ? base.string() + extension : std::string("/dev/null");
  };
  RunLog log(options.quiet || !writer ? nullptr : &std::cout, writer ? &std::cerr : nullptr);
  std::string error;
  // In a distributed run only rank 0 opens real files: the others follow its outcome rather than
  // wait for it in the analysis.
  const auto every_rank_ok = [&](bool ok) {
    return world ? world->first(!ok) == world->size() : ok;
  };
  if (!every_rank_ok(log.open(output_path(".log"), &error))) {
    if (writer) std::cerr << "clinch: error: " << error << "\n";
    return kExitUsage;
  }
  sink.sort_by_location();
  for (const Diagnostic& d : sink.diagnostics()) {
    const std::string text = render_text(d, sources);
    if (d.severity == Severity::Error)
      log.error(text);
    else
      log.warning(text);
  }
  sources.release_texts();  // the lines a warning showed are not held through the analysis
  if (stopped_before_analysis("while reading the deck", output_path(".sta"), log)) {
    return kExitStopped;
  }
  if (sink.has_errors()) {
    log.error(fmt::format("{}: {}, {}; nothing was run", deck_name,
                          count_of(sink.error_count(), "error"),
                          count_of(sink.warning_count(), "warning")));
    return kExitDeckErrors;
  }
  const double read_seconds = seconds_since(start);
  const auto plan_start = std::chrono::steady_clock::now();
  // Under mpirun each rank assembles its part of the tangent and the PETSc backend sums the
  // parts, and the plan holds the rank's share of the connectors and springs, unless another
  // backend or a feature needs the whole tangent on every rank (docs/parallel.md).
  std::string whole_tangent;
  std::optional<PlanShare> share;
  if (communicator) {
    whole_tangent =
        options.solver == SolverChoice::Automatic || options.solver == SolverChoice::Petsc
            ? whole_tangent_need(model)
            : std::string("the --solver asked for solves the whole system on every rank");
    if (whole_tangent.empty()) share = PlanShare{communicator->rank(), communicator->size(), true};
  }
  std::optional<AnalysisPlan> plan = build_analysis_plan(model, &error, share ? &*share : nullptr);
  if (share) {
    // Each rank checked the connectors of its own share, in element order: the model's first
    // error is that of the lowest rank that met one.
    if (const int failing = communicator->first(!plan); failing < communicator->size()) {
      error = communicator->broadcast(error, failing);
      plan.reset();
    }
  }
  if (!plan) {
    log.error(fmt::format("{}: error: {}", deck_name, error));
    return kExitDeckErrors;
  }
  // A rank's plan over its own equations numbers only those (equation_layout.hpp).
  const int node_equations =
      plan->layout.local ? plan->layout.global_node_equations : plan->dofs.node_equations();
  const int equations = plan->layout.local ? plan->layout.global_count : plan->dofs.equations();
  // The nodes clinch adds at the centres of mass of rigid bodies' elements are not the deck's.
  const std::size_t centres = model.constraints.element_masses.size();
  log.info(
      fmt::format("{}: {} nodes{}, {} connectors, {} springs; {} active DOFs ({:.3g} per "
                  "node), {} multipliers",
                  deck_name, model.nodes.size() - centres,
                  centres == 0 ? std::string()
                               : fmt::format(" (and {} at the centres of mass of rigid "
                                             "bodies' elements)",
                                             centres),
                  plan->connector_total, plan->spring_total, node_equations,
                  model.nodes.empty() ? 0.0 : double(node_equations) / model.nodes.size(),
                  equations - node_equations));
  // A rank's plan over its own equations holds only the dependent DOFs it reads.
  const int followers = plan->layout.local
                            ? plan->layout.global_count - plan->solved_layout.global_count
                            : static_cast<int>(plan->dependents.dofs.size());
  if (followers > 0) {
    // A rank's plan holds the condensed elements of its own share.
    double condensed = static_cast<double>(plan->expansions.size());
    if (plan->shared) communicator->sum({&condensed, 1});
    log.info(
        fmt::format("{} of the active DOFs follow others through kinematic constraints "
                    "(eliminated: {} condensed elements)",
                    followers, condensed));
  }
  if (auto stick = default_stick_stiffness_summary(model.behaviors)) log.info(*stick);
  ConnectorSystem system(model, *plan);
  if (communicator) {
    system.distribute(*communicator, whole_tangent.empty());
    const std::string vectors =
        plan->layout.local ? "; the vectors run over each rank's own rows and the ghosts its "
                             "elements read"
                           : std::string();
    const std::string held =
        whole_tangent.empty()
            ? "each holds the records and results of its own elements and assembles its part of "
              "the tangent, which PETSc sums" +
                  vectors
            : "each rank holds the whole tangent: " + whole_tangent;
    log.info(fmt::format(
        "distributed over {} processes: each evaluates about {} connectors and {} springs; {}",
        communicator->size(),
        (plan->connector_total + communicator->size() - 1) / communicator->size(),
        (plan->spring_total + communicator->size() - 1) / communicator->size(), held));
  }
  if (stopped_before_analysis("while planning the analysis", output_path(".sta"), log)) {
    return kExitStopped;
  }
  const double plan_seconds = seconds_since(plan_start);
  const auto columns_start = std::chrono::steady_clock::now();
  HistoryColumns columns(model, *plan);
  HistoryTable table;
  StatusFile status;
  // The status file first, so that it can say why the history could not be started (a header
  // larger than the file-size limit, a full disk).
  if (!every_rank_ok(
          status.open(output_path(".sta"), &error) &&
          table.open(output_path(".history.csv"), column_names(columns, options.labels), &error))) {
    if (status.is_open()) status.write_failed(error, 1, 0, 0.0);
    log.error(fmt::format("analysis stopped: {} (step 1, increment 0, time 0)", error));
    return kExitUsage;
  }
  const double columns_seconds = seconds_since(columns_start);
  if (options.labels == LabelStyle::Abaqus) {
    log.info(
        fmt::format("history: {} columns, rotational components with Abaqus's names "
                    "(--labels abaqus: CTM1 for CTF4, CUR1 for CU4, ...)",
                    columns.names().size()));
  }
  // Per step, the driver asks for the solver of the storage the step needs.
  const bool definite = !plan->has_multipliers;
  const SolverFactory solvers = [&](bool symmetric,
                                    bool tangent_changes) -> std::unique_ptr<LinearSolver> {
    if (!symmetric && options.solver == SolverChoice::Cholmod) return nullptr;
    return make_linear_solver(options.solver, symmetric, definite, tangent_changes);
  };
  Progress progress = Progress::for_stderr(options.quiet || !writer);
  HistoryRecorder history(columns, table, system);
  RunOutputs outputs(history, status, log, progress);
  ModesFile modes(output_path(".modes.csv"));
  outputs.set_modes_file(&modes);
  std::vector<std::string> step_names;
  for (const Step& step : model.history.steps) step_names.push_back(step.name.display);
  outputs.set_step_names(std::move(step_names));
  ConnectorStepProblem step_problem(model, system);
  const RunResult result = run_analysis(
      model, system, step_problem, solvers, outputs,
      RunOptions{options.check_tangent, world ? stop_signal_of_any_rank : stop_signal_name});
  progress.finish();
  const double seconds = seconds_since(start);
  const std::string summary = fmt::format(
      "{}, {}, {} in {:.3f} s", count_of(static_cast<std::size_t>(result.increments), "increment"),
      count_of(static_cast<std::size_t>(result.iterations), "iteration"),
      count_of(static_cast<std::size_t>(result.cutbacks), "cutback"), seconds);
  // scripts/bench_setup.sh reads this line: reading, plan and columns are the run's setup.
  log.info(
      fmt::format("time: reading {:.3f} s, plan {:.3f} s, columns {:.3f} s, symbolic "
                  "analysis {:.3f} s, Newton {:.3f} s, whole run {:.3f} s",
                  read_seconds, plan_seconds, columns_seconds, result.analyze_seconds,
                  result.newton_seconds, seconds));
  if (result.factorizations > 0) {
    // The per-iteration cost against its floor, one factorization plus solve
    // (scripts/bench_lattice.sh reads this line).
    const double n = result.factorizations;
    log.info(fmt::format(
        "factorize+solve: {:.6g} s per iteration ({} factorizations); Newton: "
        "{:.6g} s per iteration; whole run: {:.6g} s per iteration",
        result.linear_seconds / n, result.factorizations, result.newton_seconds / n, seconds / n));
  }
  if (!result.completed) {
    log.error(fmt::format("{}: FAILED after {}", job, summary));
    // The other ranks wait for rank 0 in their next exchange: an output it could not write ends
    // them too.
    if (result.io_error && world) world->abort(kExitUsage);
    // An output that could not be written is an I/O error (cli-contract.md), not a stop of the
    // analysis.
    return result.io_error ? kExitUsage : kExitStopped;
  }
  log.info(fmt::format("{}: COMPLETED: {}", job, summary));
  if (log.file().failed()) {
    std::cerr << "clinch: error: " << log.file().error() << "\n";
    return kExitUsage;
  }
  return kExitCompleted;
}

}  // namespace clinch
