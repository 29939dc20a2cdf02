// The clinch command line (cli-contract.md): `run`, `check`, `compare`, `study`, `fit`, `report`
// and `keywords`.
// Usage errors, and standard output that cannot be written, exit with 3.
#include <csignal>
#include <iostream>

#include <CLI/CLI.hpp>

#include "src/cli/check_command.hpp"
#include "src/cli/compare_command.hpp"
#include "src/cli/fit_command.hpp"
#include "src/cli/heap_reuse.hpp"
#include "src/cli/huge_pages.hpp"
#include "src/cli/keywords_command.hpp"
#include "src/cli/report_command.hpp"
#include "src/cli/run_command.hpp"
#include "src/cli/standard_output.hpp"
#include "src/cli/study_command.hpp"

namespace {

int run_command_line(int argc, char** argv) {
  CLI::App app{"clinch: implicit analysis of connector elements from Abaqus-style keyword decks"};
  app.set_version_flag("--version", std::string("clinch ") + CLINCH_VERSION);
  app.require_subcommand(1);

  clinch::RunCommandOptions run_options;
  std::string solver = "auto";
  CLI::App* run = app.add_subcommand(
      "run",
      "Run every step of a deck; writes <job>.history.csv, <job>.sta and <job>.log; exit "
      "0 = completed, 1 = deck errors (nothing run), 2 = stopped early (also by SIGINT or "
      "SIGTERM, which keep every converged increment), 3 = usage or I/O error (an output "
      "that cannot be written stops the run)");
  run->add_option("DECK", run_options.deck, "the deck (.inp), or - for standard input")->required();
  run->add_option("--out", run_options.out_dir, "output directory (created if missing)")
      ->capture_default_str();
  run->add_option("--job", run_options.job,
                  "job name, a file name without '/' (default: the deck's name without .inp; "
                  "stdin for -)");
  run->add_flag("--quiet", run_options.quiet, "print nothing but warnings and errors");
  std::string labels = "clinch";
  run->add_option("--labels", labels,
                  "history column names: clinch (CTF4@7, CU6@7: the component number) or abaqus "
                  "(CTM1@7, CUR3@7: Abaqus's letters for rotational components)")
      ->check(CLI::IsMember({"clinch", "abaqus"}))
      ->capture_default_str();
  run->add_flag("--check-tangent", run_options.check_tangent,
                "compare the assembled tangent with finite differences of the residual at the "
                "first iteration of each increment and log the worst entries (small decks)");
  run->add_option("--solver", solver,
                  "linear solver: auto (CHOLMOD for SPD systems, UMFPACK for the others, handing "
                  "over to petsc where factorizations cost more than AMG-preconditioned solves "
                  "(the step's log line says why) and from CHOLMOD to UMFPACK when the matrix "
                  "proves indefinite; petsc under mpirun), cholmod (symmetric steps only), "
                  "umfpack, dense (Cholesky or LU) or petsc (CG with BoomerAMG for SPD systems, "
                  "GMRES with BoomerAMG for unsymmetric ones, MUMPS with multipliers)")
      ->check(CLI::IsMember({"auto", "cholmod", "umfpack", "dense", "petsc"}))
      ->capture_default_str();

  std::string deck;
  std::string format = "text";
  CLI::App* check = app.add_subcommand(
      "check",
      "Parse and validate a deck (syntax, parameters, references, connector rules, "
      "steps) without solving; exit 0 = no errors, 1 = errors, 3 = usage or I/O error");
  check->add_option("DECK", deck, "the deck (.inp), or - for standard input")->required();
  check->add_option("--format", format, "diagnostic format: text (stderr) or json (stdout)")
      ->check(CLI::IsMember({"text", "json"}));

  clinch::CompareArguments compare_arguments;
  CLI::App* compare = app.add_subcommand(
      "compare",
      "Compare two history tables column by column: rows matched by total_time, the result "
      "interpolated linearly at the golden times; a value passes when |r - g| <= atol + rtol * "
      "max(|g|, largest |g| of the column). Prints the worst deviation of each column; exit 0 = "
      "all pass, 1 = a column fails or is missing, 3 = usage or I/O error");
  compare->add_option("RESULT", compare_arguments.result_path, "the history table to check (.csv)")
      ->required();
  compare->add_option("GOLDEN", compare_arguments.golden_path, "the reference history table (.csv)")
      ->required();
  const CLI::Validator tolerance([](std::string& text) { return clinch::check_tolerance(text); },
                                 "TOLERANCE");
  compare->add_option("--rtol", compare_arguments.rtol, "relative tolerance")
      ->check(tolerance)
      ->capture_default_str();
  compare->add_option("--atol", compare_arguments.atol, "absolute tolerance")
      ->check(tolerance)
      ->capture_default_str();
  compare->add_option("--columns", compare_arguments.columns,
                      "compare only the golden columns whose whole name matches this "
                      "regular expression (RE2 syntax; default: all)");

  clinch::StudyOptions study_options;
  CLI::App* study = app.add_subcommand(
      "study",
      "Run a deck over a ladder of increment sizes (the deck's *STATIC settings, then each "
      "--ratio times finer) and print per setting the wall time, increments, Newton iterations, "
      "cutbacks and the error of the history columns against the finest setting and as "
      "estimated by Richardson extrapolation; writes <job>.study.csv, <job>.study-columns.csv "
      "and the work-precision plot <job>.study.svg into the work directory; exit 0 = at least "
      "two settings compared, 1 = deck errors (nothing run), 2 = fewer than two settings "
      "completed, or stopped by SIGINT or SIGTERM (forwarded to the running settings; the table "
      "of what completed is written), 3 = usage or I/O error");
  study->add_option("DECK", study_options.deck, "the deck (.inp), or - for standard input")
      ->required();
  study->add_option("--work", study_options.work_dir,
                    "directory for the scaled decks, their runs and the study's outputs "
                    "(default: <job>.study)");
  study->add_option("--levels", study_options.levels, "number of settings, coarsest first")
      ->check(CLI::Range(2, 40))
      ->capture_default_str();
  study->add_option("--ratio", study_options.ratio,
                    "each setting's increments are the previous one's divided by this")
      ->check(CLI::Validator(clinch::check_ratio, "RATIO"))
      ->capture_default_str();
  study->add_option("--budget", study_options.budget_seconds,
                    "wall-time budget in seconds: a finer setting starts only when its predicted "
                    "time fits")
      ->check(CLI::Validator(clinch::check_positive, "SECONDS"));
  study->add_option("--rtol", study_options.rtol,
                    "name the cheapest setting (least work: increment attempts plus Newton "
                    "iterations) whose estimated "
                    "relative error is below this")
      ->check(CLI::Validator(clinch::check_positive, "RTOL"));
  study->add_option("--jobs", study_options.jobs, "runs at once (default: one per core)")
      ->check(CLI::Range(1, 1024));
  study->add_option("--columns", study_options.columns,
                    "estimate only the history columns whose whole name matches this regular "
                    "expression (RE2 syntax; default: all but the status codes CSLST and "
                    "CSLIPST)");
  study->add_flag(
      "--no-plot", [&](std::int64_t) { study_options.plot = false; },
      "skip the work-precision plot (it needs python3 with matplotlib)");
  study->add_flag("--quiet", study_options.quiet, "print nothing but warnings and errors");

  clinch::FitOptions fit_options;
  CLI::App* fit = app.add_subcommand(
      "fit",
      "Calibrate the deck's *PARAMETER values named by --vary against measured curves: each "
      "evaluation runs a copy of the deck (never the deck itself) as a child `clinch run`, Ceres "
      "Solver minimises the scaled differences at the data points (Levenberg-Marquardt or "
      "dogleg, bounds, optional robust loss, derivatives by finite differences over whole runs); "
      "prints the fitted values, standard errors, correlations, the residual per data file, runs "
      "and time; writes <deck>.fitted.inp beside each deck, <job>.fit.csv and "
      "<job>.fit-curves.csv into the work directory; exit 0 = converged with every parameter "
      "determined, 1 = deck errors (nothing run), 2 = not converged, a parameter the data do not "
      "determine, the runs at the deck's values failed, or stopped by SIGINT or SIGTERM, 3 = "
      "usage or I/O error");
  fit->add_option("DECK", fit_options.decks,
                  "the deck (.inp); several decks are several rigs, each compared with its own "
                  "--data file")
      ->required();
  fit->add_option("--data", fit_options.data,
                  "measured curves (.csv): history column names as a run writes them (Abaqus "
                  "labels accepted), the abscissa and one or more measured columns; repeat for "
                  "several files")
      ->required();
  fit->add_option("--vary", fit_options.vary,
                  "the *PARAMETER names to fit, NAME or NAME=LO:HI (bounds; either may be left "
                  "out), comma-separated; the deck's values are the start")
      ->delimiter(',')
      ->required();
  fit->add_option("--x", fit_options.abscissa,
                  "the data's abscissa column (e.g. CU1@1); the run's curve is interpolated there")
      ->capture_default_str();
  fit->add_option("--scale", fit_options.scales,
                  "COLUMN=S: the residual of COLUMN is (model - measured)/S (default: the "
                  "column's largest |measured value|), comma-separated")
      ->delimiter(',');
  fit->add_option("--loss", fit_options.loss,
                  "none, or a robust loss on each scaled residual: huber, cauchy or soft_l1, "
                  "with :S its scale (default 1)")
      ->capture_default_str();
  fit->add_option("--method", fit_options.method, "trust-region strategy")
      ->check(CLI::IsMember({"lm", "dogleg"}))
      ->capture_default_str();
  fit->add_option("--max-iterations", fit_options.max_iterations, "Ceres iterations at most")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  fit->add_option("--jobs", fit_options.jobs, "runs at once (default: one per core)")
      ->check(CLI::Range(1, 1024));
  fit->add_option("--work", fit_options.work_dir,
                  "directory for the deck copies, their runs and the fit's tables (default: "
                  "<job>.fit)");
  fit->add_flag("--quiet", fit_options.quiet,
                "print the result only, not the iterations and what was written");

  clinch::ReportOptions report_options;
  CLI::App* report = app.add_subcommand(
      "report",
      "Write a self-contained HTML page (plots inlined, opens offline) for a run directory: "
      "per connector the parts of each component's force against its motion (Abaqus names), "
      "time histories with step names, the Newton convergence "
      "of each increment with cutbacks marked, golden overlays with the tolerance band and the "
      "worst deviation, a study's work-precision plot, and a fit's measured and fitted "
      "curves; exit 0 = written, 3 = usage or I/O error");
  report->add_option("RUN_DIR", report_options.run_dir, "directory a `clinch run` wrote")
      ->required();
  report->add_option("--job", report_options.job,
                     "job name (default: the only <job>.history.csv in RUN_DIR)");
  report->add_option("--golden", report_options.golden, "golden history table to overlay");
  report
      ->add_option("--rtol", report_options.rtol,
                   "relative tolerance of the golden band (as `clinch compare`)")
      ->check(tolerance)
      ->capture_default_str();
  report
      ->add_option("--atol", report_options.atol,
                   "absolute tolerance of the golden band (as `clinch compare`)")
      ->check(tolerance)
      ->capture_default_str();
  report->add_option("--study", report_options.study, "a <job>.study.csv of `clinch study`");
  report->add_option("--fit", report_options.fit,
                     "a <job>.fit-curves.csv of `clinch fit`: the measured curves with the model "
                     "before and after the fit");
  report
      ->add_option("--connectors", report_options.max_connectors,
                   "draw the first N connectors and nodes of the history table")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  report
      ->add_option("--elements", report_options.elements,
                   "draw these connectors and nodes (labels as the history names them, "
                   "comma-separated; default: all, or the most loaded when there are more than "
                   "--connectors)")
      ->delimiter(',');
  report
      ->add_option("--components", report_options.components,
                   "draw these components (1-6, comma-separated; default: every component that "
                   "carries force or moves)")
      ->delimiter(',')
      ->check(CLI::Range(1, 6));
  report
      ->add_option("--variables", report_options.variables,
                   "draw these variables (CTF, CEF, CSF, CRF, CU, ...; Abaqus names such as CTM "
                   "or CUR too; comma-separated; default: all)")
      ->delimiter(',');
  report->add_option("--output,-o", report_options.output,
                     "the page to write (default: RUN_DIR/<job>.report.html)");
  report->add_flag("--quiet", report_options.quiet, "print nothing but warnings and errors");

  clinch::KeywordsOptions keywords_options;
  std::string keywords_format = "text";
  CLI::App* keywords = app.add_subcommand(
      "keywords",
      "Print what the deck language supports, from the keyword registry: every keyword, or "
      "one with its parameters and allowed values, data lines and what is refused and why; "
      "exit 0 = printed, 1 = NAME is not a keyword clinch knows, 3 = usage or I/O error");
  keywords->add_option("NAME", keywords_options.name,
                       "one keyword, with or without '*', in any case (e.g. 'connector section')");
  keywords->add_option("--format", keywords_format,
                       "text, or markdown (the form of docs/keywords.md)")
      ->check(CLI::IsMember({"text", "markdown"}))
      ->capture_default_str();

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 3;
  }
  if (run->parsed()) {
    run_options.solver = solver == "cholmod"   ? clinch::SolverChoice::Cholmod
                         : solver == "umfpack" ? clinch::SolverChoice::Umfpack
                         : solver == "dense"   ? clinch::SolverChoice::Dense
                         : solver == "petsc"   ? clinch::SolverChoice::Petsc
                                               : clinch::SolverChoice::Automatic;
    run_options.labels =
        labels == "abaqus" ? clinch::LabelStyle::Abaqus : clinch::LabelStyle::Clinch;
    return clinch::run_deck(run_options);
  }
  if (check->parsed()) {
    return clinch::run_check(
        deck, format == "json" ? clinch::DiagnosticFormat::Json : clinch::DiagnosticFormat::Text);
  }
  if (compare->parsed()) return clinch::run_compare(compare_arguments);
  if (study->parsed()) return clinch::run_study(study_options);
  if (fit->parsed()) return clinch::run_fit(fit_options);
  if (report->parsed()) return clinch::run_report(report_options);
  if (keywords->parsed()) {
    keywords_options.format = keywords_format == "markdown" ? clinch::KeywordsFormat::Markdown
                                                            : clinch::KeywordsFormat::Text;
    return clinch::run_keywords(keywords_options);
  }
  return 3;
}

}  // namespace

int main(int argc, char** argv) {
  // A write past the file-size limit (ulimit -f) then fails with EFBIG, and the output's own error
  // path reports which file could not be written (exit 3, cli-contract.md), instead of SIGXFSZ
  // ending the process without a word.
  std::signal(SIGXFSZ, SIG_IGN);
  clinch::keep_freed_heap_for_reuse();
  clinch::use_huge_pages(argv);
  const int status = run_command_line(argc, argv);
  // Output that did not reach standard output (a full disk, /dev/full) is an I/O error, whatever
  // the command found (cli-contract.md: exit 3).
  return clinch::standard_output_written() ? status : 3;
}
