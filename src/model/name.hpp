// Names of sets, sections, orientations, behaviours, amplitudes, parts, instances and steps
// (input-syntax.md §4): unquoted names are case-insensitive (identity = upper-cased text), quoted
// names are case-sensitive (identity = exact text); messages show the defining spelling.
#pragma once

#include <string>

#include "base/source_location.hpp"

namespace clinch {

struct Name {
  std::string key;      // identity used for lookup
  std::string display;  // spelling as written
  SourceLoc loc;
  bool empty() const { return key.empty(); }
};

// Identity of a name as written (quoted or not).
std::string name_key(const std::string& text, bool quoted);

}  // namespace clinch
