// Behaviour-update cost of coupled plasticity. The spot weld of derived-components-and-potentials.md §3 (BUSHING, six
// components, the elliptical potential with β = 1.5 through the `normal` and `shear` derived
// components) is integrated from the virgin state for a fixed set of trial motions that all yield,
// with the consistent tangent, as the assembly asks for it. An elastic variant (trial motions
// below yield) shows the cost of the yield check alone. Whole runs are the measure of speed
// (docs/benchmarks.md); these figures locate the update's share of them.
// scripts/bench_plastic.sh prints the medians of 5 repetitions and the ratios.
#include <benchmark/benchmark.h>

#include <fstream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "parser/deck_reader.hpp"
#include "base/diagnostic.hpp"
#include "parser/source_manager.hpp"
#include "src/behavior/potential/connector_potential.hpp"
#include "src/behavior/plastic/elastic_plastic_behavior.hpp"
#include "src/model/model.hpp"

namespace clinch {
namespace {

// The weld of decks/bench/spot_weld_behavior.inp on one BUSHING between coincident nodes.
constexpr const char* kConnector = R"(*NODE
1, 0., 0., 0.
2, 0., 0., 0.
*ELEMENT, TYPE=CONN3D2, ELSET=WELD
1, 1, 2
*ORIENTATION, NAME=GLOBAL
1., 0., 0., 0., 1., 0.
*CONNECTOR SECTION, ELSET=WELD, BEHAVIOR=weld
BUSHING,
GLOBAL
)";

// The weld's stiffnesses k1..k6 as the deck has them, and a variant with k2 = 2e5 and
// k5 = 1.6e6: its (f1, f2) and (m1, m2) groups then have unequal k C², so that the flow in them
// is not radial.
const Vector6 kStiffness = (Vector6() << 1e5, 1e5, 2e5, 1e6, 1e6, 5e5).finished();
const Vector6 kUnequalStiffness = (Vector6() << 1e5, 2e5, 2e5, 1e6, 1.6e6, 5e5).finished();

std::string spot_weld_deck(const Vector6& stiffness) {
  std::ifstream file(std::string(CLINCH_SOURCE_DIR) + "/decks/bench/spot_weld_behavior.inp");
  std::stringstream behavior;
  behavior << file.rdbuf();
  std::string text = behavior.str();
  for (int c = 0; c < 6; ++c) {
    const std::string key = "COMPONENT=" + std::to_string(c + 1) + "\n";
    const std::size_t at = text.find(key) + key.size();
    text.replace(at, text.find('\n', at) - at, std::to_string(stiffness[c]));
  }
  return kConnector + text + "*STEP\n*STATIC\n*END STEP\n";
}

struct SpotWeld {
  SourceManager sources;
  Model model;
  DiagnosticSink sink;
  std::unique_ptr<Behavior> behavior;
  explicit SpotWeld(const Vector6& stiffness) {
    read_deck_text("spot_weld.inp", spot_weld_deck(stiffness), sources, model, sink);
    if (sink.has_errors() || model.behaviors.behaviors.empty()) return;  // run() skips
    behavior = make_connector_behavior(model.behaviors.behaviors.front(), 0b111111);
  }
};

// Trial motions from the virgin state along random rays, scaled to `lo`…`hi` times the motion of
// first yield on the ray: P is positively homogeneous, so first yield is at F_y(0) / P(K u).
std::vector<Vector6> trial_motions(const ConnectorBehavior& behavior, const Vector6& stiffness,
                                   double lo, double hi) {
  const ConnectorPotential potential =
      ConnectorPotential::compile(behavior, behavior.potentials.at(0));
  constexpr double kInitialYield = 40000.0;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vector6> motions;
  while (motions.size() < 1024) {
    Vector6 u;
    for (int i = 0; i < 6; ++i) u[i] = 2.0 * unit(rng) - 1.0;
    const double p = potential.value(stiffness.cwiseProduct(u));
    if (p <= 0) continue;
    motions.push_back(u * ((lo + (hi - lo) * unit(rng)) * kInitialYield / p));
  }
  return motions;
}

void run(benchmark::State& state, double lo, double hi, const Vector6& stiffness = kStiffness) {
  SpotWeld weld(stiffness);
  if (!weld.behavior) {
    state.SkipWithError("no behaviour");
    return;
  }
  const std::vector<Vector6> motions =
      trial_motions(weld.model.behaviors.behaviors.at(0), stiffness, lo, hi);
  std::vector<double> history(static_cast<std::size_t>(weld.behavior->history_size()), 0.0);
  std::vector<double> trial(history.size());
  const Vector6 zero = Vector6::Zero();
  std::size_t n = 0;
  std::size_t failures = 0;
  for (auto _ : state) {
    const BehaviorInput in{zero, motions[n++ & 1023], 0, 0, history, TangentRequest::Consistent};
    BehaviorOutput out;
    out.history_new = trial;
    if (weld.behavior->integrate(in, out) != IntegrationStatus::Success) ++failures;
    benchmark::DoNotOptimize(out.tangent.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  state.counters["failures"] = static_cast<double>(failures);
}

// Motions of 2 to 20 times the first-yield motion along random rays: every update is plastic.
void BM_SpotWeldPlasticUpdate(benchmark::State& state) { run(state, 2.0, 20.0); }
void BM_SpotWeldNearYield(benchmark::State& state) { run(state, 1.05, 1.5); }
BENCHMARK(BM_SpotWeldNearYield);
// Motions of 1e-3 to 1e-2 of the first-yield motion: every update is elastic.
void BM_SpotWeldElasticUpdate(benchmark::State& state) { run(state, 1e-3, 1e-2); }
BENCHMARK(BM_SpotWeldPlasticUpdate);
BENCHMARK(BM_SpotWeldElasticUpdate);
// Plastic updates of the variant with unequal stiffnesses in its NORM groups.
void BM_SpotWeldUnequalStiffnessPlasticUpdate(benchmark::State& state) {
  run(state, 2.0, 20.0, kUnequalStiffness);
}
BENCHMARK(BM_SpotWeldUnequalStiffnessPlasticUpdate);

}  // namespace
}  // namespace clinch

BENCHMARK_MAIN();
