// The family of derived components, potentials and friction: the specs of
// derived_component.cpp, potential.cpp and friction.cpp.
#include "parser/keywords/keyword_families.hpp"
#include "parser/keywords/potential_friction_specs.hpp"

namespace clinch {

std::vector<KeywordSpec> potential_friction_keyword_specs() {
  std::vector<KeywordSpec> specs;
  specs.push_back(derived_component_keyword_spec());
  specs.push_back(potential_keyword_spec());
  for (KeywordSpec& spec : friction_keyword_specs()) specs.push_back(std::move(spec));
  return specs;
}

}  // namespace clinch
