// `clinch fit DECK.inp [DECK2.inp ...] --data TEST.csv [--data ...] --vary NAME[=LO:HI],...
// [--x COLUMN] [--scale COLUMN=S,...] [--loss huber|cauchy|soft_l1[:S]] [--method lm|dogleg]
// [--max-iterations N] [--jobs J] [--work DIR] [--quiet]` (cli-contract.md, docs/fit.md):
// calibrates the deck's *PARAMETER values named by --vary against measured curves. With one deck
// every data file is compared with its run; with several decks (several rigs), the k-th data
// file with the k-th deck's run, and one parameter set serves them all. Prints the fitted values,
// standard errors, correlations, the residual per data file, runs and time; writes
// <deck>.fitted.inp beside each deck and <job>.fit.csv, <job>.fit-curves.csv into the work
// directory. Exit 0 = converged with every parameter determined by the data, 1 = a deck has
// errors (nothing was run), 2 = not converged, a parameter not determined, the runs at the
// deck's own values or at the fitted ones failed, or stopped by SIGINT/SIGTERM, 3 = usage or
// I/O error (bad --vary, a data column the run does not write, a missing file).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace clinch {

struct FitOptions {
  std::vector<std::string> decks;
  std::vector<std::string> data;
  std::vector<std::string> vary;  // NAME or NAME=LO:HI, either bound may be left out
  std::string abscissa = "total_time";
  std::vector<std::string> scales;  // COLUMN=S
  std::string loss = "none";        // none, huber, cauchy or soft_l1, with an optional :S
  std::string method = "lm";
  int max_iterations = 50;
  int jobs = 0;  // 0: one per core
  std::optional<std::string> work_dir;
  bool quiet = false;
};

int run_fit(const FitOptions& options);

}  // namespace clinch
