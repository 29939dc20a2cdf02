// Plain data for *CONNECTOR DERIVED COMPONENT (derived-components-and-potentials.md §1). Each
// keyword occurrence is one term; the terms with the same NAME in one behaviour block add up to
// one derived component. The reader fills the terms; resolve_potentials_and_friction classifies
// them (§1.5). Which contexts use a name (§4) is answered by potential_queries.hpp.
#pragma once

#include <cstdint>
#include <vector>

#include "base/source_location.hpp"
#include "src/model/name.hpp"

namespace clinch {

// OPERATOR= of one term (§1.1); NORM is the default.
enum class DerivedOperator : std::uint8_t { Norm, MacauleySum, Sum };

// Type of a whole derived component (§1.5): g_S (only SUM terms), g_M (only MACAULEY SUM terms),
// g_N (NORM terms, possibly with MACAULEY SUM terms), or mixed (SUM with NORM/MACAULEY SUM).
enum class DerivedType : std::uint8_t { Sum, Macauley, Norm, Mixed };

struct DerivedComponentTerm {
  Name name;                       // NAME= (key: identity; display: as written; loc: the value)
  SourceLoc loc;                   // the keyword line
  DerivedOperator op = DerivedOperator::Norm;
  SourceLoc operator_loc;          // the OPERATOR parameter (invalid when defaulted)
  int sign = 1;                    // +1 POSITIVE, −1 NEGATIVE
  SourceLoc sign_loc;              // the SIGN parameter (invalid when defaulted)
  std::vector<int> components;     // k_j, 1…6
  std::vector<SourceLoc> component_locs;
  std::vector<double> coefficients;  // C_j, one per component
  bool complete = false;           // both data lines were read without error
  // Set by validation: the type of the whole derived component this term belongs to, and
  // whether any potential or CONTACT FORCE refers to its name.
  DerivedType component_type = DerivedType::Norm;
  bool referenced = false;
};

const char* derived_operator_name(DerivedOperator op);  // "NORM", "MACAULEY SUM", "SUM"
// "SUM" (g_S), "MACAULEY" (g_M), "NORM" (g_N), "MIXED".
const char* derived_type_name(DerivedType type);
// Classification of a list of terms (§1.5 table).
DerivedType classify_terms(const std::vector<const DerivedComponentTerm*>& terms);

}  // namespace clinch
