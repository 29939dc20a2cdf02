// History column names in clinch's form and in Abaqus's (output-variables.md §1.1): clinch names a
// rotational connector component by its number (CTF4, CU6), Abaqus by a letter of its own and the
// axis (CTM1, CUR3). One mapping, from the request aliases of src/model/output_variables.*, serves
// `clinch compare` (a golden in either form), `clinch run --labels abaqus`, the report and the log;
// with it go what a column means and what kind of quantity it holds, for plot labels and for the
// scales of `clinch study`.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace clinch {

enum class LabelStyle : std::uint8_t { Clinch, Abaqus };

// "CTM1" → "CTF4", "CUR3" → "CU6", "CDMGR2" → "CDMG5"; any other label as it is.
std::string canonical_label(std::string_view label);
// "CTF4" → "CTM1", "CU6" → "CUR3"; any other label (CTF1, CDMG, U1) as it is.
std::string abaqus_label(std::string_view label);

// A variable without its component: "CTM" → "CTF", "CUR" → "CU", "UR" → "U", "RM" → "RF",
// "ctf" → "CTF"; others as they are, in capitals.
std::string canonical_variable(std::string_view variable);

// The same on a column name `<LABEL>@<where>` (the part after the first '@' is kept as it is).
std::string canonical_column_name(std::string_view name);
std::string abaqus_column_name(std::string_view name);
std::string column_name_in(std::string_view name, LabelStyle style);

// What a column holds, for scales and plot axes: forces and moments are measured against the
// largest force of the model, motions against the largest motion.
enum class Quantity : std::uint8_t {
  Force,         // CTF1, CEF2, RF3, CDERF-…, S11
  Moment,        // CTF4 (CTM1), RM1
  Displacement,  // CU1, CUP2, U3, E11
  Rotation,      // CU4 (CUR1), UR2
  Ratio,         // damage, initiation criteria: dimensionless
  Status,        // CSLST, CSLIPST: codes
  Rate,          // V1, VR2, A3, AR1: nodal velocities and accelerations
  Other,         // a name clinch does not write
};
Quantity column_quantity(std::string_view name);
bool is_force_like(Quantity q);   // Force or Moment
bool is_motion_like(Quantity q);  // Displacement or Rotation

const char* quantity_name(Quantity q);  // "force", "moment", "displacement", ...

// A history column as the report shows it: its canonical variable and component ("CTF", 4 for
// CTF4@7 and CTM1@7; "U", 5 for UR2@3; 0 for a scalar), the derived component's "-name", where it
// is, its Abaqus name, meaning and quantity.
struct ColumnDescription {
  std::string variable;
  int component = 0;
  std::string derived;
  std::string where;
  std::string abaqus_name;
  std::string meaning;
  Quantity quantity = Quantity::Ratio;
};
ColumnDescription describe_column(std::string_view name);

// What a label means, in Abaqus's words: "CTF1" → "total force in direction 1", "CTF4" (or
// "CTM1") → "total moment about axis 1", "CU6" → "relative rotation about axis 3", "CDMG" →
// "overall damage". The label alone when it is not a known one.
std::string label_meaning(std::string_view label);

}  // namespace clinch
