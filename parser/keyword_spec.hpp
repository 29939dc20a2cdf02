// Declarative description of a keyword: its class (supported, no effect, not supported), where it
// may appear (input-syntax.md §8), its parameters and how its data lines are read. The generic
// parameter checks (unknown, duplicate, abbreviated, missing, flag/value, enumerations:
// input-syntax.md §2) run from this description before a handler sees the block
// (parser/reader/keyword_checks.hpp).
#pragma once

#include <initializer_list>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "parser/lexer.hpp"

namespace clinch {

class KeywordHandler;

enum class ParamKind {
  Flag,         // NAME alone (a value is E0207)
  FlagOrYesNo,  // NAME alone = YES, or NAME=YES/NO
  Value,        // NAME=value of any text (checked by the handler)
  Enum,         // NAME=one of `values` (case- and blank-insensitive, unique prefixes accepted)
  OptionalValue,  // NAME or NAME=value (e.g. DIRECT, DIRECT=NO STOP)
};

struct ParamSpec {
  std::string_view name;  // canonical spelling, e.g. "TIME INTERVAL"
  ParamKind kind = ParamKind::Value;
  bool required = false;
  std::vector<std::string_view> values = {};  // for Enum (canonical spellings)
};

enum class KeywordClass { Supported, NoEffect, NotSupported };

// Where a keyword may stand (input-syntax.md §8 table).
enum class KeywordLevel {
  Anywhere,        // *PARAMETER, *INCLUDE
  Model,           // model data, outside part/assembly (behaviours, amplitude model form…)
  ModelGeometry,   // model data inside a part or the assembly (or anywhere in a flat deck)
  ModelOrHistory,  // *AMPLITUDE, *BOUNDARY, *CONNECTOR MOTION
  History,         // inside a step
  Block,           // *PART, *ASSEMBLY, *INSTANCE and their ends, *STEP, *END STEP
};

enum class DataMode {
  None,    // no data lines: a data line is E0307
  Fields,  // data lines split into fields
  Raw,     // raw text lines (*HEADING, *STEP description, *PARAMETER)
  Skip,    // lines are skipped (no-effect and unsupported keywords)
};

struct KeywordSpec {
  std::string_view name;  // canonical, e.g. "CONNECTOR SECTION"
  KeywordClass keyword_class = KeywordClass::Supported;
  KeywordLevel level = KeywordLevel::Model;
  DataMode data = DataMode::Fields;
  std::vector<ParamSpec> params = {};
  // Creates the handler for one block; null for keywords without semantics (no-effect ones).
  std::unique_ptr<KeywordHandler> (*make_handler)() = nullptr;
  // Accept any parameter without E0203 (no-effect keywords are checked loosely, §2.2).
  bool loose_params = false;
  // A sub-option of *CONNECTOR BEHAVIOR (behaviors.md §2): valid only inside an open behaviour
  // block; any other keyword (except *PARAMETER and *INCLUDE) closes the block.
  bool behavior_suboption = false;
  // A sub-option of *MATERIAL (*ELASTIC, *DENSITY, ...): valid only right after the *MATERIAL
  // line or another of its sub-options.
  bool material_suboption = false;
  // *KINEMATIC and *DISTRIBUTING: valid only right after a *COUPLING line.
  bool coupling_suboption = false;
  // Outside a behaviour block this keyword means something clinch does not support (*FRICTION
  // of surface contact): E0202 instead of E0608.
  bool unsupported_outside_behavior = false;
  // A step procedure clinch does not run (*FREQUENCY, *DYNAMIC, ...): its refusal stands for the
  // step, which is not reported again as a step without a procedure.
  bool refused_procedure = false;
  // No-effect keywords: parameters that would change the analysis (*RESTART, READ); any of them
  // makes the keyword E0210 with `refused_reason` instead of W0201.
  std::vector<std::string_view> refused_params = {};
  std::string_view refused_reason = {};
};

// The validated parameters of one keyword line.
class ParamSet {
 public:
  struct Entry {
    const ParamSpec* spec;
    const KeywordParam* param;
    std::string enum_value;  // canonical enumeration value after abbreviation expansion
  };
  void add(Entry entry) { entries_.push_back(std::move(entry)); }
  bool has(std::string_view canonical_name) const { return find(canonical_name) != nullptr; }
  const Entry* find(std::string_view canonical_name) const;
  // The value field of a parameter given with a value, or nullptr.
  const Field* value(std::string_view canonical_name) const;
  // The canonical enum value ("" when absent).
  std::string_view enum_value(std::string_view canonical_name) const;
  // Location of the parameter's name, or of its value if `at_value` (invalid if absent).
  SourceLoc loc(std::string_view canonical_name, bool at_value = false) const;
  // FlagOrYesNo: true for NAME or NAME=YES; `fallback` when absent.
  bool flag(std::string_view canonical_name, bool fallback = false) const;
  const std::vector<Entry>& entries() const { return entries_; }

 private:
  std::vector<Entry> entries_;
};

}  // namespace clinch
