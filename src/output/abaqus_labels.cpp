#include "src/output/abaqus_labels.hpp"

#include <array>
#include <cctype>

#include "src/model/output_variables.hpp"

namespace clinch {
namespace {

// A label split as "CTF" + 4, "CDERF" + "-normal", "CDMG" (no number).
struct SplitLabel {
  std::string_view base;
  int number = 0;  // 0: none
  std::string_view rest;  // "-name" of a derived component, or what follows the digits
};

SplitLabel split(std::string_view label) {
  SplitLabel s;
  std::size_t i = 0;
  while (i < label.size() && std::isalpha(static_cast<unsigned char>(label[i]))) ++i;
  s.base = label.substr(0, i);
  std::size_t digits = i;
  while (digits < label.size() && std::isdigit(static_cast<unsigned char>(label[digits]))) ++digits;
  if (digits > i && digits - i <= 2) {
    for (std::size_t k = i; k < digits; ++k) s.number = s.number * 10 + (label[k] - '0');
    i = digits;
  }
  s.rest = label.substr(i);
  return s;
}

std::string join(std::string_view base, int number, std::string_view rest) {
  std::string out(base);
  if (number > 0) out += std::to_string(number);
  out += rest;
  return out;
}

std::string with_where(std::string label, std::string_view name, std::size_t at) {
  if (at != std::string_view::npos) label += name.substr(at);
  return label;
}

// What each canonical variable is (output-variables.md §2, §3), its words for a translational and
// a rotational component, and its quantity.
struct VariableWords {
  std::string_view variable;
  std::string_view translational, rotational;
  Quantity quantity;  // of a translational component (the rotational one follows)
};
constexpr std::array<VariableWords, 39> kWords{{
    {"CTF", "total force", "total moment", Quantity::Force},
    {"CEF", "elastic force", "elastic moment", Quantity::Force},
    {"CVF", "viscous (damping) force", "viscous (damping) moment", Quantity::Force},
    {"CSF", "friction force", "friction moment", Quantity::Force},
    {"CRF", "reaction force (constraint, stop, lock or motion)",
     "reaction moment (constraint, stop, lock or motion)", Quantity::Force},
    {"CCF", "applied connector force", "applied connector moment", Quantity::Force},
    {"CNF", "friction-generating contact force", "friction-generating contact moment",
     Quantity::Force},
    {"CALPHAF", "kinematic hardening shift force", "kinematic hardening shift moment",
     Quantity::Force},
    {"CSFC", "friction force in the slip direction", "", Quantity::Force},
    {"CNFC", "contact force of the coupled friction", "", Quantity::Force},
    {"CDERF", "derived force", "", Quantity::Force},
    {"RF", "reaction force", "reaction moment", Quantity::Force},
    {"CF", "concentrated force", "concentrated moment", Quantity::Force},
    {"S", "spring or dashpot force", "", Quantity::Force},
    {"CU", "relative displacement", "relative rotation", Quantity::Displacement},
    {"CCU", "constitutive displacement", "constitutive rotation", Quantity::Displacement},
    {"CP", "relative position", "relative angle", Quantity::Displacement},
    {"CUE", "elastic displacement", "elastic rotation", Quantity::Displacement},
    {"CUP", "plastic displacement", "plastic rotation", Quantity::Displacement},
    {"CUPEQ", "equivalent plastic motion", "equivalent plastic rotation", Quantity::Displacement},
    {"CUPEQC", "equivalent plastic motion of the coupled plasticity", "", Quantity::Displacement},
    {"CASU", "accumulated slip", "accumulated slip (rotation)", Quantity::Displacement},
    {"CASUC", "accumulated slip in the slip direction", "", Quantity::Displacement},
    {"CDERU", "derived motion", "", Quantity::Displacement},
    {"CV", "relative velocity", "relative angular velocity", Quantity::Displacement},
    {"CA", "relative acceleration", "relative angular acceleration", Quantity::Displacement},
    {"U", "displacement", "rotation", Quantity::Displacement},
    {"V", "velocity", "angular velocity", Quantity::Rate},
    {"A", "acceleration", "angular acceleration", Quantity::Rate},
    {"E", "spring or dashpot elongation", "", Quantity::Displacement},
    {"CDMG", "overall damage", "overall damage", Quantity::Ratio},
    {"CDIF", "force-based damage initiation criterion",
     "force-based damage initiation criterion", Quantity::Ratio},
    {"CDIFC", "force-based damage initiation criterion in the slip direction", "",
     Quantity::Ratio},
    {"CDIM", "motion-based damage initiation criterion",
     "motion-based damage initiation criterion", Quantity::Ratio},
    {"CDIMC", "motion-based damage initiation criterion in the slip direction", "",
     Quantity::Ratio},
    {"CDIP", "plastic-motion-based damage initiation criterion",
     "plastic-motion-based damage initiation criterion", Quantity::Ratio},
    {"CDIPC", "plastic-motion-based damage initiation criterion in the slip direction", "",
     Quantity::Ratio},
    {"CSLST", "stop/lock status", "stop/lock status", Quantity::Status},
    {"CSLIPST", "stick/slip status", "stick/slip status", Quantity::Status},
}};

const VariableWords* words_of(std::string_view variable) {
  for (const VariableWords& w : kWords) {
    if (w.variable == variable) return &w;
  }
  return nullptr;
}

// The canonical variable and component of a label: "CTM1" → CTF 4, "UR2" → U 5, "RM1" → RF 4,
// "S11" → S 0, "CDMG" → CDMG 0.
struct Canonical {
  std::string variable;
  int component = 0;
  std::string rest;
};

Canonical canonical_parts(std::string_view label) {
  const SplitLabel s = split(canonical_label(label));
  Canonical c{std::string(s.base), s.number, std::string(s.rest)};
  if (c.variable == "S" || c.variable == "E") c.component = 0;  // S11, E11: one component
  // Nodal rotations (output-variables.md §3): UR2 is component 5 of U.
  for (auto [rotational, variable] : std::array<std::pair<std::string_view, std::string_view>, 5>{
           {{"UR", "U"}, {"RM", "RF"}, {"CM", "CF"}, {"VR", "V"}, {"AR", "A"}}}) {
    if (c.variable == rotational) {
      c.variable = std::string(variable);
      if (c.component > 0) c.component += 3;
    }
  }
  return c;
}

}  // namespace

std::string canonical_label(std::string_view label) {
  const SplitLabel s = split(label);
  if (s.number >= 1 && s.number <= 3 && s.rest.empty()) {
    for (const OutputAlias& a : rotation_aliases()) {
      if (a.alias == s.base) return join(a.canonical, s.number + 3, s.rest);
    }
  }
  return std::string(label);
}

std::string abaqus_label(std::string_view label) {
  const SplitLabel s = split(label);
  if (s.number >= 4 && s.number <= 6 && s.rest.empty()) {
    for (const OutputAlias& a : rotation_aliases()) {
      if (a.canonical == s.base) return join(a.alias, s.number - 3, s.rest);
    }
  }
  return std::string(label);
}

std::string canonical_variable(std::string_view variable) {
  std::string v(variable);
  for (char& c : v) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const OutputAlias& a : rotation_aliases()) {
    if (a.alias == v) return std::string(a.canonical);
  }
  if (v == "UR") return "U";  // nodal rotations, reactions and loads (output-variables.md §3)
  if (v == "RM") return "RF";
  if (v == "CM") return "CF";
  if (v == "VR") return "V";
  if (v == "AR") return "A";
  return v;
}

std::string canonical_column_name(std::string_view name) {
  const std::size_t at = name.find('@');
  return with_where(canonical_label(name.substr(0, at)), name, at);
}

std::string abaqus_column_name(std::string_view name) {
  const std::size_t at = name.find('@');
  return with_where(abaqus_label(name.substr(0, at)), name, at);
}

std::string column_name_in(std::string_view name, LabelStyle style) {
  return style == LabelStyle::Abaqus ? abaqus_column_name(name) : std::string(name);
}

Quantity column_quantity(std::string_view name) {
  const Canonical c = canonical_parts(name.substr(0, name.find('@')));
  const VariableWords* w = words_of(c.variable);
  if (w == nullptr) return Quantity::Other;
  if (c.component >= 4) {
    if (w->quantity == Quantity::Force) return Quantity::Moment;
    if (w->quantity == Quantity::Displacement) return Quantity::Rotation;
  }
  return w->quantity;
}

bool is_force_like(Quantity q) { return q == Quantity::Force || q == Quantity::Moment; }
bool is_motion_like(Quantity q) { return q == Quantity::Displacement || q == Quantity::Rotation; }

std::string label_meaning(std::string_view label) {
  const Canonical c = canonical_parts(label);
  const VariableWords* w = words_of(c.variable);
  if (w == nullptr) return std::string(label);
  const bool rotational = c.component >= 4 && !w->rotational.empty();
  std::string text(rotational ? w->rotational : w->translational);
  if (c.variable == "CDERF" || c.variable == "CDERU") {
    text += " " + (c.rest.empty() ? std::string() : c.rest.substr(1));
  } else if (c.component >= 1 && c.component <= 3) {
    text += " in direction " + std::to_string(c.component);
  } else if (c.component >= 4) {
    text += " about axis " + std::to_string(c.component - 3);
  }
  return text;
}

const char* quantity_name(Quantity q) {
  switch (q) {
    case Quantity::Force:
      return "force";
    case Quantity::Moment:
      return "moment";
    case Quantity::Displacement:
      return "displacement";
    case Quantity::Rotation:
      return "rotation";
    case Quantity::Ratio:
      return "ratio";
    case Quantity::Status:
      return "status";
    case Quantity::Rate:
      return "rate";
    case Quantity::Other:
      return "other";
  }
  return "";
}

ColumnDescription describe_column(std::string_view name) {
  const std::size_t at = name.find('@');
  const std::string_view label = name.substr(0, at);
  const Canonical c = canonical_parts(label);
  ColumnDescription d;
  d.variable = c.variable;
  d.component = c.component;
  d.derived = c.rest;
  if (at != std::string_view::npos) d.where = std::string(name.substr(at + 1));
  d.abaqus_name = abaqus_column_name(name);
  d.meaning = label_meaning(label);
  d.quantity = column_quantity(name);
  return d;
}

}  // namespace clinch
