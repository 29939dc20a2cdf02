// Plain data for *MPC and *EQUATION as the deck writes them (docs/constraints.md "MPCs",
// "Equations"). The resolve stage (src/resolve/resolve_mpc_equations.cpp) turns them into the
// followers, linear constraints and links of constraint_model.hpp.
#pragma once

#include <cstdint>
#include <vector>

#include "base/source_location.hpp"
#include "src/model/references.hpp"

namespace clinch {

// One *MPC data line: `type, a, b`. The entries are nodes or node sets (the manual's "General
// multi-point constraints": a set first is matched entry by entry with a set second, or repeats
// a single node second).
struct MpcDefinition {
  enum class Type : std::uint8_t { Beam, Link, Pin, Tie };
  Type type = Type::Beam;
  SourceLoc loc;            // column 1 of the data line
  SourceLoc type_loc;       // the type field
  TargetRef first, second;  // a (dependent) and b (independent)
};

// One term of an *EQUATION as written.
struct EquationTermDefinition {
  TargetRef target;  // node or node set
  int dof = 0;       // 1…6 (2-D: 1, 2, 6, checked when resolved)
  double coefficient = 0;
  SourceLoc dof_loc, coefficient_loc;
};

// One equation: the line with its number of terms N and the N terms that follow.
struct EquationDefinition {
  SourceLoc count_loc;  // the N field
  std::vector<EquationTermDefinition> terms;
};

}  // namespace clinch
