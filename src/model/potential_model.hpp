// Plain data for *CONNECTOR POTENTIAL (derived-components-and-potentials.md §2). A potential
// belongs to the nearest preceding owner keyword of its behaviour block (§2.7); the reader
// records the attachment, validation resolves derived-component names and stores the
// contribution types P_N / P_S (§2.6) that the checks and the return mappings need.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/source_location.hpp"
#include "src/model/name.hpp"

namespace clinch {

enum class PotentialOperator : std::uint8_t { Sum, Max };
// H_i (§2.2): ABS (default), MACAULEY, NONE (identity).
enum class PotentialFunction : std::uint8_t { Abs, Macauley, None };
// Contribution type (§2.6): norm-type P_N or sum-type P_S.
enum class ContributionType : std::uint8_t { Norm, Sum };

const char* potential_function_name(PotentialFunction h);  // "ABS", "MACAULEY", "NONE"

// One data line: X_i = (E_i − a_i)/R_i, P_i = H_i(X_i), weighted by s_i (§2.3).
struct PotentialContribution {
  SourceLoc loc;                 // the data line (column 1)
  bool derived = false;          // field 1 names a derived component
  int component = 0;             // intrinsic component 1…6 when !derived
  Name derived_name;             // when derived (loc: field 1)
  SourceLoc source_loc;          // field 1
  std::int32_t first_term = -1;  // set by validation: first term of the derived component
  double scale = 1.0;            // R_i
  SourceLoc scale_loc;
  double alpha = 2.0;            // α_i (β when not given)
  bool alpha_given = false;
  SourceLoc alpha_loc;
  std::string alpha_text;        // as written, for messages
  PotentialFunction function = PotentialFunction::Abs;
  bool function_given = false;
  SourceLoc function_loc;
  double shift = 0.0;            // a_i
  double sign = 1.0;             // s_i (+1 or −1)
  SourceLoc sign_loc;
  bool valid = false;            // the line was read without error
  ContributionType type = ContributionType::Norm;  // set by validation (when resolved)
  bool type_known = false;
};

struct Potential {
  SourceLoc loc;                 // the keyword line
  PotentialOperator op = PotentialOperator::Sum;
  double exponent = 2.0;         // β
  bool exponent_given = false;
  SourceLoc exponent_loc;        // the EXPONENT value
  std::string exponent_text;
  std::vector<PotentialContribution> contributions;
  // Index into ConnectorBehavior::potential_owners; −1 when it could not be attached
  // (potential-no-owner, -not-allowed, -duplicate): then only its own data are checked.
  std::int32_t owner = -1;
  // Set by validation: the common contribution type (when all are known and equal).
  ContributionType type = ContributionType::Norm;
  bool mixed = false;
};

}  // namespace clinch
