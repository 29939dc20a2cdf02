// Parameter readers shared by *RIGID BODY and the coupling keywords (rigid_body.cpp,
// coupling.cpp): a node-or-set parameter (REF NODE=) and a set-name parameter (ELSET=,
// PIN NSET=, ...), as references in the current scope.
#pragma once

#include <optional>
#include <string_view>

#include "src/model/references.hpp"

namespace clinch {

class BlockContext;

// The value of `param` as a set name (a bare label is an error); nullopt when absent or bad.
std::optional<TargetRef> set_param(BlockContext& ctx, std::string_view param, bool element_set);
// The value of `param` as a node label or node set; nullopt when absent or bad.
std::optional<TargetRef> node_param(BlockContext& ctx, std::string_view param);

}  // namespace clinch
