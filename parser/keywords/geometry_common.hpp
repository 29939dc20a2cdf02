// Helpers shared by the geometry keyword handlers (*NODE, *ELEMENT, *NSET, *ELSET, parts).
#pragma once

#include <optional>

#include "parser/keyword_spec.hpp"
#include "src/model/references.hpp"
#include "src/model/geometry.hpp"

namespace clinch {

class BlockContext;

// The set `name` of a part, created if new (input-syntax.md §7.4: an existing set is extended).
Set& define_set(Part& part, bool element_set, const Name& name);

// The ELSET= value as an element-set reference in the current scope (a set name, possibly
// instance-qualified at assembly level; a bare label is not a set); nullopt when absent or bad.
std::optional<TargetRef> elset_param(BlockContext& ctx);

KeywordSpec node_keyword_spec();
KeywordSpec element_keyword_spec();
KeywordSpec nset_keyword_spec();
KeywordSpec elset_keyword_spec();
std::vector<KeywordSpec> part_assembly_keyword_specs();

}  // namespace clinch
