// `clinch run DECK.inp [--out DIR] [--job NAME] [--labels clinch|abaqus]` (cli-contract.md): read and validate the deck,
// build the analysis plan, run every step, and write <job>.history.csv, <job>.sta and <job>.log.
// Exit 0 completed, 1 deck errors (nothing run), 2 stopped early, 3 usage or I/O error.
#pragma once

#include <optional>
#include <string>

#include "src/linalg/linear_solver.hpp"
#include "src/output/abaqus_labels.hpp"

namespace clinch {

struct RunCommandOptions {
  std::string deck;
  std::string out_dir = ".";
  std::optional<std::string> job;  // unset: the deck's file name without .inp
  bool quiet = false;
  bool check_tangent = false;
  SolverChoice solver = SolverChoice::Automatic;
  LabelStyle labels = LabelStyle::Clinch;  // --labels: how the history columns are named
};

int run_deck(const RunCommandOptions& options);

}  // namespace clinch
