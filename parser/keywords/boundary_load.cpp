// *BOUNDARY, *CLOAD, *CONNECTOR MOTION and *CONNECTOR LOAD (keywords.md §9–§13). Each block
// becomes a ConditionBlock (OP, AMPLITUDE, FIXED, TYPE) and its data lines become entries that
// point at it, in the step or, for *BOUNDARY and *CONNECTOR MOTION, in model data (zero values
// only). Targets are resolved and DOFs/components checked against the model in resolve_history.
#include <fmt/format.h>

#include <cctype>
#include <cmath>

#include "base/fold_name.hpp"
#include "parser/keywords/history_keywords.hpp"

namespace clinch {
namespace {

// Named boundary types of keywords.md §9 and the DOFs they set to zero.
struct NamedBoundary {
  std::string_view name;
  std::uint8_t dofs;
};
constexpr NamedBoundary kNamedBoundaries[] = {
    {"ENCASTRE", 0b111111}, {"PINNED", 0b000111}, {"XSYMM", 0b110001},  {"YSYMM", 0b101010},
    {"ZSYMM", 0b011100},    {"XASYMM", 0b001110}, {"YASYMM", 0b010101}, {"ZASYMM", 0b100011},
};
constexpr std::string_view kNamedBoundaryNames[] = {"ENCASTRE", "PINNED", "XSYMM",  "YSYMM",
                                                    "ZSYMM",    "XASYMM", "YASYMM", "ZASYMM"};

std::uint8_t dof_range(int first, int last) {
  std::uint8_t mask = 0;
  for (int d = first; d <= last; ++d) mask = static_cast<std::uint8_t>(mask | (1u << (d - 1)));
  return mask;
}

class ConditionHandler : public KeywordHandler {
 public:
  explicit ConditionHandler(ConditionKind kind) : kind_(kind) {}

  void begin(BlockContext& ctx) override {
    const ParamSet& params = ctx.params();
    in_step_ = ctx.position().in_step;
    const std::string keyword = ctx.keyword_display();
    switch (kind_) {
      case ConditionKind::Boundary:
        skip_ = report_unsupported_params(ctx, {"USER", "SUBMODEL", "LOAD CASE", "REGION TYPE"});
        break;
      case ConditionKind::Load:
        skip_ = report_unsupported_params(
            ctx, {"FOLLOWER", "USER", "LOAD CASE", "CROSS SECTIONAL", "SUBMODEL", "SYSTEM"});
        break;
      case ConditionKind::Motion:
        skip_ = report_unsupported_params(ctx, {"USER"});
        break;
      case ConditionKind::ConnectorLoad:
        break;
      case ConditionKind::Gravity:
        skip_ = report_unsupported_params(ctx, {"FOLLOWER", "USER", "LOAD CASE", "ORIENTATION",
                                                "REF NODE", "CONSTANT RESULTANT", "SUBMODEL"});
        break;
    }
    const std::string_view type = params.enum_value("TYPE");
    // A dynamic step's *BOUNDARY (*CONNECTOR MOTION) may prescribe the velocity or the
    // acceleration of a DOF (a connector component); the *DYNAMIC line comes before the
    // conditions of its step.
    const bool rate_boundary = (type == "VELOCITY" || type == "ACCELERATION") && in_step_ &&
                               current_step(ctx).dynamic;
    if ((type == "VELOCITY" || type == "ACCELERATION") && !rate_boundary) {
      ctx.report(DiagCode::unsupported_option, params.loc("TYPE", true),
                 fmt::format("TYPE={} on {} is not supported by clinch outside a *DYNAMIC step "
                             "(static steps prescribe displacements)",
                             type, keyword));
      skip_ = true;
    }
    if (skip_) return;  // a rejected block defines nothing (and takes no part in W0805)
    ConditionBlock block;
    block.kind = kind_;
    block.loc = ctx.keyword().loc;
    block.op_new = params.enum_value("OP") == "NEW";
    block.fixed = params.has("FIXED");
    block.explicit_type = type == "DISPLACEMENT";
    block.rate_order = !rate_boundary ? 0 : type == "VELOCITY" ? 1 : 2;
    fixed_ = block.fixed;
    if (block.fixed && params.has("TYPE")) {
      ctx.report(DiagCode::conflicting_parameters, params.loc("FIXED"),
                 fmt::format("FIXED cannot be combined with TYPE on {}", keyword))
          .notes.push_back({params.loc("TYPE"), "TYPE given here"});
    }
    if (params.has("AMPLITUDE")) {
      if (auto name = ctx.name_param("AMPLITUDE")) block.amplitude = *name;
    }

    if (!in_step_) {
      // Model data (keywords.md §9, §11): zero values, no amplitude, no OP.
      if (params.has("AMPLITUDE")) {
        ctx.report(DiagCode::amplitude_in_model_data, params.loc("AMPLITUDE"),
                   fmt::format("AMPLITUDE cannot be used on model-data {}", keyword));
        block.amplitude = Name{};
      }
      if (params.has("OP")) {
        ctx.report(DiagCode::parameter_ignored, params.loc("OP"),
                   fmt::format("OP has no effect on model-data {}", keyword));
      }
      if (params.has("FIXED")) {
        ctx.report(
            DiagCode::parameter_ignored, params.loc("FIXED"),
            fmt::format("FIXED has no effect on model-data {} (its values are zero)", keyword));
      }
      block.op_new = false;
      HistoryModel& history = ctx.model().history;
      block_ = static_cast<std::int32_t>(history.model_blocks.size());
      history.model_blocks.push_back(std::move(block));
      return;
    }

    Step& step = current_step(ctx);
    // W0805: some blocks of this kind with OP=NEW and others without (§13). Reported once, at
    // the first block that makes the mix.
    bool has_new = false, has_mod = false;
    for (const ConditionBlock& other : step.blocks) {
      if (other.kind != kind_) continue;
      (other.op_new ? has_new : has_mod) = true;
    }
    if ((block.op_new && has_mod && !has_new) || (!block.op_new && has_new && !has_mod)) {
      ctx.report(DiagCode::mixed_op, block.loc,
                 fmt::format("mixed OP=NEW and OP=MOD on {} in one step; all are treated as "
                             "OP=NEW",
                             keyword));
    }
    block_ = static_cast<std::int32_t>(step.blocks.size());
    step.blocks.push_back(std::move(block));
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (skip_ || line.blank) return;
    switch (kind_) {
      case ConditionKind::Boundary:
        boundary_line(ctx, line, fields);
        break;
      case ConditionKind::Load:
        load_line(ctx, line, fields);
        break;
      case ConditionKind::Motion:
      case ConditionKind::ConnectorLoad:
        connector_line(ctx, line, fields);
        break;
      case ConditionKind::Gravity:
        gravity_line(ctx, line, fields);
        break;
    }
  }

 private:
  std::optional<TargetRef> read_target(BlockContext& ctx, const DataLine& line,
                                       const std::vector<Field>& fields, bool element) {
    if (fields.empty() || fields[0].empty()) {
      ctx.missing(fields.empty() ? line.loc : fields[0].loc,
                  element ? "element or element set" : "node or node set");
      return std::nullopt;
    }
    return ctx.target(fields[0], element ? "element" : "node");
  }

  // A DOF number 1–6 (keywords.md, DOF numbering: 7 and above are E0801 here).
  std::optional<int> read_dof(BlockContext& ctx, const Field& field, std::string_view what) {
    auto value = ctx.integer(field, what);
    if (!value) return std::nullopt;
    if (*value < 1 || *value > 6) {
      ctx.report(DiagCode::invalid_dof, field,
                 fmt::format("{} {} is not valid (DOFs are 1-6)", what, *value));
      return std::nullopt;
    }
    return static_cast<int>(*value);
  }

  // The magnitude field (blank → 0); model data accepts only zero (E0802).
  std::optional<double> read_magnitude(BlockContext& ctx, const std::vector<Field>& fields,
                                       std::size_t index, SourceLoc& loc) {
    if (index >= fields.size() || fields[index].empty()) return 0.0;
    auto value = ctx.real(fields[index], "the magnitude");
    if (!value) return std::nullopt;
    loc = fields[index].loc;
    if (fixed_ && in_step_) {
      if (!fixed_reported_) {
        fixed_reported_ = true;
        ctx.report(DiagCode::parameter_ignored, fields[index],
                   fmt::format("magnitude ignored with FIXED on {} (the value at the start of "
                               "the step is held)",
                               ctx.keyword_display()));
      }
      return 0.0;
    }
    if (!in_step_ && *value != 0) {
      ctx.report(DiagCode::nonzero_model_data_condition, fields[index],
                 fmt::format("non-zero {} in model data is not supported; prescribe it in the "
                             "first step",
                             ctx.keyword_display()));
      return std::nullopt;
    }
    return value;
  }

  void boundary_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    auto target = read_target(ctx, line, fields, false);
    BoundaryCondition bc;
    bc.block = block_;
    bc.loc = line.loc;
    if (fields.size() < 2 || fields[1].empty()) {
      ctx.missing(fields.size() < 2 ? BlockContext::end_of_line(line) : fields[1].loc, "first DOF");
      return;
    }
    const Field& second = fields[1];
    bc.dof_loc = second.loc;
    const bool named = !second.quoted && !second.text.empty() &&
                       std::isalpha(static_cast<unsigned char>(second.text[0]));
    if (named) {
      ctx.check_field_count(line, fields, 2, "node or node set, boundary type");
      auto word = ctx.word(second, kNamedBoundaryNames, "the boundary type");
      if (!word || !target) return;
      for (const NamedBoundary& nb : kNamedBoundaries) {
        if (nb.name == *word) bc.dofs = nb.dofs;
      }
      bc.named_type = *word;
    } else {
      ctx.check_field_count(line, fields, 4, "node or node set, first DOF, last DOF, magnitude");
      auto first = read_dof(ctx, second, "first DOF");
      std::optional<int> last = first;
      if (fields.size() > 2 && !fields[2].empty()) last = read_dof(ctx, fields[2], "last DOF");
      auto magnitude = read_magnitude(ctx, fields, 3, bc.magnitude_loc);
      if (!first || !last || !magnitude || !target) return;
      if (*first > *last) {
        ctx.report(DiagCode::invalid_dof, fields[2],
                   fmt::format("first DOF {} is greater than last DOF {}", *first, *last));
        return;
      }
      bc.first_dof = *first;
      bc.last_dof = *last;
      bc.dofs = dof_range(*first, *last);
      bc.magnitude = *magnitude;
    }
    bc.target = std::move(*target);
    HistoryModel& history = ctx.model().history;
    if (in_step_) {
      current_step(ctx).boundaries.push_back(std::move(bc));
    } else {
      history.model_boundaries.push_back(std::move(bc));
    }
  }

  void load_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    ctx.check_field_count(line, fields, 3, "node or node set, DOF, magnitude");
    auto target = read_target(ctx, line, fields, false);
    if (fields.size() < 2 || fields[1].empty()) {
      ctx.missing(fields.size() < 2 ? BlockContext::end_of_line(line) : fields[1].loc, "DOF");
      return;
    }
    ConcentratedLoad load;
    load.block = block_;
    load.loc = line.loc;
    load.dof_loc = fields[1].loc;
    auto dof = read_dof(ctx, fields[1], "DOF");
    SourceLoc magnitude_loc;
    auto magnitude = read_magnitude(ctx, fields, 2, magnitude_loc);
    if (!target || !dof || !magnitude) return;
    load.target = std::move(*target);
    load.dof = *dof;
    load.magnitude = *magnitude;
    current_step(ctx).loads.push_back(std::move(load));
  }

  // `element or set, GRAV, g, d1, d2, d3` (docs/dynamics.md "Gravity"): a blank first field is
  // the whole model; the direction is normalised. Other load types act on surfaces and volumes
  // that connector models do not have.
  void gravity_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    ctx.check_field_count(line, fields, 6, "element or element set, GRAV, magnitude, direction");
    GravityLoad load;
    load.block = block_;
    load.loc = line.loc;
    if (!fields.empty() && !fields[0].empty()) {
      load.target = ctx.target(fields[0], "element");
      if (!load.target) return;
    }
    if (fields.size() < 2 || fields[1].empty()) {
      ctx.missing(fields.size() < 2 ? BlockContext::end_of_line(line) : fields[1].loc,
                  "load type");
      return;
    }
    if (fold_name(fields[1].text) != "GRAV") {
      ctx.report(DiagCode::unsupported_option, fields[1],
                 fmt::format("*DLOAD type {} is not supported by clinch (only GRAV: connector "
                             "models have no surfaces or volumes to load)",
                             fields[1].text));
      return;
    }
    SourceLoc magnitude_loc;
    auto magnitude = read_magnitude(ctx, fields, 2, magnitude_loc);
    if (!magnitude) return;
    double length = 0.0;
    for (std::size_t i = 0; i < 3; ++i) {
      if (3 + i >= fields.size() || fields[3 + i].empty()) continue;
      auto value = ctx.real(fields[3 + i], "the gravity direction");
      if (!value) return;
      load.direction[i] = *value;
      length += *value * *value;
    }
    load.direction_loc = fields.size() > 3 ? fields[3].loc : BlockContext::end_of_line(line);
    if (length == 0.0) {
      ctx.report(DiagCode::invalid_value, load.direction_loc,
                 "the gravity direction (fields 4-6) is zero; give the components of the "
                 "direction in which gravity acts");
      return;
    }
    for (double& d : load.direction) d /= std::sqrt(length);
    load.magnitude = *magnitude;
    current_step(ctx).gravity.push_back(std::move(load));
  }

  void connector_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    ctx.check_field_count(line, fields, 3, "element or element set, component, magnitude");
    auto target = read_target(ctx, line, fields, true);
    if (fields.size() < 2 || fields[1].empty()) {
      ctx.missing(fields.size() < 2 ? BlockContext::end_of_line(line) : fields[1].loc, "component");
      return;
    }
    ConnectorCondition condition;
    condition.block = block_;
    condition.loc = line.loc;
    condition.component_loc = fields[1].loc;
    std::optional<int> component;
    if (auto value = ctx.integer(fields[1], "the component")) {
      if (*value < 1 || *value > 6) {
        ctx.report(DiagCode::value_out_of_range, fields[1],
                   fmt::format("component {} is out of range (1-6)", *value));
      } else {
        component = static_cast<int>(*value);
      }
    }
    auto magnitude = read_magnitude(ctx, fields, 2, condition.magnitude_loc);
    if (!target || !component || !magnitude) return;
    condition.target = std::move(*target);
    condition.component = *component;
    condition.magnitude = *magnitude;
    if (!in_step_) {
      ctx.model().history.model_motions.push_back(std::move(condition));
    } else if (kind_ == ConditionKind::Motion) {
      current_step(ctx).motions.push_back(std::move(condition));
    } else {
      current_step(ctx).connector_loads.push_back(std::move(condition));
    }
  }

  ConditionKind kind_;
  bool in_step_ = false;
  bool skip_ = false;
  bool fixed_ = false;
  bool fixed_reported_ = false;
  std::int32_t block_ = -1;
};

template <ConditionKind kind>
std::unique_ptr<KeywordHandler> make_condition() {
  return std::make_unique<ConditionHandler>(kind);
}

}  // namespace

std::vector<KeywordSpec> condition_keyword_specs() {
  std::vector<KeywordSpec> specs;
  const ParamSpec op{"OP", ParamKind::Enum, false, {"MOD", "NEW"}};
  const ParamSpec amplitude{"AMPLITUDE"};
  const ParamSpec type{
      "TYPE", ParamKind::Enum, false, {"DISPLACEMENT", "VELOCITY", "ACCELERATION"}};
  const ParamSpec fixed{"FIXED", ParamKind::Flag};

  KeywordSpec boundary;
  boundary.name = "BOUNDARY";
  boundary.level = KeywordLevel::ModelOrHistory;
  boundary.params = {op,
                     amplitude,
                     type,
                     fixed,
                     unsupported_param("USER"),
                     unsupported_param("SUBMODEL"),
                     unsupported_param("LOAD CASE"),
                     unsupported_param("REGION TYPE")};
  boundary.make_handler = &make_condition<ConditionKind::Boundary>;
  specs.push_back(std::move(boundary));

  KeywordSpec cload;
  cload.name = "CLOAD";
  cload.level = KeywordLevel::History;
  cload.params = {op,
                  amplitude,
                  unsupported_param("FOLLOWER"),
                  unsupported_param("USER"),
                  unsupported_param("LOAD CASE"),
                  unsupported_param("CROSS SECTIONAL"),
                  unsupported_param("SUBMODEL"),
                  unsupported_param("SYSTEM")};
  cload.make_handler = &make_condition<ConditionKind::Load>;
  specs.push_back(std::move(cload));

  KeywordSpec motion;
  motion.name = "CONNECTOR MOTION";
  motion.level = KeywordLevel::ModelOrHistory;
  motion.params = {op, amplitude, type, fixed, unsupported_param("USER")};
  motion.make_handler = &make_condition<ConditionKind::Motion>;
  specs.push_back(std::move(motion));

  KeywordSpec load;
  load.name = "CONNECTOR LOAD";
  load.level = KeywordLevel::History;
  load.params = {op, amplitude};
  load.make_handler = &make_condition<ConditionKind::ConnectorLoad>;
  specs.push_back(std::move(load));

  KeywordSpec dload;
  dload.name = "DLOAD";
  dload.level = KeywordLevel::History;
  dload.params = {op,
                  amplitude,
                  unsupported_param("FOLLOWER"),
                  unsupported_param("USER"),
                  unsupported_param("LOAD CASE"),
                  unsupported_param("ORIENTATION"),
                  unsupported_param("REF NODE"),
                  unsupported_param("CONSTANT RESULTANT"),
                  unsupported_param("SUBMODEL")};
  dload.make_handler = &make_condition<ConditionKind::Gravity>;
  specs.push_back(std::move(dload));
  return specs;
}

}  // namespace clinch
