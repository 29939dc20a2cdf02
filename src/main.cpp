// The clinch command line (cli-contract.md): `run`, `check` and `compare`. Usage errors exit
// with 3.
#include <iostream>

#include <CLI/CLI.hpp>

#include "src/cli/check_command.hpp"
#include "src/cli/compare_command.hpp"
#include "src/cli/huge_pages.hpp"
#include "src/cli/run_command.hpp"

int main(int argc, char** argv) {
  clinch::use_huge_pages(argv);
  CLI::App app{"clinch: implicit analysis of connector elements from Abaqus-style keyword decks"};
  app.set_version_flag("--version", std::string("clinch ") + CLINCH_VERSION);
  app.require_subcommand(1);

  clinch::RunCommandOptions run_options;
  std::string solver = "auto";
  CLI::App* run = app.add_subcommand(
      "run", "Run every step of a deck; writes <job>.history.csv, <job>.sta and <job>.log; exit "
             "0 = completed, 1 = deck errors (nothing run), 2 = stopped early (also by SIGINT or "
             "SIGTERM, which keep every converged increment), 3 = usage or I/O error (an output "
             "that cannot be written stops the run)");
  run->add_option("DECK", run_options.deck, "the deck (.inp), or - for standard input")
      ->required();
  run->add_option("--out", run_options.out_dir, "output directory (created if missing)")
      ->capture_default_str();
  run->add_option("--job", run_options.job,
                  "job name, a file name without '/' (default: the deck's name without .inp; "
                  "stdin for -)");
  run->add_flag("--quiet", run_options.quiet, "print nothing but warnings and errors");
  run->add_flag("--check-tangent", run_options.check_tangent,
                "compare the assembled tangent with finite differences of the residual at the "
                "first iteration of each increment and log the worst entries (small decks)");
  run->add_option("--solver", solver,
                  "linear solver: auto (CHOLMOD for SPD systems, UMFPACK otherwise), cholmod, "
                  "umfpack or dense")
      ->check(CLI::IsMember({"auto", "cholmod", "umfpack", "dense"}))
      ->capture_default_str();

  std::string deck;
  std::string format = "text";
  CLI::App* check = app.add_subcommand(
      "check", "Parse and validate a deck (syntax, parameters, references, connector rules, "
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
  const CLI::Validator tolerance(
      [](std::string& text) { return clinch::check_tolerance(text); }, "TOLERANCE");
  compare->add_option("--rtol", compare_arguments.rtol, "relative tolerance")
      ->check(tolerance)
      ->capture_default_str();
  compare->add_option("--atol", compare_arguments.atol, "absolute tolerance")
      ->check(tolerance)
      ->capture_default_str();
  compare->add_option("--columns", compare_arguments.columns,
                      "compare only the golden columns whose whole name matches this "
                      "regular expression (RE2 syntax; default: all)");

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
                                               : clinch::SolverChoice::Automatic;
    return clinch::run_deck(run_options);
  }
  if (check->parsed()) {
    return clinch::run_check(deck, format == "json" ? clinch::DiagnosticFormat::Json
                                                    : clinch::DiagnosticFormat::Text);
  }
  if (compare->parsed()) return clinch::run_compare(compare_arguments);
  return 3;
}
