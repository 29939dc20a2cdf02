// The keyword specs of the derived-component, potential and friction keywords, one per file
// (derived_component.cpp, potential.cpp, friction.cpp); potential_friction.cpp gathers them into
// the family function of keyword_families.hpp.
#pragma once

#include <vector>

#include "parser/keyword_spec.hpp"

namespace clinch {

KeywordSpec derived_component_keyword_spec();  // *CONNECTOR DERIVED COMPONENT
KeywordSpec potential_keyword_spec();          // *CONNECTOR POTENTIAL
std::vector<KeywordSpec> friction_keyword_specs();  // *CONNECTOR FRICTION, *FRICTION

}  // namespace clinch
