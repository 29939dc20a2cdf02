// Queries on the derived components, potentials and potential owners of one behaviour block:
// keyword names for messages, the grouping of derived-component terms by name, and the contexts
// in which a derived component is evaluated (derived-components-and-potentials.md §4), which the
// CDERF/CDERU output checks and the history writer use. Valid after validation.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "src/model/behavior_model.hpp"

namespace clinch {

// "*CONNECTOR PLASTICITY", "*CONNECTOR FRICTION", ...
const char* owner_keyword(PotentialOwner::Kind kind);

// Index of the first term named `key` (Name::key identity), or −1.
std::int32_t find_derived_component(const ConnectorBehavior& behavior, std::string_view key);
// The first term of every derived component, in deck order of first definition (the order of a
// bare CDERF/CDERU request, §4).
std::vector<std::int32_t> derived_component_first_terms(const ConnectorBehavior& behavior);
// Every term named `key`, in deck order.
std::vector<std::int32_t> derived_component_terms(const ConnectorBehavior& behavior,
                                                  std::string_view key);

// Where a derived component is evaluated (§4): on forces (plasticity, friction, CONTACT FORCE,
// damage initiation with CRITERION=FORCE) or on relative motions (damage initiation with
// CRITERION=MOTION, damage evolution).
enum class DerivedContextKind : std::uint8_t {
  PlasticityPotential,
  FrictionPotential,
  ContactForce,
  DamageForcePotential,
  DamageMotionPotential,
};
bool is_force_context(DerivedContextKind kind);

struct DerivedComponentUse {
  DerivedContextKind kind = DerivedContextKind::PlasticityPotential;
  SourceLoc loc;                // the potential data line, or the CONTACT FORCE value
  std::int32_t owner = -1;      // index into ConnectorBehavior::potential_owners
  std::int32_t friction = -1;   // friction definition (friction potential, CONTACT FORCE)
  std::int32_t potential = -1;  // potential (−1 for CONTACT FORCE)
  std::int32_t contribution = -1;
};

// The uses of derived component `key` in deck order. Only potentials attached to an owner count.
std::vector<DerivedComponentUse> derived_component_uses(const ConnectorBehavior& behavior,
                                                        std::string_view key);
// The first use in a force (force = true) or motion context: what CDERF-<name> (CDERU-<name>)
// reports. nullopt when there is none: a request for it is `cder-no-context`.
std::optional<DerivedComponentUse> first_derived_context(const ConnectorBehavior& behavior,
                                                         std::string_view key, bool force);
bool derived_has_force_context(const ConnectorBehavior& behavior, std::string_view key);
bool derived_has_motion_context(const ConnectorBehavior& behavior, std::string_view key);
// The derived components a bare CDERF (force = true) or CDERU request reports: the first term of
// each derived component with a context of that kind, in deck order of first definition (§4).
std::vector<std::int32_t> derived_output_terms(const ConnectorBehavior& behavior, bool force);
// Number of contexts of that kind, a potential counting once (more than one: the `cder-multiple-contexts` note of §4).
std::size_t derived_context_count(const ConnectorBehavior& behavior, std::string_view key,
                                  bool force);

}  // namespace clinch
