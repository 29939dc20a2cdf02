// References from data fields to nodes, elements and sets (node-or-set, element-or-set fields,
// input-syntax.md §3.2 and §7.3). They are recorded while reading and resolved once the model
// data is complete (src/resolve/reference_lookup.hpp), because labels may refer to definitions
// later in the file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/source_location.hpp"

namespace clinch {

struct Model;

struct TargetRef {
  bool is_label = false;
  std::int32_t label = 0;
  std::string set_key;  // set identity (input-syntax.md §4) when !is_label
  std::string set_display;
  std::string instance_key;  // qualifier "Inst." (empty: none)
  std::string instance_display;
  SourceLoc loc;
  std::int32_t part = 0;  // scope where the reference was written (0: flat model or assembly)
};

// The display of a reference for messages: "node 12", "element set 'W1'", "Inst.12".
std::string describe(const TargetRef& ref, bool element);

// Column-name qualifier of a global node/element: "12" or "Part-1-1.12" (cli-contract.md).
std::string qualified_label(const Model& model, std::int32_t instance, std::int32_t label);

}  // namespace clinch
