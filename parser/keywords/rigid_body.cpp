// *RIGID BODY (docs/constraints.md "Rigid bodies"): the Abaqus form (REF NODE with ELSET, PIN
// NSET, TIE NSET) and the CalculiX form (NSET, REF NODE, ROT NODE). The definition is kept as
// written; resolve_rigid_bodies follows its references.
#include <fmt/format.h>

#include "parser/block_context.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keywords/keyword_families.hpp"
#include "parser/keywords/constraint_params.hpp"

namespace clinch {

std::optional<TargetRef> set_param(BlockContext& ctx, std::string_view param, bool element_set) {
  const Field* field = ctx.params().value(param);
  if (!field) return std::nullopt;
  std::optional<TargetRef> ref = ctx.target(*field, element_set ? "element set" : "node set");
  if (ref && ref->is_label) {
    ctx.report(DiagCode::expected_name, *field,
               fmt::format("expected {} name for {}, got '{}'",
                           element_set ? "an element set" : "a node set", param, field->text));
    return std::nullopt;
  }
  return ref;
}

std::optional<TargetRef> node_param(BlockContext& ctx, std::string_view param) {
  const Field* field = ctx.params().value(param);
  return field ? ctx.target(*field, "node") : std::nullopt;
}

namespace {

class RigidBodyHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    const ParamSet& params = ctx.params();
    RigidBodyDefinition body;
    body.keyword_loc = ctx.keyword().loc;
    body.part = ctx.position().part;
    bool ok = true;
    // Abaqus/Standard requires the reference node (the manual's *RIGID BODY, "Required
    // parameters"); CalculiX generates one at the body's centre, a node the deck does not have.
    if (!params.has("REF NODE")) {
      ctx.report(DiagCode::missing_parameter, ctx.keyword().loc,
                 "*RIGID BODY needs REF NODE=: clinch does not generate a reference node (as "
                 "CalculiX does without it); define a node and name it with REF NODE=");
      ok = false;
    }
    if (params.enum_value("POSITION") == "CENTER OF MASS") {
      ctx.report(DiagCode::unsupported_option, params.loc("POSITION", true),
                 "POSITION=CENTER OF MASS is not supported by clinch: it needs the masses of the "
                 "body, which a static analysis does not have; place the reference node with "
                 "POSITION=INPUT (the default)");
      ok = false;
    }
    // ISOTHERMAL and ALPHA concern temperatures, which clinch's mechanical steps do not have.
    if (params.flag("ISOTHERMAL")) {
      ctx.report(DiagCode::parameter_ignored, params.loc("ISOTHERMAL"),
                 "ISOTHERMAL applies to coupled thermal-stress analyses and has no effect here");
    }
    if (params.has("ALPHA")) {
      ctx.report(DiagCode::parameter_ignored, params.loc("ALPHA"),
                 "ALPHA (thermal expansion of the body) has no effect: clinch applies no "
                 "temperatures");
    }
    for (std::string_view explicit_only : {"DENSITY", "NODAL THICKNESS", "OFFSET"}) {
      if (params.has(explicit_only)) {
        ctx.report(DiagCode::parameter_ignored, params.loc(explicit_only),
                   fmt::format("{} applies to Abaqus/Explicit only and is ignored",
                               explicit_only));
      }
    }
    if (!params.has("ELSET") && !params.has("PIN NSET") && !params.has("TIE NSET") &&
        !params.has("NSET") && !params.has("ANALYTICAL SURFACE")) {
      ctx.report(DiagCode::missing_parameter, ctx.keyword().loc,
                 "*RIGID BODY needs at least one of ELSET=, PIN NSET=, TIE NSET=, NSET= or "
                 "ANALYTICAL SURFACE=");
      ok = false;
    }
    body.ref_node = node_param(ctx, "REF NODE");
    body.rot_node = node_param(ctx, "ROT NODE");
    body.elset = set_param(ctx, "ELSET", true);
    body.pin_nset = set_param(ctx, "PIN NSET", false);
    body.tie_nset = set_param(ctx, "TIE NSET", false);
    body.nset = set_param(ctx, "NSET", false);
    auto bad = [&](std::string_view param, const std::optional<TargetRef>& ref) {
      return params.value(param) && !ref;
    };
    if (bad("REF NODE", body.ref_node) || bad("ROT NODE", body.rot_node) ||
        bad("ELSET", body.elset) || bad("PIN NSET", body.pin_nset) ||
        bad("TIE NSET", body.tie_nset) || bad("NSET", body.nset)) {
      ok = false;
    }
    if (!ok) return;
    ctx.model().constraints.rigid_bodies.push_back(std::move(body));
  }

  // Abaqus/Explicit's thickness of rigid elements: no role in clinch's analysis.
  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (line.blank || fields.empty() || warned_) return;
    warned_ = true;
    ctx.report(DiagCode::parameter_ignored, line.loc,
               "the *RIGID BODY data line (the thickness of rigid elements in Abaqus/Explicit) "
               "is ignored");
  }

 private:
  bool warned_ = false;
};

}  // namespace

std::vector<KeywordSpec> rigid_body_keyword_specs() {
  KeywordSpec spec;
  spec.name = "RIGID BODY";
  spec.level = KeywordLevel::ModelGeometry;
  spec.params = {{"REF NODE", ParamKind::Value},
                 {"ELSET", ParamKind::Value},
                 {"PIN NSET", ParamKind::Value},
                 {"TIE NSET", ParamKind::Value},
                 {"NSET", ParamKind::Value},
                 {"ROT NODE", ParamKind::Value},
                 {"ANALYTICAL SURFACE", ParamKind::Value},
                 {"POSITION", ParamKind::Enum, false, {"INPUT", "CENTER OF MASS"}},
                 {"ISOTHERMAL", ParamKind::FlagOrYesNo},
                 {"ALPHA", ParamKind::Value},
                 {"DENSITY", ParamKind::Value},
                 {"NODAL THICKNESS", ParamKind::Flag},
                 {"OFFSET", ParamKind::Value}};
  spec.make_handler = [] { return std::unique_ptr<KeywordHandler>(new RigidBodyHandler); };
  return {std::move(spec)};
}

}  // namespace clinch
