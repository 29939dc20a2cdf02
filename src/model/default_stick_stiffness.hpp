// The stick stiffness of a *CONNECTOR FRICTION that omits STICK STIFFNESS (friction.md §5, a
// clinch rule): the friction law uses it, and the run log states it once so that golden
// comparisons can pin it (docs/decisions.md, "Friction").
#pragma once

#include <array>
#include <optional>
#include <string>

#include "src/model/behavior_model.hpp"
#include "src/model/section_model.hpp"

namespace clinch {

struct DefaultStickStiffness {
  std::array<double, 6> value{};  // k_j of components 1…6
  ComponentMask fallback = 0;     // components without an elasticity to scale from (1.0e6)
};

// k_j = 1000·K_ref,j, with K_ref,j the linear elastic stiffness of j in `behavior` (the diagonal
// of a coupled one), or else the largest one of the same kind (translational 1–3, rotational
// 4–6); 1.0e6 when there is none.
DefaultStickStiffness default_stick_stiffness(const ConnectorBehavior& behavior);

// "2e+06 for component 1; 1e+07 for components 4, 6": the values of `stiffness` on the components
// of `j`, those that share a value listed together.
std::string describe_stick_stiffness(const DefaultStickStiffness& stiffness, ComponentMask j);

// The one run-log line that states the stick stiffness of every friction definition of `model`
// that omits STICK STIFFNESS; none when every definition gives it.
std::optional<std::string> default_stick_stiffness_summary(const BehaviorModel& model);

}  // namespace clinch
