#include "src/model/default_stick_stiffness.hpp"

#include <algorithm>

namespace clinch {
namespace {

// The linear elastic stiffness of each component from the behaviour's *CONNECTOR ELASTICITY
// options: an uncoupled linear one, or the diagonal of a coupled one (behaviors.md §4).
std::array<double, 6> linear_stiffness(const ConnectorBehavior& behavior) {
  std::array<double, 6> k{};
  for (const ConnectorElasticity& e : behavior.elasticities) {
    if (!e.valid) continue;
    if (e.kind == ConnectorElasticity::Kind::Linear && e.component >= 1 && e.component <= 6) {
      k[static_cast<std::size_t>(e.component - 1)] = e.stiffness;
    } else if (e.kind == ConnectorElasticity::Kind::Coupled) {
      for (std::size_t i = 0; i < 6; ++i) k[i] = e.coupled[i][i];
    }
  }
  return k;
}

}  // namespace

DefaultStickStiffness default_stick_stiffness(const ConnectorBehavior& behavior) {
  const std::array<double, 6> k = linear_stiffness(behavior);
  double largest[2] = {0.0, 0.0};
  for (std::size_t i = 0; i < 6; ++i) largest[i / 3] = std::max(largest[i / 3], k[i]);
  DefaultStickStiffness out;
  for (std::size_t i = 0; i < 6; ++i) {
    const double ref = k[i] > 0.0 ? k[i] : largest[i / 3];
    if (ref > 0.0) {
      out.value[i] = 1000.0 * ref;
    } else {
      out.value[i] = 1.0e6;
      out.fallback |= component_bit(static_cast<int>(i) + 1);
    }
  }
  return out;
}

}  // namespace clinch
