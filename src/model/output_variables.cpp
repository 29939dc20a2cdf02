#include "src/model/output_variables.hpp"

#include <array>
#include <cctype>

#include "base/suggest.hpp"

namespace clinch {
namespace {

constexpr std::uint8_t kTranslations = 0b000111;
constexpr std::uint8_t kRotations = 0b111000;
constexpr std::uint8_t kAll = 0b111111;

// Connector variables of output-variables.md §2 and §5 (CV, CA), with their producers.
constexpr std::array<OutputVariableInfo, 30> kVariables{{
    {"CTF", OutputKind::Connector, OutputProducer::Always, ""},
    {"CEF", OutputKind::Connector, OutputProducer::Elasticity, "elasticity"},
    {"CVF", OutputKind::Connector, OutputProducer::Always, ""},
    {"CSF", OutputKind::Connector, OutputProducer::Friction, "friction"},
    {"CSFC", OutputKind::Connector, OutputProducer::Friction, "friction"},
    {"CRF", OutputKind::Connector, OutputProducer::Always, ""},
    {"CCF", OutputKind::Connector, OutputProducer::Always, ""},
    {"CNF", OutputKind::Connector, OutputProducer::Friction, "friction"},
    {"CNFC", OutputKind::Connector, OutputProducer::Friction, "friction"},
    {"CU", OutputKind::Connector, OutputProducer::Always, ""},
    {"CCU", OutputKind::Connector, OutputProducer::Always, ""},
    {"CP", OutputKind::Connector, OutputProducer::Always, ""},
    {"CUE", OutputKind::Connector, OutputProducer::Elasticity, "elasticity"},
    {"CUP", OutputKind::Connector, OutputProducer::Plasticity, "plasticity"},
    {"CUPEQ", OutputKind::Connector, OutputProducer::Plasticity, "plasticity"},
    {"CUPEQC", OutputKind::Connector, OutputProducer::Plasticity, "plasticity"},
    {"CALPHAF", OutputKind::Connector, OutputProducer::KinematicHardening, "kinematic hardening"},
    {"CDMG", OutputKind::Connector, OutputProducer::Damage, "damage"},
    {"CDIF", OutputKind::Connector, OutputProducer::ForceCriterion, "FORCE damage criterion"},
    {"CDIFC", OutputKind::Connector, OutputProducer::ForceCriterion, "FORCE damage criterion"},
    {"CDIM", OutputKind::Connector, OutputProducer::MotionCriterion, "MOTION damage criterion"},
    {"CDIMC", OutputKind::Connector, OutputProducer::MotionCriterion, "MOTION damage criterion"},
    {"CDIP", OutputKind::Connector, OutputProducer::PlasticMotionCriterion,
     "PLASTIC MOTION damage criterion"},
    {"CDIPC", OutputKind::Connector, OutputProducer::PlasticMotionCriterion,
     "PLASTIC MOTION damage criterion"},
    {"CSLST", OutputKind::Connector, OutputProducer::StopsOrLocks, "stops or locks"},
    {"CSLIPST", OutputKind::Connector, OutputProducer::Friction, "friction"},
    {"CASU", OutputKind::Connector, OutputProducer::Friction, "friction"},
    {"CASUC", OutputKind::Connector, OutputProducer::Friction, "friction"},
    {"CV", OutputKind::Connector, OutputProducer::StaticZero, ""},
    {"CA", OutputKind::Connector, OutputProducer::StaticZero, ""},
}};

constexpr std::array<OutputVariableInfo, 2> kDerived{{
    {"CDERF", OutputKind::Connector, OutputProducer::Derived, "derived components"},
    {"CDERU", OutputKind::Connector, OutputProducer::Derived, "derived components"},
}};

constexpr std::array<OutputVariableInfo, 14> kOther{{
    {"U", OutputKind::Nodal, OutputProducer::Always, ""},
    {"V", OutputKind::Nodal, OutputProducer::StaticZero, ""},
    {"A", OutputKind::Nodal, OutputProducer::StaticZero, ""},
    {"RF", OutputKind::Nodal, OutputProducer::Always, ""},
    {"CF", OutputKind::Nodal, OutputProducer::Always, ""},
    {"S", OutputKind::Spring, OutputProducer::Always, ""},
    {"E", OutputKind::Spring, OutputProducer::Always, ""},
    // Whole-model energies (energy_balance.hpp).
    {"ALLKE", OutputKind::Model, OutputProducer::StaticZero, ""},
    {"ALLIE", OutputKind::Model, OutputProducer::Always, ""},
    {"ALLFD", OutputKind::Model, OutputProducer::Always, ""},
    {"ALLVD", OutputKind::Model, OutputProducer::Always, ""},
    {"ALLSD", OutputKind::Model, OutputProducer::Always, ""},
    {"ALLWK", OutputKind::Model, OutputProducer::Always, ""},
    {"ETOTAL", OutputKind::Model, OutputProducer::Always, ""},
}};

// Variables that are one scalar column when no component is given (output-variables.md §1.2).
bool scalar_by_default(std::string_view v) {
  return v == "CDMG" || v == "CUPEQ" || v == "CDIF" || v == "CDIM" || v == "CDIP";
}
// Coupled forms: one column, no components.
bool is_coupled_form(std::string_view v) {
  return v == "CSFC" || v == "CNFC" || v == "CUPEQC" || v == "CDIFC" || v == "CDIMC" ||
         v == "CDIPC" || v == "CASUC";
}

// Rotational aliases accepted in requests (output-variables.md §1.1: c for CTM/CEM/CNM/CDMGR/
// CDIFR, b for the rest): the alias with n means component n + 3 of the canonical variable.
constexpr std::array<OutputAlias, 19> kRotationAliases{{
    {"CTM", "CTF"},         {"CEM", "CEF"},    {"CVM", "CVF"},    {"CSM", "CSF"},
    {"CRM", "CRF"},         {"CCM", "CCF"},    {"CNM", "CNF"},    {"CUR", "CU"},
    {"CCUR", "CCU"},        {"CPR", "CP"},     {"CURE", "CUE"},   {"CURP", "CUP"},
    {"CALPHAM", "CALPHAF"}, {"CDMGR", "CDMG"}, {"CDIFR", "CDIF"}, {"CDIMR", "CDIM"},
    {"CDIPR", "CDIP"},      {"CVR", "CV"},     {"CAR", "CA"},
}};

// Nodal names (output-variables.md §3): name → canonical variable and DOF mask; the numbered
// forms (U1, UR2, …) add 0 or 3 to the number.
struct NodalName {
  std::string_view name, canonical;
  std::uint8_t mask;
  int offset;  // numbered form: DOF = offset + n
};
constexpr std::array<NodalName, 14> kNodalNames{{
    {"U", "U", kAll, 0},
    {"UT", "U", kTranslations, -1},
    {"UR", "U", kRotations, 3},
    {"V", "V", kAll, 0},
    {"VT", "V", kTranslations, -1},
    {"VR", "V", kRotations, 3},
    {"A", "A", kAll, 0},
    {"AT", "A", kTranslations, -1},
    {"AR", "A", kRotations, 3},
    {"RF", "RF", kAll, 0},
    {"RT", "RF", kTranslations, -1},
    {"RM", "RF", kRotations, 3},
    {"CF", "CF", kAll, 0},
    {"CM", "CF", kRotations, 3},
}};

// Known identifiers that clinch v1 does not support (output-variables.md §5), and the Abaqus and
// CalculiX identifiers keywords.md §18 names (velocities, accelerations, temperatures, energies,
// stresses and strains of continuum elements): E0904, not "unknown".
constexpr std::array<std::string_view, 34> kUnsupported{{
    "NT", "PN", "MF", "TF", "POR", "NFORC",
    "ENER", "ELSE", "EVOL", "PEEQ", "SDV", "COORD", "ELEN", "ELKE", "ELPD", "ELSD", "ESEDEN",
    "SENER", "MISES", "LE", "PE", "NE", "SF", "SM",
    "CUF",
    "CIVC",
    "ALLSE",
    "ALLPD",
    "ALLAE",
    "ALLCD",
    "ALLDMD",
    "ALLSD",
    "ALLEE",
    "ALLCCE",
}};

std::string upper(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

const OutputVariableInfo* find_in(std::string_view name) {
  for (const auto& v : kVariables) {
    if (v.name == name) return &v;
  }
  for (const auto& v : kDerived) {
    if (v.name == name) return &v;
  }
  for (const auto& v : kOther) {
    if (v.name == name) return &v;
  }
  return nullptr;
}

// "CTF12" → ("CTF", 12); false without trailing digits or when all is digits.
bool split_number(std::string_view text, std::string_view& base, int& number) {
  std::size_t end = text.size();
  std::size_t start = end;
  while (start > 0 && std::isdigit(static_cast<unsigned char>(text[start - 1]))) --start;
  if (start == end || start == 0 || end - start > 2) return false;
  base = text.substr(0, start);
  number = 0;
  for (std::size_t i = start; i < end; ++i) number = number * 10 + (text[i] - '0');
  return true;
}

bool accepts(OutputKind kind, OutputContext context) {
  switch (context) {
    case OutputContext::NodeOutput:
    case OutputContext::NodePrint:
      return kind == OutputKind::Nodal;
    case OutputContext::ElementOutput:
    case OutputContext::ElPrint:
      return kind == OutputKind::Connector || kind == OutputKind::Spring;
    case OutputContext::EnergyOutput:
      return kind == OutputKind::Model;
  }
  return false;
}

std::vector<std::string> candidates(OutputContext context) {
  std::vector<std::string> out;
  const bool nodal = context == OutputContext::NodeOutput || context == OutputContext::NodePrint;
  if (nodal) {
    for (const auto& n : kNodalNames) out.emplace_back(n.name);
    return out;
  }
  if (context == OutputContext::EnergyOutput) {
    for (const auto& v : kOther) {
      if (v.kind == OutputKind::Model) out.emplace_back(v.name);
    }
    return out;
  }
  for (const auto& v : kVariables) out.emplace_back(v.name);
  for (const auto& v : kDerived) out.emplace_back(v.name);
  for (const auto& a : kRotationAliases) out.emplace_back(a.alias);
  out.emplace_back("S");
  out.emplace_back("E");
  return out;
}

IdentifierParse classify(std::string_view text) {
  IdentifierParse result;
  const std::string u = upper(text);
  OutputIdentifier& id = result.id;
  id.text = std::string(text);

  // CDERF-<name>, CDERU-<name> (derived-components-and-potentials.md §4).
  for (const auto& d : kDerived) {
    std::string prefix = std::string(d.name) + "-";
    if (u.size() > prefix.size() && u.compare(0, prefix.size(), prefix) == 0) {
      id.variable = std::string(d.name);
      id.derived_name = std::string(text.substr(prefix.size()));
      result.info = &d;
      result.status = IdentifierStatus::Ok;
      return result;
    }
  }

  auto ok = [&](const OutputVariableInfo* info, std::uint8_t mask, bool explicit_component) {
    id.variable = std::string(info->name);
    id.components = mask;
    id.explicit_component = explicit_component;
    result.info = info;
    result.status = IdentifierStatus::Ok;
    return result;
  };

  // Nodal names, bare and numbered.
  for (const auto& n : kNodalNames) {
    if (u == n.name) return ok(find_in(n.canonical), n.mask, false);
  }
  std::string_view base;
  int number = 0;
  const bool numbered = split_number(u, base, number);
  if (numbered) {
    for (const auto& n : kNodalNames) {
      if (base != n.name || n.offset < 0 || number < 1 || number > 3) continue;
      return ok(find_in(n.canonical), static_cast<std::uint8_t>(1u << (n.offset + number - 1)),
                true);
    }
  }

  // Springs: S, E and their only component S11, E11 (keywords.md §17, clinch).
  if (u == "S" || u == "E" || u == "S11" || u == "E11") {
    return ok(find_in(u.substr(0, 1)), 0b1, u.size() > 1);
  }

  // Whole-model energies: one scalar each.
  if (const OutputVariableInfo* info = find_in(u); info && info->kind == OutputKind::Model) {
    return ok(info, 0, false);
  }
  // Connector variables, bare.
  if (const OutputVariableInfo* info = find_in(u); info && info->kind == OutputKind::Connector) {
    if (is_coupled_form(u) || scalar_by_default(u)) return ok(info, 0, false);
    return ok(info, kAll, false);
  }
  for (const auto& a : kRotationAliases) {
    if (u == a.alias) return ok(find_in(a.canonical), kRotations, false);
  }
  // Numbered connector variables and aliases.
  if (numbered) {
    if (const OutputVariableInfo* info = find_in(base);
        info && info->kind == OutputKind::Connector && !is_coupled_form(base) &&
        info->producer != OutputProducer::Derived && number >= 1 && number <= 6) {
      return ok(info, static_cast<std::uint8_t>(1u << (number - 1)), true);
    }
    for (const auto& a : kRotationAliases) {
      if (base == a.alias && number >= 1 && number <= 3) {
        return ok(find_in(a.canonical), static_cast<std::uint8_t>(1u << (number + 2)), true);
      }
    }
  }

  for (std::string_view name : kUnsupported) {
    if (u == name || (numbered && base == name)) {
      result.status = IdentifierStatus::Unsupported;
      return result;
    }
  }
  result.status = IdentifierStatus::Unknown;
  return result;
}

}  // namespace

IdentifierParse parse_output_identifier(std::string_view text, OutputContext context) {
  IdentifierParse result = classify(text);
  if (result.status == IdentifierStatus::Ok && !accepts(result.info->kind, context)) {
    result.status = IdentifierStatus::WrongKind;
    const OutputKind kind = result.info->kind;
    const bool print = context == OutputContext::NodePrint || context == OutputContext::ElPrint;
    result.kind_hint = kind == OutputKind::Nodal   ? "a nodal"
                       : kind == OutputKind::Model ? "a whole-model"
                                                   : "an element";
    result.request_with = kind == OutputKind::Model   ? "*ENERGY OUTPUT"
                          : kind == OutputKind::Nodal ? (print ? "*NODE PRINT" : "*NODE OUTPUT")
                                                      : (print ? "*EL PRINT" : "*ELEMENT OUTPUT");
    result.info = nullptr;
    return result;
  }
  if (result.status == IdentifierStatus::Ok) {
    // *NODE PRINT: U and RF are translations only, as CalculiX prints them (keywords.md §18).
    if (context == OutputContext::NodePrint && !result.id.explicit_component) {
      const std::string u = upper(text);
      if (u == "U" || u == "RF") result.id.components = kTranslations;
    }
    return result;
  }
  if (result.status == IdentifierStatus::Unknown) {
    std::vector<std::string> names = candidates(context);
    if (auto guess = closest_match(upper(text), names)) result.suggestion = *guess;
  }
  return result;
}

std::span<const OutputAlias> rotation_aliases() { return kRotationAliases; }

const OutputVariableInfo* output_variable_info(std::string_view canonical) {
  return find_in(canonical);
}

std::string output_column_label(std::string_view variable, int component,
                                std::string_view derived_display) {
  std::string v(variable);
  if (v == "CDERF" || v == "CDERU") return v + "-" + std::string(derived_display);
  if (component == 0) return v;
  if (v == "S" || v == "E") return v + "11";
  if (v == "U" || v == "RF" || v == "CF" || v == "V" || v == "A") {
    if (component <= 3) return v + std::to_string(component);
    const char* rotational = v == "U"    ? "UR"
                             : v == "RF" ? "RM"
                             : v == "CF" ? "CM"
                             : v == "V"  ? "VR"
                                         : "AR";
    return std::string(rotational) + std::to_string(component - 3);
  }
  return v + std::to_string(component);
}

}  // namespace clinch
