// Helpers shared by the geometry keyword handlers (*NODE, *ELEMENT, *NSET, *ELSET, parts).
#pragma once

#include "parser/keyword_spec.hpp"
#include "src/model/geometry.hpp"

namespace clinch {

// The set `name` of a part, created if new (input-syntax.md §7.4: an existing set is extended).
Set& define_set(Part& part, bool element_set, const Name& name);

KeywordSpec node_keyword_spec();
KeywordSpec element_keyword_spec();
KeywordSpec nset_keyword_spec();
KeywordSpec elset_keyword_spec();
std::vector<KeywordSpec> part_assembly_keyword_specs();

}  // namespace clinch
