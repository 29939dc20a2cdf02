// Factorization floor of the implicit solver (ARCHITECTURE.md "Performance by design"): CHOLMOD
// numeric factorization plus one solve on the 7-point Laplacian of an N³ lattice, with the
// analysis (ordering) done once outside the timed loop, as Newton does.
#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <string>

#include "src/linalg/cholmod_solver.hpp"
#include "tests/support/model_problems.hpp"

namespace clinch {
namespace {

void BM_CholmodFactorizeSolve(benchmark::State& state) {
  const SparseMatrix k = laplacian_3d(static_cast<int>(state.range(0)));
  CholmodSolver solver;
  std::string message;
  if (solver.analyze(k, &message) != LinearStatus::Ok) {
    state.SkipWithError(message.c_str());
    return;
  }
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(k.n);
  Eigen::VectorXd x;
  for (auto _ : state) {
    if (solver.factorize(k, &message) != LinearStatus::Ok ||
        solver.solve(b, x, &message) != LinearStatus::Ok) {
      state.SkipWithError(message.c_str());
      return;
    }
    benchmark::DoNotOptimize(x.data());
  }
  state.counters["unknowns"] = k.n;
  for (const auto& trial : solver.ordering_trials()) {
    state.counters[std::string("nnz_L_") + trial.ordering] = trial.factor_nonzeros;
  }
  state.SetLabel(std::string("ordering ") + solver.ordering());
}
BENCHMARK(BM_CholmodFactorizeSolve)->Arg(20)->Arg(30)->Arg(40)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace clinch

BENCHMARK_MAIN();
