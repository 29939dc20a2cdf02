// Helpers shared by the handlers of the *CONNECTOR BEHAVIOR sub-options (behaviors.md §1–§8):
// finding the open behaviour, reading COMPONENT= style parameters, the explicit-only and
// dependence rules of §0 and §1.2, and the keyword-spec lists of each option file. Internal to
// parser/keywords/ (connector_behavior.cpp, elasticity.cpp, stop_lock.cpp, plasticity.cpp,
// damage.cpp) and the potential, derived-component and friction handlers.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "parser/block_context.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keyword_spec.hpp"
#include "src/model/behavior_model.hpp"

namespace clinch {

// The behaviour whose block is open, or null when that block's *CONNECTOR BEHAVIOR line was
// rejected by the generic parameter checks (its sub-options are then skipped: the keyword line
// already carries an error, and attaching them to an earlier behaviour would mislead).
ConnectorBehavior* current_behavior(BlockContext& ctx);

// A component number parameter (COMPONENT=): 1…6. Returns 0 when the parameter is absent and
// nullopt when the value is bad (reported: E0302, or E0308 at the value, behaviors.md §1.1).
std::optional<int> component_param(BlockContext& ctx, std::string_view param = "COMPONENT");
// LOCK= / RELEASE=: ALL (returned as 0, also the default) or a component number 1…6.
std::optional<int> component_or_all_param(BlockContext& ctx, std::string_view param);
// A component number in a data field (RIGID and AFFECTED COMPONENTS lines).
std::optional<int> component_field(BlockContext& ctx, const Field& field, std::string_view what);

// Warns `explicit-only-parameter` for each of `names` that is given (behaviors.md §0).
void warn_explicit_only(BlockContext& ctx, std::initializer_list<std::string_view> names);
// DEPENDENCIES=n: 0 is accepted; n > 0 is `unsupported-dependencies` (§1.2). False when rejected
// or unreadable.
bool check_dependencies(BlockContext& ctx, std::string_view what);
// The option's EXTRAPOLATION wins, then the behaviour's, then CONSTANT (§1.2).
Extrapolation option_extrapolation(BlockContext& ctx, const ConnectorBehavior& behavior);

// Temperature and field-variable columns of one option's data lines (§1.2): rows may share one
// temperature (ignored with `temperature-ignored`) or leave it blank; different temperatures or
// any field-variable value are `unsupported-dependencies`, reported once per option.
class DependenceColumns {
 public:
  DependenceColumns(std::size_t temperature_column, std::size_t field_columns, std::string what)
      : temperature_column_(temperature_column),
        field_columns_(field_columns),
        what_(std::move(what)) {}
  // Checks one row; false when it has unsupported dependence (or a bad temperature value).
  bool check_row(BlockContext& ctx, const std::vector<Field>& fields);
  // Whether some row had a temperature that differs from the first one.
  bool temperature_varies() const { return varies_; }
  bool rejected() const { return rejected_; }
  // Warns `temperature-ignored` once if a temperature was given and nothing was rejected.
  void finish(BlockContext& ctx);

 private:
  std::size_t temperature_column_;
  std::size_t field_columns_;
  std::string what_;
  std::optional<double> temperature_;
  std::string temperature_text_;
  SourceLoc temperature_loc_;
  bool rejected_ = false;
  bool varies_ = false;
};

// Reads a real field that must be present: E0305 at the field or the end of the line otherwise.
std::optional<double> required_real(BlockContext& ctx, const DataLine& line,
                                    const std::vector<Field>& fields, std::size_t index,
                                    std::string_view what);
// Reads an optional real field (blank or beyond the end of the line: nullopt, no report).
// `bad` is set when the field was present but not a number (reported).
std::optional<double> optional_real(BlockContext& ctx, const std::vector<Field>& fields,
                                    std::size_t index, std::string_view what, bool* bad);

// A second data line where an option takes one: `unexpected-data-line`, unless the dependence
// columns already explained it (different temperatures → `unsupported-dependencies`).
void report_extra_line(BlockContext& ctx, const DataLine& line, std::string_view layout);
// E0306 at the keyword line when an option that needs data lines has none.
void report_missing_data(BlockContext& ctx, std::string_view layout);

// Common parameter specs.
ParamSpec component_param_spec(bool required = false);
ParamSpec extrapolation_param_spec();
// REGULARIZE, RTOL (Explicit only).
std::vector<ParamSpec> regularize_param_specs();
// RATE FILTER FACTOR, RATE INTERPOLATION (Explicit only).
std::vector<ParamSpec> rate_param_specs();

// The spec of a behaviour sub-option (level Model, fields, behavior_suboption).
KeywordSpec behavior_suboption_spec(std::string_view name, std::vector<ParamSpec> params,
                                    std::unique_ptr<KeywordHandler> (*make)(),
                                    DataMode data = DataMode::Fields);

// Keyword specs of each option file (the behaviour family is their concatenation).
std::vector<KeywordSpec> elasticity_keyword_specs();
std::vector<KeywordSpec> stop_lock_keyword_specs();
std::vector<KeywordSpec> plasticity_keyword_specs();
std::vector<KeywordSpec> damage_keyword_specs();

}  // namespace clinch
