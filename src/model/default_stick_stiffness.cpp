#include "src/model/default_stick_stiffness.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>
#include <vector>

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

std::string describe_stick_stiffness(const DefaultStickStiffness& stiffness, ComponentMask j) {
  std::vector<std::pair<double, std::string>> groups;
  for (int c = 1; c <= 6; ++c) {
    if (!has_component(j, c)) continue;
    const double value = stiffness.value[static_cast<std::size_t>(c - 1)];
    auto it = std::find_if(groups.begin(), groups.end(),
                           [&](const auto& g) { return g.first == value; });
    if (it == groups.end()) {
      groups.push_back({value, std::to_string(c)});
    } else {
      it->second += ", " + std::to_string(c);
    }
  }
  std::string values;
  for (const auto& [value, components] : groups) {
    if (!values.empty()) values += "; ";
    values += fmt::format("{:.6g} for component{} {}", value,
                          components.find(',') == std::string::npos ? "" : "s", components);
  }
  return values;
}

std::optional<std::string> default_stick_stiffness_summary(const BehaviorModel& model) {
  // A large model may have many behaviours: the first few name the values, a count the rest.
  constexpr int kListed = 4;
  std::string listed;
  int count = 0;
  for (const ConnectorBehavior& b : model.behaviors) {
    for (const FrictionDefinition& f : b.frictions) {
      if (f.stick_stiffness || f.friction_components == 0) continue;
      if (++count > kListed) continue;
      listed += fmt::format("{}behavior '{}': {}", listed.empty() ? "" : "; ", b.name.display,
                            describe_stick_stiffness(default_stick_stiffness(b),
                                                     f.friction_components));
    }
  }
  if (count == 0) return std::nullopt;
  return fmt::format(
      "friction: STICK STIFFNESS omitted in {} *CONNECTOR FRICTION definition{}, so the stick "
      "stiffness is 1000 times the connector's elastic stiffness (friction.md §5): {}{}",
      count, count == 1 ? "" : "s", listed,
      count > kListed ? fmt::format("; and {} more", count - kListed) : "");
}

}  // namespace clinch
