// *INITIAL CONDITIONS (model data): TYPE=VELOCITY, the nodal velocities a *DYNAMIC step starts
// from (docs/dynamics.md). Data lines: node or node set, DOF (1–6), velocity. Every other TYPE
// sets a field clinch has no use for yet, and is refused at its value.
#include <fmt/format.h>

#include "parser/keywords/history_keywords.hpp"

namespace clinch {
namespace {

class InitialConditionsHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    const ParamSet& params = ctx.params();
    skip_ = report_unsupported_params(ctx, {"USER", "FILE", "STEP", "INC", "INTERPOLATE"});
    const std::string_view type = params.enum_value("TYPE");
    if (type != "VELOCITY") {
      ctx.report(DiagCode::unsupported_option, params.loc("TYPE", true),
                 fmt::format("TYPE={} on *INITIAL CONDITIONS is not supported by clinch (only "
                             "TYPE=VELOCITY)",
                             params.value("TYPE") ? params.value("TYPE")->text : type));
      skip_ = true;
    }
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (skip_ || line.blank) return;
    ctx.check_field_count(line, fields, 3, "node or node set, DOF, velocity");
    if (fields.empty() || fields[0].empty()) {
      ctx.missing(fields.empty() ? line.loc : fields[0].loc, "node or node set");
      return;
    }
    auto target = ctx.target(fields[0], "node");
    if (fields.size() < 2 || fields[1].empty()) {
      ctx.missing(fields.size() < 2 ? BlockContext::end_of_line(line) : fields[1].loc, "DOF");
      return;
    }
    auto dof = ctx.integer(fields[1], "DOF");
    if (dof && (*dof < 1 || *dof > 6)) {
      ctx.report(DiagCode::invalid_dof, fields[1],
                 fmt::format("DOF {} is not valid (DOFs are 1-6)", *dof));
      return;
    }
    std::optional<double> value = 0.0;
    if (fields.size() > 2 && !fields[2].empty()) value = ctx.real(fields[2], "the velocity");
    if (!target || !dof || !value) return;
    InitialVelocity velocity;
    velocity.target = std::move(*target);
    velocity.dof = static_cast<int>(*dof);
    velocity.value = *value;
    velocity.loc = line.loc;
    velocity.dof_loc = fields[1].loc;
    ctx.model().history.initial_velocities.push_back(std::move(velocity));
  }

 private:
  bool skip_ = false;
};

}  // namespace

std::vector<KeywordSpec> initial_condition_keyword_specs() {
  KeywordSpec spec;
  spec.name = "INITIAL CONDITIONS";
  spec.level = KeywordLevel::Model;
  spec.params = {
      {"TYPE",
       ParamKind::Enum,
       true,
       {"VELOCITY", "ROTATING VELOCITY", "STRESS", "TEMPERATURE", "FIELD", "SOLUTION",
        "PLASTIC STRAIN", "HARDENING", "RATIO", "SATURATION", "PORE PRESSURE", "DENSITY",
        "INITIAL GAP", "CONTACT", "REF COORDINATE", "SPECIFIC ENERGY", "MASS FLOW RATE",
        "NODE REF COORDINATE", "CONCENTRATION", "ACOUSTIC STATIC PRESSURE", "FLUID PRESSURE"}},
      unsupported_param("USER"),
      unsupported_param("FILE"),
      unsupported_param("STEP"),
      unsupported_param("INC"),
      unsupported_param("INTERPOLATE"),
  };
  spec.make_handler = &make<InitialConditionsHandler>;
  return {std::move(spec)};
}

}  // namespace clinch
