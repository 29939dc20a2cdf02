// The catalogue of output identifiers (output-variables.md §2, §3, §5; keywords.md §17, §18):
// which identifiers each request keyword accepts, their aliases (CTM1 ≡ CTF4), which are scalar
// by default (CDMG), which behaviour produces them, and how a requested component becomes a
// history column name (`<LABEL>@<where>`, cli-contract.md). The output keyword handlers classify
// identifiers with it; resolve_history and the history writer expand requests with it.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "src/model/history_model.hpp"

namespace clinch {

// The request keyword an identifier stands under: each accepts its own set (§17, §18).
enum class OutputContext : std::uint8_t {
  NodeOutput,
  ElementOutput,
  NodePrint,
  ElPrint,
  EnergyOutput  // *ENERGY OUTPUT: whole-model energies (docs/dynamics.md "Energies")
};

// What makes a connector variable non-zero (output-variables.md §2 "prod."): a variable whose
// producer the element's behaviour lacks gives zero columns and `output-no-behavior`.
enum class OutputProducer : std::uint8_t {
  Always,
  Elasticity,
  Plasticity,
  KinematicHardening,
  Damage,
  ForceCriterion,
  MotionCriterion,
  PlasticMotionCriterion,
  StopsOrLocks,
  Friction,
  Derived,     // CDERF/CDERU: checked against the behaviour's derived components
  StaticZero,  // CV, CA: always 0 in a static step (W0904)
};

enum class OutputKind : std::uint8_t { Nodal, Connector, Spring, Model };

struct OutputVariableInfo {
  std::string_view name;  // canonical identifier ("CTF")
  OutputKind kind;
  OutputProducer producer;
  const char* producer_text;  // for messages: "friction", "plasticity", ...
};

enum class IdentifierStatus : std::uint8_t { Ok, Unknown, Unsupported, WrongKind };

struct IdentifierParse {
  IdentifierStatus status = IdentifierStatus::Unknown;
  OutputIdentifier id;                       // filled when Ok
  const OutputVariableInfo* info = nullptr;  // when Ok
  std::string suggestion;                    // Unknown: closest identifier ("" if none)
  std::string kind_hint;                     // WrongKind: "an element" / "a nodal"
  std::string_view request_with;             // WrongKind: the keyword that takes it
};

// Classifies one identifier written under `context`. `text` is the field as written.
IdentifierParse parse_output_identifier(std::string_view text, OutputContext context);

// Info of a canonical variable, or nullptr.
const OutputVariableInfo* output_variable_info(std::string_view canonical);

// Abaqus's separate letters for rotational components (output-variables.md §1.1): `alias` n is
// component n + 3 of `canonical` (CTM1 ≡ CTF4, CUR3 ≡ CU6).
struct OutputAlias {
  std::string_view alias, canonical;
};
std::span<const OutputAlias> rotation_aliases();

// Column label of component `component` (0 for a scalar) of canonical variable `variable`:
// "CTF4", "UR2", "RM1", "S11", "CDMG", "CDERF-normal" (`derived_display` for CDERF/CDERU).
std::string output_column_label(std::string_view variable, int component,
                                std::string_view derived_display = {});

}  // namespace clinch
