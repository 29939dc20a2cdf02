// The clinch command line (cli-contract.md): `check` today; `run` and `compare` arrive with the
// solver. Usage errors exit with 3.
#include <iostream>

#include <CLI/CLI.hpp>

#include "src/cli/check_command.hpp"

int main(int argc, char** argv) {
  CLI::App app{"clinch: implicit analysis of connector elements from Abaqus-style keyword decks"};
  app.set_version_flag("--version", std::string("clinch ") + CLINCH_VERSION);
  app.require_subcommand(1);

  std::string deck;
  std::string format = "text";
  CLI::App* check = app.add_subcommand(
      "check", "Parse and validate a deck (syntax, parameters, references, connector rules, "
               "steps) without solving; exit 0 = no errors, 1 = errors, 3 = usage or I/O error");
  check->add_option("DECK", deck, "the deck (.inp)")->required();
  check->add_option("--format", format, "diagnostic format: text (stderr) or json (stdout)")
      ->check(CLI::IsMember({"text", "json"}));

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
  if (check->parsed()) {
    return clinch::run_check(deck, format == "json" ? clinch::DiagnosticFormat::Json
                                                    : clinch::DiagnosticFormat::Text);
  }
  return 3;
}
