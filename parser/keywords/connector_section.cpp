// *ORIENTATION, *CONNECTOR SECTION, *SPRING, *DASHPOT and *SECTION CONTROLS (keywords.md §4–§7). The
// handlers read what each block can know on its own (names, connection types and their
// combination, orientation points, spring data lines) into SectionModel; everything that needs
// the elements (element kinds, CONN2D2, the spring's element type, references to other
// definitions) is checked by resolve_sections.
#include <fmt/format.h>

#include <cmath>

#include "parser/block_context.hpp"
#include "parser/expression.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keywords/keyword_families.hpp"
#include "src/model/connection_types.hpp"
#include "src/model/orientation_triad.hpp"

namespace clinch {
namespace {

// The ELSET= value as an element-set reference in the current scope (a set name, possibly
// instance-qualified at assembly level; a bare label is not a set).
std::optional<TargetRef> elset_param(BlockContext& ctx) {
  const Field* field = ctx.params().value("ELSET");
  if (!field) return std::nullopt;
  std::optional<TargetRef> ref = ctx.target(*field, "element set");
  if (ref && ref->is_label) {
    ctx.report(DiagCode::expected_name, *field,
               fmt::format("expected an element set name for ELSET, got '{}'", field->text));
    return std::nullopt;
  }
  return ref;
}

// ---------------------------------------------------------------------------------------------
// *ORIENTATION (keywords.md §6)

class OrientationHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    const ParamSet& params = ctx.params();
    orientation_.keyword_loc = ctx.keyword().loc;
    orientation_.part = ctx.position().part;
    bool supported = true;
    if (auto system = params.enum_value("SYSTEM"); !system.empty() && system != "RECTANGULAR") {
      ctx.report(
          DiagCode::unsupported_orientation, params.loc("SYSTEM", true),
          fmt::format("SYSTEM={} is not supported for connector and spring orientations", system));
      supported = false;
    }
    if (auto definition = params.enum_value("DEFINITION"); definition == "OFFSET TO NODES") {
      ctx.report(DiagCode::unsupported_orientation, params.loc("DEFINITION", true),
                 "DEFINITION=OFFSET TO NODES is not supported for connector and spring "
                 "orientations (it needs continuum element nodes)");
      supported = false;
    } else if (definition == "NODES") {
      orientation_.definition = Orientation::Definition::Nodes;
    }
    if (params.has("LOCAL DIRECTIONS")) {
      ctx.report(DiagCode::unsupported_orientation, params.loc("LOCAL DIRECTIONS"),
                 "LOCAL DIRECTIONS is not supported for connector and spring orientations");
      supported = false;
    }
    std::optional<Name> name = ctx.name_param("NAME");
    if (!name) {
      skip_ = true;
      return;
    }
    orientation_.name = *name;
    SectionModel& sections = ctx.model().sections;
    const std::string key = scoped_name_key(orientation_.part, name->key);
    if (auto it = sections.orientation_by_key.find(key); it != sections.orientation_by_key.end()) {
      const Orientation& first = sections.orientations[static_cast<std::size_t>(it->second)];
      ctx.report(DiagCode::duplicate_name, name->loc,
                 fmt::format("orientation '{}' is already defined", name->display))
          .notes.push_back({first.keyword_loc, "previous definition is here"});
      skip_ = true;
      return;
    }
    index_ = static_cast<std::int32_t>(sections.orientations.size());
    sections.orientation_by_key.emplace(key, index_);
    // Registered even when unsupported, so that its uses do not add "undefined" errors.
    sections.orientations.push_back(orientation_);
    if (!supported) skip_ = true;
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (skip_) return;
    const std::uint32_t position = ctx.line_index();
    if (position == 1) {
      seen_points_ = true;
      if (orientation_.definition == Orientation::Definition::Coordinates) {
        read_coordinates(ctx, line, fields);
      } else {
        read_nodes(ctx, line, fields);
      }
    } else if (position == 2) {
      read_rotation(ctx, fields);
    } else if (!line.blank && !extra_reported_) {
      extra_reported_ = true;
      ctx.report(DiagCode::unexpected_data_line, line.loc,
                 "*ORIENTATION takes at most two data lines (points, then 'axis, angle')");
    }
  }

  void end(BlockContext& ctx) override {
    if (skip_) return;
    Orientation& stored = ctx.model().sections.orientations[static_cast<std::size_t>(index_)];
    if (ctx.line_index() == 0) {
      ctx.report(DiagCode::missing_data_line, ctx.keyword().loc,
                 "*ORIENTATION needs a data line with points a and b");
      stored.data_ok = false;
      return;
    }
    orientation_.data_ok = seen_points_ && points_ok_ && rotation_ok_;
    if (orientation_.data_ok && orientation_.definition == Orientation::Definition::Coordinates) {
      TriadStatus status =
          orientation_triad(orientation_.a, orientation_.b, orientation_.c, orientation_.axis,
                            orientation_.angle_degrees, orientation_.triad);
      if (status == TriadStatus::PointAAtOrigin) {
        ctx.report(DiagCode::degenerate_geometry, orientation_.a_loc,
                   fmt::format("orientation '{}': point a coincides with the origin c",
                               orientation_.name.display));
      } else if (status == TriadStatus::PointBOnAxis) {
        ctx.report(DiagCode::degenerate_geometry, orientation_.b_loc,
                   fmt::format("orientation '{}': point b lies on the local 1-axis",
                               orientation_.name.display));
      }
      orientation_.valid = status == TriadStatus::Ok;
    }
    stored = orientation_;
  }

 private:
  // `a1, a2, a3, b1, b2, b3 [, c1, c2, c3]`; a and b required, c defaults to the origin.
  void read_coordinates(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    if (!ctx.check_field_count(line, fields, 9, "a1, a2, a3, b1, b2, b3, c1, c2, c3")) {
      points_ok_ = false;
      return;
    }
    orientation_.a_loc = !fields.empty() ? fields[0].loc : line.loc;
    orientation_.b_loc = fields.size() > 3 ? fields[3].loc : BlockContext::end_of_line(line);
    std::array<Vec3*, 3> points = {&orientation_.a, &orientation_.b, &orientation_.c};
    for (std::size_t k = 0; k < 9; ++k) {
      const bool present = k < fields.size() && !fields[k].empty();
      if (!present) {
        if (k < 6) {
          ctx.missing(k < fields.size() ? fields[k].loc : BlockContext::end_of_line(line),
                      k < 3 ? "point a" : "point b");
          points_ok_ = false;
          return;
        }
        continue;
      }
      auto value = ctx.real(fields[k], k < 3 ? "point a" : k < 6 ? "point b" : "point c");
      if (!value) {
        points_ok_ = false;
        continue;
      }
      (*points[k / 3])[k % 3] = *value;
    }
  }

  // `na, nb [, nc]`: node labels whose initial coordinates give a, b, c (resolved by
  // resolve_sections once the geometry is complete).
  void read_nodes(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    if (!ctx.check_field_count(line, fields, 3, "node a, node b, node c")) {
      points_ok_ = false;
      return;
    }
    orientation_.a_loc = !fields.empty() ? fields[0].loc : line.loc;
    orientation_.b_loc = fields.size() > 1 ? fields[1].loc : BlockContext::end_of_line(line);
    static constexpr std::string_view kWhat[] = {"node a", "node b", "node c"};
    for (std::size_t k = 0; k < 3; ++k) {
      const bool present = k < fields.size() && !fields[k].empty();
      if (!present) {
        if (k < 2) {
          ctx.missing(k < fields.size() ? fields[k].loc : BlockContext::end_of_line(line),
                      kWhat[k]);
          points_ok_ = false;
          return;
        }
        continue;
      }
      auto ref = ctx.label_ref(fields[k], "node");
      if (!ref) {
        points_ok_ = false;
        continue;
      }
      orientation_.nodes[k] = *ref;
      if (k == 2) orientation_.has_node_c = true;
    }
  }

  // `axis, angle`: extra rotation in degrees about local axis 1, 2 or 3 (default 1, 0).
  void read_rotation(BlockContext& ctx, std::vector<Field>& fields) {
    if (fields.empty()) return;
    if (fields.size() > 2) {
      ctx.report(DiagCode::too_many_fields, fields[2],
                 "too many fields: the second *ORIENTATION data line takes at most 2 (local "
                 "axis, angle in degrees)");
      rotation_ok_ = false;
      return;
    }
    if (!fields[0].empty()) {
      auto axis = ctx.integer(fields[0], "local axis");
      if (!axis) {
        rotation_ok_ = false;
      } else if (*axis < 1 || *axis > 3) {
        ctx.report(DiagCode::value_out_of_range, fields[0],
                   fmt::format("local axis {} is out of range (1-3)", *axis));
        rotation_ok_ = false;
      } else {
        orientation_.axis = static_cast<int>(*axis);
      }
    }
    if (fields.size() > 1 && !fields[1].empty()) {
      auto angle = ctx.real(fields[1], "angle");
      if (!angle) {
        rotation_ok_ = false;
      } else {
        orientation_.angle_degrees = *angle;
      }
    }
  }

  Orientation orientation_;
  std::int32_t index_ = -1;
  bool skip_ = false;
  bool seen_points_ = false;
  bool points_ok_ = true;
  bool rotation_ok_ = true;
  bool extra_reported_ = false;
};

// ---------------------------------------------------------------------------------------------
// *CONNECTOR SECTION (keywords.md §4, connection-types.md §1.3, §1.5)

class ConnectorSectionHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    const ParamSet& params = ctx.params();
    section_.keyword_loc = ctx.keyword().loc;
    if (params.has("ELIMINATION")) {
      ctx.report(DiagCode::parameter_ignored, params.loc("ELIMINATION"),
                 "ELIMINATION has no effect in clinch (Abaqus/Explicit only)");
    }
    std::optional<TargetRef> elset = elset_param(ctx);
    if (!elset) {
      // Stored without a set, so that its elements do not also get "no section" errors.
      skip_ = true;
      ctx.model().sections.connector_sections.push_back(std::move(section_));
      return;
    }
    section_.elset = *elset;
    if (params.value("BEHAVIOR")) {
      if (auto name = ctx.name_param("BEHAVIOR")) section_.behavior = *name;
    }
    if (params.value("CONTROLS")) {
      if (auto name = ctx.name_param("CONTROLS")) section_.controls = *name;
    }
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (skip_) return;
    const std::uint32_t position = ctx.line_index();
    if (position == 1) {
      read_types(ctx, line, fields);
    } else if (position == 2) {
      read_orientations(ctx, line, fields);
    } else if (!line.blank && !extra_reported_) {
      extra_reported_ = true;
      if (position == 3 && uses_third_line_) return;  // E0704 already given for the type
      ctx.report(DiagCode::unexpected_data_line, line.loc,
                 position == 3 ? "a third *CONNECTOR SECTION data line is used only by SLIPRING, "
                                 "RETRACTOR and FLOW-CONVERTER"
                               : "*CONNECTOR SECTION takes at most three data lines");
    }
  }

  void end(BlockContext& ctx) override {
    if (skip_) return;
    if (ctx.line_index() == 0) {
      ctx.report(DiagCode::missing_data_line, ctx.keyword().loc,
                 "*CONNECTOR SECTION needs a data line naming the connection type");
    }
    if (section_.valid) check_orientation_use(ctx);
    ctx.model().sections.connector_sections.push_back(std::move(section_));
  }

 private:
  // Line 1: one assembled type, or one translational and/or one rotational basic type, the
  // translational first (§1.5 rule 1).
  void read_types(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    section_.type_loc = !fields.empty() ? fields[0].loc : line.loc;
    if (fields.empty() || fields[0].empty()) {
      ctx.missing(section_.type_loc, "connection type");
      return;
    }
    if (!ctx.check_field_count(line, fields, 2, "connection type, second connection type")) {
      return;
    }
    std::vector<const ConnectionTypeInfo*> infos;
    std::vector<const Field*> type_fields;
    bool ok = true;
    for (const Field& field : fields) {
      if (field.empty()) continue;
      const ConnectionTypeInfo* info = find_connection_type(field.text);
      if (!info) {
        Diagnostic& d = ctx.report(DiagCode::unknown_connection_type, field,
                                   fmt::format("unknown connection type '{}'", field.text));
        if (auto guess = suggest_connection_type(field.text)) {
          d.notes.push_back({field.loc, fmt::format("did you mean '{}'?", *guess)});
        }
        ok = false;
        continue;
      }
      if (info->support == V1Support::Unsupported) {
        ctx.report(DiagCode::unsupported_connection_type, field,
                   fmt::format("connection type '{}' is not supported by clinch", info->name));
        const std::string key = connection_type_key(info->name);
        if (key == "SLIPRING" || key == "RETRACTOR" || key == "FLOWCONVERTER") {
          uses_third_line_ = true;
        }
        ok = false;
        continue;
      }
      if (info->support == V1Support::Converted) {
        // connection-types.md §1.5 rule 4: clinch runs implicit static steps only.
        ctx.report(DiagCode::accelerometer_converted, field,
                   fmt::format("connection type '{}' is converted to CARTESIAN in a static "
                               "analysis",
                               info->name));
        info = &converted_type();
      }
      infos.push_back(info);
      type_fields.push_back(&field);
    }
    if (!ok) return;
    if (infos.size() == 2 && !check_combination(ctx, infos, type_fields)) return;
    for (std::size_t k = 0; k < infos.size(); ++k) {
      section_.type_names.emplace_back(infos[k]->name);
      section_.type_locs.push_back(type_fields[k]->loc);
    }
    const ConnectionSummary summary = summarize_connection(infos, false);
    section_.available = summary.available;
    section_.constrained = summary.constrained;
    section_.valid = !infos.empty();
  }

  bool check_combination(BlockContext& ctx, const std::vector<const ConnectionTypeInfo*>& infos,
                         const std::vector<const Field*>& fields) {
    const ConnectionTypeInfo& first = *infos[0];
    const ConnectionTypeInfo& second = *infos[1];
    std::string message;
    if (first.kind == ConnectionKind::Assembled || second.kind == ConnectionKind::Assembled) {
      const ConnectionTypeInfo& assembled =
          first.kind == ConnectionKind::Assembled ? first : second;
      const ConnectionTypeInfo& other = &assembled == &first ? second : first;
      message = fmt::format("assembled connection type '{}' cannot be combined with '{}'",
                            assembled.name, other.name);
    } else if (first.kind == second.kind) {
      message =
          fmt::format("connection types '{}' and '{}' are both {}", first.name, second.name,
                      first.kind == ConnectionKind::Translational ? "translational" : "rotational");
    } else if (first.kind == ConnectionKind::Rotational) {
      message = fmt::format(
          "the translational type '{}' must come before the rotational type "
          "'{}'",
          second.name, first.name);
    } else {
      return true;
    }
    ctx.report(DiagCode::invalid_type_combination, *fields[1], std::move(message));
    return false;
  }

  // Line 2: orientation names at a and b; blank fields mean the defaults.
  void read_orientations(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    if (!ctx.check_field_count(line, fields, 2, "orientation at node a, orientation at node b")) {
      return;
    }
    for (std::size_t k = 0; k < fields.size() && k < 2; ++k) {
      if (fields[k].empty()) continue;
      if (auto name =
              ctx.name(fields[k], k == 0 ? "orientation at node a" : "orientation at node b")) {
        section_.orientations[k] = *name;
      }
    }
  }

  // connection-types.md §1.3: a required orientation that is missing uses the defaults with
  // orientation-defaulted (not confirmed whether Abaqus rejects the deck instead); one given
  // where every type of the line ignores it gives orientation-ignored.
  void check_orientation_use(BlockContext& ctx) {
    for (int end = 0; end < 2; ++end) {
      const Name& given = section_.orientations[static_cast<std::size_t>(end)];
      const char* node = end == 0 ? "a" : "b";
      bool all_ignore = true;
      bool defaulted = false;
      for (std::size_t k = 0; k < section_.type_names.size(); ++k) {
        const ConnectionTypeInfo* info = find_connection_type(section_.type_names[k]);
        if (!info) continue;
        const OrientationUse use = end == 0 ? info->orientation_a : info->orientation_b;
        if (use != OrientationUse::Ignored) all_ignore = false;
        if (use == OrientationUse::Required && given.empty() && !defaulted) {
          defaulted = true;  // once per end, naming the first type that needs it
          ctx.report(
              DiagCode::orientation_defaulted, section_.type_locs[k],
              fmt::format("connection type '{}' needs an orientation at node {}; {} are "
                          "used",
                          info->name, node,
                          end == 0 ? "the global axes" : "the initial directions at node a"));
        }
      }
      if (!given.empty() && all_ignore) {
        ctx.report(DiagCode::orientation_ignored, given.loc,
                   fmt::format("the orientation at node {} is ignored by connection type '{}'",
                               node, connection_display(section_)));
      }
    }
  }

  ConnectorSection section_;
  bool skip_ = false;
  bool uses_third_line_ = false;
  bool extra_reported_ = false;
};

// ---------------------------------------------------------------------------------------------
// *SPRING (keywords.md §7)

// A real written in a field (rather than an integer): the W0703 test of §7 for SPRINGA.
bool looks_real(const Field& field) {
  if (field.parameter) return field.parameter->kind == ParamValue::Kind::Float;
  return field.text.find_first_of(".eEdD") != std::string::npos;
}

// *SPRING, and *DASHPOT (`dashpot`), whose data have the same layout (behaviors.md §8).
class SpringHandler : public KeywordHandler {
 public:
  explicit SpringHandler(bool dashpot) { spring_.dashpot = dashpot; }

  void begin(BlockContext& ctx) override {
    const ParamSet& params = ctx.params();
    spring_.keyword_loc = ctx.keyword().loc;
    spring_.nonlinear = params.has("NONLINEAR");
    std::optional<TargetRef> elset = elset_param(ctx);
    if (!elset) {
      skip_ = true;
      spring_.data_ok = false;
      ctx.model().sections.springs.push_back(std::move(spring_));
      return;
    }
    spring_.elset = *elset;
    if (params.value("ORIENTATION")) {
      if (auto name = ctx.name_param("ORIENTATION")) {
        spring_.orientation = *name;
        spring_.orientation_param_loc = params.loc("ORIENTATION");
      }
    }
    if (params.value("DEPENDENCIES")) {
      if (auto n = ctx.integer_param("DEPENDENCIES")) {
        if (*n < 0) {
          ctx.report(DiagCode::value_out_of_range, *params.value("DEPENDENCIES"),
                     fmt::format("DEPENDENCIES={} is out of range (at least 0)", *n));
        } else if (*n > 0) {
          ctx.report(DiagCode::unsupported_dependencies, *params.value("DEPENDENCIES"),
                     fmt::format("field-variable-dependent {} data is not supported",
                                 spring_.words().element));
          rejected_ = true;
        }
      }
    }
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (skip_ || rejected_) return;
    if (ctx.line_index() == 1) {
      read_first_line(ctx, line, fields);
      return;
    }
    if (line.blank || fields.empty()) return;  // repeated lines: blanks are skipped (§3.4)
    spring_.property_lines.push_back(read_property_line(ctx, line, fields));
  }

  void end(BlockContext& ctx) override {
    if (skip_) return;
    if (rejected_ || ctx.line_index() == 0) {
      if (!rejected_) {
        ctx.report(DiagCode::missing_data_line, ctx.keyword().loc,
                   fmt::format("{} needs a DOF line and a line with the {} data",
                               spring_.words().keyword, spring_.words().element));
      }
      spring_.data_ok = false;
    } else if (spring_.property_lines.empty() && !spring_.first_line_real) {
      const DiscreteElementWords& words = spring_.words();
      ctx.report(DiagCode::missing_data_line, ctx.keyword().loc,
                 spring_.nonlinear ? fmt::format("{}, NONLINEAR needs force, {} lines after the "
                                                 "DOF line", words.keyword, words.motion)
                                   : fmt::format("{} needs a line with the {} after the DOF "
                                                 "line", words.keyword, words.coefficient));
      spring_.data_ok = false;
    }
    ctx.model().sections.springs.push_back(std::move(spring_));
  }

 private:
  // The DOF line position: blank (SPRINGA), `dof` (SPRING1) or `dof1, dof2` (SPRING2); a line
  // holding a real is kept as a candidate property line for the SPRINGA rule (W0703).
  void read_first_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    spring_.has_first_line = true;
    spring_.first_line_loc = line.loc;
    if (line.blank || fields.empty()) {
      spring_.first_line_blank = true;
      return;
    }
    for (const Field& field : fields) {
      if (!field.empty() && looks_real(field)) spring_.first_line_real = true;
    }
    if (spring_.first_line_real) {
      spring_.first_line_as_property = read_property_line(ctx, line, fields);
      return;
    }
    for (const Field& field : fields) {
      std::int64_t value = 0;
      bool is_integer = false;
      if (field.parameter) {
        is_integer = field.parameter->kind == ParamValue::Kind::Int;
        value = is_integer ? field.parameter->i : 0;
      } else {
        is_integer = !field.quoted && parse_integer_text(field.text, value);
      }
      if (!is_integer) {
        const std::string_view keyword = spring_.words().keyword;
        ctx.report(DiagCode::spring_dof_line, field.loc,
                   field.empty() ? fmt::format("missing DOF on the {} DOF line", keyword)
                                 : fmt::format("expected an integer DOF on the {} DOF line, "
                                               "got '{}'",
                                               keyword, field.text));
        spring_.first_line_ok = false;
        return;
      }
      spring_.first_line_integers.push_back(value);
      spring_.first_line_locs.push_back(field.loc);
    }
  }

  // `k [, frequency] [, temperature]` or `F, Δ [, temperature]`: numbers only; what they mean
  // and how many lines there may be is checked by resolve_sections.
  SpringLine read_property_line(BlockContext& ctx, const DataLine& line,
                                std::vector<Field>& fields) {
    SpringLine out;
    out.loc = line.loc;
    const DiscreteElementWords& words = spring_.words();
    const std::string layout =
        spring_.nonlinear ? fmt::format("force, {}, temperature", words.motion)
                          : fmt::format("{}, frequency, temperature", words.coefficient);
    if (!ctx.check_field_count(line, fields, 3, layout)) {
      out.ok = false;
      return out;
    }
    for (const Field& field : fields) {
      SpringValue v;
      v.loc = field.loc;
      if (!field.empty() || field.parameter) {
        v.value = ctx.real(field, spring_.nonlinear ? fmt::format("{} table", words.element)
                                                    : std::string(words.coefficient));
        if (!v.value) out.ok = false;
      }
      out.values.push_back(v);
    }
    return out;
  }

  SpringProperty spring_;
  bool skip_ = false;
  bool rejected_ = false;  // DEPENDENCIES > 0: data lines are not read
};

// ---------------------------------------------------------------------------------------------
// *SECTION CONTROLS (keywords.md §5): ELEMENT DELETION, MAX DEGRADATION and VISCOSITY of the
// damage of the connectors that name them (docs/decisions.md "Damage").

constexpr std::string_view kSectionControlsParams[] = {"NAME", "ELEMENTDELETION", "MAXDEGRADATION",
                                                       "VISCOSITY"};

class SectionControlsHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    const ParamSet& params = ctx.params();
    // Any other parameter (hourglass, distortion, …) is a control clinch does not have.
    for (const KeywordParam& param : ctx.keyword().params) {
      bool known = false;
      for (std::string_view name : kSectionControlsParams) {
        if (param.name.size() <= name.size() && name.substr(0, param.name.size()) == param.name &&
            !param.name.empty()) {
          known = true;
        }
      }
      if (!known) {
        ctx.report(DiagCode::unsupported_option, param.loc,
                   fmt::format("parameter '{}' of *SECTION CONTROLS is not supported by clinch",
                               param.spelled));
      }
    }
    SectionControls controls;
    controls.keyword_loc = ctx.keyword().loc;
    controls.element_deletion = params.enum_value("ELEMENT DELETION") != "NO";
    if (params.value("MAX DEGRADATION")) {
      if (auto value = ctx.real_param("MAX DEGRADATION")) {
        const Field& field = *params.value("MAX DEGRADATION");
        if (!(*value > 0 && *value <= 1)) {
          ctx.report(DiagCode::value_out_of_range, field,
                     fmt::format("MAX DEGRADATION {} is out of range (0, 1]", field.text));
        } else {
          controls.max_degradation = *value;
        }
      }
    }
    if (params.value("VISCOSITY")) {
      if (auto value = ctx.real_param("VISCOSITY")) {
        const Field& field = *params.value("VISCOSITY");
        if (*value < 0) {
          ctx.report(DiagCode::value_out_of_range, field,
                     fmt::format("VISCOSITY {} is out of range (at least 0)", field.text));
        } else {
          controls.viscosity = *value;
        }
      }
    }
    // The controls are registered even after an error, so that CONTROLS= finds them.
    std::optional<Name> name = ctx.name_param("NAME");
    if (!name) return;
    controls.name = *name;
    SectionModel& sections = ctx.model().sections;
    if (auto it = sections.controls_by_key.find(name->key); it != sections.controls_by_key.end()) {
      ctx.report(DiagCode::duplicate_name, name->loc,
                 fmt::format("section controls '{}' is already defined", name->display))
          .notes.push_back({sections.controls[static_cast<std::size_t>(it->second)].keyword_loc,
                            "previous definition is here"});
      return;
    }
    sections.controls_by_key.emplace(name->key,
                                     static_cast<std::int32_t>(sections.controls.size()));
    sections.controls.push_back(std::move(controls));
  }
};

template <class Handler>
std::unique_ptr<KeywordHandler> make() {
  return std::make_unique<Handler>();
}

}  // namespace

std::vector<KeywordSpec> section_keyword_specs() {
  std::vector<KeywordSpec> specs;

  KeywordSpec orientation;
  orientation.name = "ORIENTATION";
  orientation.level = KeywordLevel::ModelGeometry;
  orientation.params = {
      {"NAME", ParamKind::Value, true},
      {"SYSTEM",
       ParamKind::Enum,
       false,
       {"RECTANGULAR", "CYLINDRICAL", "SPHERICAL", "Z RECTANGULAR", "USER"}},
      {"DEFINITION", ParamKind::Enum, false, {"COORDINATES", "NODES", "OFFSET TO NODES"}},
      {"LOCAL DIRECTIONS", ParamKind::OptionalValue},
  };
  orientation.make_handler = &make<OrientationHandler>;
  specs.push_back(std::move(orientation));

  KeywordSpec section;
  section.name = "CONNECTOR SECTION";
  section.level = KeywordLevel::ModelGeometry;
  section.params = {
      {"ELSET", ParamKind::Value, true},
      {"BEHAVIOR", ParamKind::Value},
      {"CONTROLS", ParamKind::Value},
      {"ELIMINATION", ParamKind::Enum, false, {"YES", "NO"}},
  };
  section.make_handler = &make<ConnectorSectionHandler>;
  specs.push_back(std::move(section));

  KeywordSpec spring;
  spring.name = "SPRING";
  spring.level = KeywordLevel::ModelGeometry;
  spring.params = {
      {"ELSET", ParamKind::Value, true},
      {"NONLINEAR", ParamKind::Flag},
      {"ORIENTATION", ParamKind::Value},
      {"DEPENDENCIES", ParamKind::Value},
  };
  spring.make_handler = [] { return std::unique_ptr<KeywordHandler>(new SpringHandler(false)); };
  KeywordSpec dashpot = spring;
  dashpot.name = "DASHPOT";
  dashpot.make_handler = [] { return std::unique_ptr<KeywordHandler>(new SpringHandler(true)); };
  specs.push_back(std::move(spring));
  specs.push_back(std::move(dashpot));

  KeywordSpec controls;
  controls.name = "SECTION CONTROLS";
  controls.level = KeywordLevel::Model;
  controls.data = DataMode::None;
  controls.loose_params = true;
  controls.params = {
      {"NAME", ParamKind::Value, true},
      {"ELEMENT DELETION", ParamKind::Enum, false, {"YES", "NO"}},
      {"MAX DEGRADATION", ParamKind::Value},
      {"VISCOSITY", ParamKind::Value},
  };
  controls.make_handler = &make<SectionControlsHandler>;
  specs.push_back(std::move(controls));

  return specs;
}

}  // namespace clinch
