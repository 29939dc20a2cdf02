#include "parser/keywords/behavior_option_common.hpp"

#include <fmt/format.h>

#include "parser/expression.hpp"

namespace clinch {

ConnectorBehavior* current_behavior(BlockContext& ctx) {
  auto& behaviors = ctx.model().behaviors.behaviors;
  if (!ctx.position().in_behavior || behaviors.empty()) return nullptr;
  ConnectorBehavior& last = behaviors.back();
  // The last behaviour belongs to the open block only if it was created from that block's
  // keyword line (a rejected *CONNECTOR BEHAVIOR line creates nothing).
  if (!(last.loc == ctx.position().behavior_loc)) return nullptr;
  return &last;
}

std::optional<int> component_field(BlockContext& ctx, const Field& field, std::string_view what) {
  std::optional<std::int64_t> value = ctx.integer(field, what);
  if (!value) return std::nullopt;
  if (*value < 1 || *value > 6) {
    // behaviors.md §1.1: out of 1–6 is an error where the option is read.
    ctx.report(DiagCode::value_out_of_range, field,
               fmt::format("component {} is out of range (components are 1-6)", *value));
    return std::nullopt;
  }
  return static_cast<int>(*value);
}

std::optional<int> component_param(BlockContext& ctx, std::string_view param) {
  const Field* field = ctx.params().value(param);
  if (!field) return 0;
  if (field->empty()) {
    ctx.report(DiagCode::parameter_needs_value, ctx.params().loc(param),
               fmt::format("parameter '{}' needs a component number", param));
    return std::nullopt;
  }
  return component_field(ctx, *field, param);
}

std::optional<int> component_or_all_param(BlockContext& ctx, std::string_view param) {
  const Field* field = ctx.params().value(param);
  if (!field) return 0;
  if (!field->parameter && fold_name(field->text) == "ALL") return 0;
  if (field->parameter && field->parameter->kind == ParamValue::Kind::String &&
      fold_name(field->parameter->s) == "ALL") {
    return 0;
  }
  return component_field(ctx, *field, param);
}

void warn_explicit_only(BlockContext& ctx, std::initializer_list<std::string_view> names) {
  for (std::string_view name : names) {
    if (!ctx.params().has(name)) continue;
    ctx.report(DiagCode::explicit_only_parameter, ctx.params().loc(name),
               fmt::format("{} applies only to Abaqus/Explicit; ignored", name));
  }
}

bool check_dependencies(BlockContext& ctx, std::string_view what) {
  if (!ctx.params().value("DEPENDENCIES")) return true;
  std::optional<std::int64_t> n = ctx.integer_param("DEPENDENCIES");
  if (!n) return false;
  const Field& field = *ctx.params().value("DEPENDENCIES");
  if (*n < 0) {
    ctx.report(DiagCode::value_out_of_range, field,
               fmt::format("DEPENDENCIES must be 0 or more, got {}", *n));
    return false;
  }
  if (*n > 0) {
    ctx.report(DiagCode::unsupported_dependencies, field,
               fmt::format("field-variable-dependent {} data (DEPENDENCIES={}) is not supported",
                           what, *n));
    return false;
  }
  return true;
}

Extrapolation option_extrapolation(BlockContext& ctx, const ConnectorBehavior& behavior) {
  std::string_view own = ctx.params().enum_value("EXTRAPOLATION");
  std::string_view value = own.empty() ? std::string_view(behavior.extrapolation) : own;
  return value == "LINEAR" ? Extrapolation::Linear : Extrapolation::Constant;
}

bool DependenceColumns::check_row(BlockContext& ctx, const std::vector<Field>& fields) {
  if (rejected_) return false;
  if (temperature_column_ < fields.size() && !fields[temperature_column_].empty()) {
    const Field& field = fields[temperature_column_];
    std::optional<double> t = ctx.real(field, "temperature");
    if (!t) return false;
    if (!temperature_) {
      temperature_ = *t;
      temperature_text_ = field.text;
      temperature_loc_ = field.loc;
    } else if (*t != *temperature_) {
      varies_ = true;
      rejected_ = true;
      ctx.report(DiagCode::unsupported_dependencies, field,
                 fmt::format("temperature-dependent {} data is not supported (temperature {} "
                             "after {})",
                             what_, field.text, temperature_text_));
      return false;
    }
  }
  for (std::size_t k = temperature_column_ + 1;
       k <= temperature_column_ + field_columns_ && k < fields.size(); ++k) {
    if (fields[k].empty()) continue;
    rejected_ = true;
    ctx.report(DiagCode::unsupported_dependencies, fields[k],
               fmt::format("field-variable-dependent {} data is not supported (field variable "
                           "{} is given)",
                           what_, k - temperature_column_));
    return false;
  }
  return true;
}

void DependenceColumns::finish(BlockContext& ctx) {
  if (!temperature_ || rejected_) return;
  ctx.report(DiagCode::temperature_ignored, temperature_loc_,
             fmt::format("temperature {} is ignored: {} data do not depend on temperature in "
                         "clinch",
                         temperature_text_, what_));
}

std::optional<double> required_real(BlockContext& ctx, const DataLine& line,
                                    const std::vector<Field>& fields, std::size_t index,
                                    std::string_view what) {
  if (index >= fields.size()) {
    ctx.missing(BlockContext::end_of_line(line), what);
    return std::nullopt;
  }
  if (fields[index].empty()) {
    ctx.missing(fields[index].loc, what);
    return std::nullopt;
  }
  return ctx.real(fields[index], what);
}

std::optional<double> optional_real(BlockContext& ctx, const std::vector<Field>& fields,
                                    std::size_t index, std::string_view what, bool* bad) {
  if (bad) *bad = false;
  if (index >= fields.size() || fields[index].empty()) return std::nullopt;
  std::optional<double> value = ctx.real(fields[index], what);
  if (!value && bad) *bad = true;
  return value;
}

void report_extra_line(BlockContext& ctx, const DataLine& line, std::string_view layout) {
  ctx.report(DiagCode::unexpected_data_line, line.loc,
             fmt::format("{} takes one data line ({})", ctx.keyword_display(), layout));
}

void report_missing_data(BlockContext& ctx, std::string_view layout) {
  ctx.report(DiagCode::missing_data_line, ctx.keyword().loc,
             fmt::format("{} needs a data line ({})", ctx.keyword_display(), layout));
}

ParamSpec component_param_spec(bool required) {
  return ParamSpec{"COMPONENT", ParamKind::Value, required};
}

ParamSpec extrapolation_param_spec() {
  return ParamSpec{"EXTRAPOLATION", ParamKind::Enum, false, {"CONSTANT", "LINEAR"}};
}

std::vector<ParamSpec> regularize_param_specs() {
  return {ParamSpec{"REGULARIZE", ParamKind::Enum, false, {"ON", "OFF"}},
          ParamSpec{"RTOL", ParamKind::Value}};
}

std::vector<ParamSpec> rate_param_specs() {
  return {ParamSpec{"RATE FILTER FACTOR", ParamKind::Value},
          ParamSpec{"RATE INTERPOLATION", ParamKind::Value}};
}

KeywordSpec behavior_suboption_spec(std::string_view name, std::vector<ParamSpec> params,
                                    std::unique_ptr<KeywordHandler> (*make)(), DataMode data) {
  KeywordSpec spec;
  spec.name = name;
  spec.level = KeywordLevel::Model;
  spec.data = data;
  spec.params = std::move(params);
  spec.make_handler = make;
  spec.behavior_suboption = true;
  return spec;
}

}  // namespace clinch
