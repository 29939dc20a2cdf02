// *CONNECTOR PLASTICITY and *CONNECTOR HARDENING (behaviors.md §6.1). A plasticity is an owner
// of a following *CONNECTOR POTENTIAL (derived-components-and-potentials.md §2.7); a hardening
// attaches to the nearest preceding plasticity of the block (behaviors.md §2). The rules that
// need the elasticity of the behaviour (softening-too-steep, plasticity-needs-linear-elasticity)
// are checked by check_behaviors.
#include <fmt/format.h>

#include "parser/block_context.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keywords/behavior_option_common.hpp"

namespace clinch {
namespace {

class PlasticityHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    ConnectorBehavior* behavior = current_behavior(ctx);
    if (!behavior) return;
    ConnectorPlasticity plasticity;
    plasticity.loc = ctx.keyword().loc;
    std::optional<int> component = component_param(ctx);
    const bool has_component = ctx.params().has("COMPONENT");
    plasticity.valid = component.has_value();
    // A bad COMPONENT value still means "uncoupled": keep it off the coupled path.
    plasticity.component = has_component ? component.value_or(-1) : 0;
    plasticity.component_loc = ctx.params().loc("COMPONENT", true);
    behavior->plasticities.push_back(plasticity);

    PotentialOwner owner;
    owner.kind = PotentialOwner::Kind::Plasticity;
    owner.index = static_cast<std::int32_t>(behavior->plasticities.size() - 1);
    owner.loc = ctx.keyword().loc;
    // §6.1: coupled plasticity (no COMPONENT) needs a potential; uncoupled forbids one.
    owner.requires_potential = !has_component;
    owner.allows_potential = !has_component;
    if (has_component) {
      const Field* value = ctx.params().value("COMPONENT");
      owner.why_not_allowed = fmt::format("COMPONENT={}", value ? value->text : std::string());
    }
    behavior->potential_owners.push_back(std::move(owner));
  }
};

class HardeningHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    ConnectorBehavior* behavior = current_behavior(ctx);
    if (!behavior) return;
    const ParamSet& params = ctx.params();
    if (behavior->plasticities.empty()) {
      ctx.report(DiagCode::hardening_no_plasticity, ctx.keyword().loc,
                 "*CONNECTOR HARDENING must follow a *CONNECTOR PLASTICITY in the same "
                 "*CONNECTOR BEHAVIOR");
      return;
    }
    warn_explicit_only(ctx, {"RATE FILTER FACTOR", "RATE INTERPOLATION", "REGULARIZE", "RTOL"});
    plasticity_ = &behavior->plasticities.back();
    kinematic_ = params.enum_value("TYPE") == "KINEMATIC";
    std::string_view definition = params.enum_value("DEFINITION");
    if (definition.empty()) definition = kinematic_ ? "HALF CYCLE" : "TABULAR";
    const bool iso_definition = definition == "TABULAR" || definition == "EXPONENTIAL LAW";
    if (iso_definition == kinematic_) {
      ctx.report(DiagCode::conflicting_parameters, params.loc("DEFINITION", true),
                 fmt::format("DEFINITION={} is not valid for TYPE={}", definition,
                             kinematic_ ? "KINEMATIC" : "ISOTROPIC"));
      plasticity_ = nullptr;
      return;
    }
    // §2: one ISOTROPIC and one KINEMATIC option per plasticity at most.
    const bool duplicate =
        kinematic_ ? plasticity_->kinematic.has_value() : plasticity_->isotropic.has_value();
    if (duplicate) {
      Diagnostic& d =
          ctx.report(DiagCode::hardening_duplicate, ctx.keyword().loc,
                     fmt::format("this *CONNECTOR PLASTICITY already has a TYPE={} hardening",
                                 kinematic_ ? "KINEMATIC" : "ISOTROPIC"));
      d.notes.push_back({kinematic_ ? plasticity_->kinematic->loc : plasticity_->isotropic->loc,
                         "previous hardening of the same type is here"});
      plasticity_ = nullptr;
      return;
    }
    bool valid = check_dependencies(ctx, "connector hardening");
    if (definition == "STABILIZED") {
      ctx.report(DiagCode::unsupported_option, params.loc("DEFINITION", true),
                 "DEFINITION=STABILIZED kinematic hardening is not supported by clinch");
      valid = false;
    }
    if (kinematic_ && plasticity_->coupled()) {
      // §6.5: optional in v1; clinch rejects it.
      ctx.report(DiagCode::unsupported_option,
                 params.has("TYPE") ? params.loc("TYPE", true) : ctx.keyword().loc,
                 "kinematic hardening with coupled plasticity is not supported by clinch");
      valid = false;
    }
    ignore_data_ = !valid;
    if (kinematic_) {
      KinematicHardening& k = plasticity_->kinematic.emplace();
      k.loc = ctx.keyword().loc;
      k.valid = valid;
      k.definition = definition == "PARAMETERS" ? KinematicHardening::Definition::Parameters
                                                : KinematicHardening::Definition::HalfCycle;
      half_cycle_ = definition == "HALF CYCLE";
      deps_ = half_cycle_ ? DependenceColumns(2, 5, "kinematic hardening")
                          : DependenceColumns(3, 4, "kinematic hardening");
    } else {
      IsotropicHardening& h = plasticity_->isotropic.emplace();
      h.loc = ctx.keyword().loc;
      h.valid = valid;
      h.definition = definition == "EXPONENTIAL LAW"
                         ? IsotropicHardening::Definition::ExponentialLaw
                         : IsotropicHardening::Definition::Tabular;
      h.extrapolation = option_extrapolation(ctx, *behavior);
      tabular_ = h.definition == IsotropicHardening::Definition::Tabular;
    }
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (!plasticity_ || ignore_data_) return;
    ++rows_;
    if (!deps_.check_row(ctx, fields)) {
      set_invalid();
      return;
    }
    if (kinematic_) {
      half_cycle_ ? half_cycle_line(ctx, line, fields) : parameters_line(ctx, line, fields);
    } else {
      tabular_ ? tabular_line(ctx, line, fields) : exponential_line(ctx, line, fields);
    }
  }

  void end(BlockContext& ctx) override {
    if (!plasticity_ || ignore_data_) return;
    deps_.finish(ctx);
    if (deps_.rejected()) set_invalid();
    if (rows_ == 0) {
      report_missing_data(ctx, kinematic_ ? (half_cycle_ ? "F, u^pl" : "F_0, C, gamma")
                                          : (tabular_ ? "F_y, u^pl" : "F_0, Q_inf, b"));
      set_invalid();
      return;
    }
    if (kinematic_ && half_cycle_ && valid()) {
      KinematicHardening& k = *plasticity_->kinematic;
      if (k.half_cycle.size() < 2) {
        ctx.report(DiagCode::table_too_short, ctx.keyword().loc,
                   fmt::format("HALF CYCLE kinematic hardening needs exactly two rows, got {}",
                               k.half_cycle.size()));
        set_invalid();
        return;
      }
      // §6.1: two rows map to linear (Ziegler) hardening; not confirmed for Abaqus (§9.7).
      const TablePoint& p1 = k.half_cycle[0];
      const TablePoint& p2 = k.half_cycle[1];
      k.f0 = p1.value;
      k.f0_loc = p1.loc;
      k.c = (p2.value - p1.value) / p2.at;
      k.gamma = 0;
    }
  }

 private:
  bool valid() const {
    return kinematic_ ? plasticity_->kinematic->valid : plasticity_->isotropic->valid;
  }
  void set_invalid() {
    if (kinematic_) {
      plasticity_->kinematic->valid = false;
    } else {
      plasticity_->isotropic->valid = false;
    }
  }

  bool single_row(BlockContext& ctx, const DataLine& line, std::string_view layout) {
    if (rows_ == 1) return true;
    if (rows_ == 2) report_extra_line(ctx, line, layout);
    set_invalid();
    return false;
  }

  void tabular_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    IsotropicHardening& h = *plasticity_->isotropic;
    ctx.check_field_count(line, fields, 8, "F_y, u^pl, rate, temperature, field1..field4");
    std::optional<double> fy = required_real(ctx, line, fields, 0, "yield force");
    bool bad = false;
    std::optional<double> u = optional_real(ctx, fields, 1, "equivalent plastic motion", &bad);
    check_rate(ctx, fields);
    if (!fy || bad) {
      h.valid = false;
      return;
    }
    const double at = u.value_or(0.0);  // a blank field is 0
    const Field& at_field = fields.size() > 1 && !fields[1].empty() ? fields[1] : fields[0];
    if (*fy <= 0) {
      ctx.report(DiagCode::yield_not_positive, fields[0],
                 fmt::format("yield force must be positive, got {}", fields[0].text));
      h.valid = false;
    }
    if (h.table.empty() && at != 0) {
      ctx.report(DiagCode::hardening_first_point, at_field,
                 fmt::format("the first hardening point must be at zero equivalent plastic "
                             "motion, got {}",
                             at_field.text));
      h.valid = false;
    }
    if (!h.table.empty() && !(at > h.table.back().at)) {
      if (!increasing_reported_) {
        ctx.report(DiagCode::table_not_increasing, at_field,
                   fmt::format("equivalent plastic motions must increase ({} after {})",
                               u ? at_field.text : "0", last_at_text_));
      }
      increasing_reported_ = true;
      h.valid = false;
      return;
    }
    h.table.push_back({*fy, at, fields[0].loc});
    if (h.table.size() == 1) h.data_loc = fields[0].loc;
    last_at_text_ = u ? at_field.text : "0";
  }

  // §6.1: the rate column must be blank or hold one common value.
  void check_rate(BlockContext& ctx, const std::vector<Field>& fields) {
    if (fields.size() < 3 || fields[2].empty() || rate_rejected_) return;
    std::optional<double> rate = ctx.real(fields[2], "rate");
    if (!rate) return;
    if (!rate_) {
      rate_ = *rate;
      rate_text_ = fields[2].text;
    } else if (*rate != *rate_) {
      rate_rejected_ = true;
      set_invalid();
      ctx.report(DiagCode::unsupported_dependencies, fields[2],
                 fmt::format("rate-dependent connector hardening data is not supported (rate {} "
                             "after {})",
                             fields[2].text, rate_text_));
    }
  }

  void exponential_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    if (!single_row(ctx, line, "F_0, Q_inf, b, temperature, field1..field4")) return;
    IsotropicHardening& h = *plasticity_->isotropic;
    ctx.check_field_count(line, fields, 8, "F_0, Q_inf, b, temperature, field1..field4");
    std::optional<double> f0 = required_real(ctx, line, fields, 0, "F_0");
    bool bad_q = false, bad_b = false;
    std::optional<double> q = optional_real(ctx, fields, 1, "Q_inf", &bad_q);
    std::optional<double> b = optional_real(ctx, fields, 2, "b", &bad_b);
    if (!f0 || bad_q || bad_b) {
      h.valid = false;
      return;
    }
    h.f0 = *f0;
    h.q_inf = q.value_or(0.0);
    h.b = b.value_or(0.0);
    h.data_loc = fields[0].loc;
    if (h.f0 <= 0) {
      ctx.report(DiagCode::yield_not_positive, fields[0],
                 fmt::format("initial yield force F_0 must be positive, got {}", fields[0].text));
      h.valid = false;
    } else if (h.f0 + h.q_inf <= 0) {
      ctx.report(DiagCode::yield_not_positive, fields[1],
                 fmt::format("the yield force F_0 + Q_inf = {} reached at large plastic motion "
                             "must be positive",
                             h.f0 + h.q_inf));
      h.valid = false;
    }
    if (h.b < 0) {
      ctx.report(DiagCode::value_out_of_range, fields[2],
                 fmt::format("hardening rate b must be 0 or more, got {}", fields[2].text));
      h.valid = false;
    }
  }

  void parameters_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    if (!single_row(ctx, line, "F_0, C, gamma, temperature, field1..field4")) return;
    KinematicHardening& k = *plasticity_->kinematic;
    ctx.check_field_count(line, fields, 8, "F_0, C, gamma, temperature, field1..field4");
    std::optional<double> f0 = required_real(ctx, line, fields, 0, "F_0");
    bool bad_c = false, bad_g = false;
    std::optional<double> c = optional_real(ctx, fields, 1, "C", &bad_c);
    std::optional<double> gamma = optional_real(ctx, fields, 2, "gamma", &bad_g);
    if (!f0 || bad_c || bad_g) {
      k.valid = false;
      return;
    }
    k.f0 = *f0;
    k.f0_loc = fields[0].loc;
    k.c = c.value_or(0.0);
    k.gamma = gamma.value_or(0.0);
    if (k.c < 0) {
      ctx.report(
          DiagCode::value_out_of_range, fields[1],
          fmt::format("kinematic hardening modulus C must be 0 or more, got {}", fields[1].text));
      k.valid = false;
    }
    if (k.gamma < 0) {
      ctx.report(
          DiagCode::value_out_of_range, fields[2],
          fmt::format("kinematic hardening rate gamma must be 0 or more, got {}", fields[2].text));
      k.valid = false;
    }
  }

  void half_cycle_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    KinematicHardening& k = *plasticity_->kinematic;
    if (rows_ > 2) {
      if (rows_ == 3) {
        ctx.report(DiagCode::unsupported_option, line.loc,
                   "HALF CYCLE kinematic hardening with more than two rows is not supported by "
                   "clinch");
      }
      k.valid = false;
      return;
    }
    ctx.check_field_count(line, fields, 8, "F, u^pl, temperature, field1..field5");
    std::optional<double> f = required_real(ctx, line, fields, 0, "force");
    bool bad = false;
    std::optional<double> u = optional_real(ctx, fields, 1, "plastic motion", &bad);
    if (!f || bad) {
      k.valid = false;
      return;
    }
    const double at = u.value_or(0.0);
    const Field& at_field = fields.size() > 1 && !fields[1].empty() ? fields[1] : fields[0];
    if (rows_ == 1 && at != 0) {
      ctx.report(DiagCode::hardening_first_point, at_field,
                 fmt::format("the first HALF CYCLE point must be at zero plastic motion, got {}",
                             at_field.text));
      k.valid = false;
    }
    if (rows_ == 2 && !k.half_cycle.empty() && !(at > k.half_cycle.front().at)) {
      ctx.report(DiagCode::table_not_increasing, at_field,
                 fmt::format("plastic motions must increase ({} after {})", u ? at_field.text : "0",
                             last_at_text_));
      k.valid = false;
      return;
    }
    k.half_cycle.push_back({*f, at, fields[0].loc});
    last_at_text_ = u ? at_field.text : "0";
  }

  ConnectorPlasticity* plasticity_ = nullptr;
  bool kinematic_ = false;
  bool tabular_ = true;
  bool half_cycle_ = false;
  bool ignore_data_ = false;
  bool increasing_reported_ = false;
  bool rate_rejected_ = false;
  std::optional<double> rate_;
  std::string rate_text_;
  std::string last_at_text_;
  std::size_t rows_ = 0;
  DependenceColumns deps_{3, 4, "isotropic hardening"};
};

}  // namespace

std::vector<KeywordSpec> plasticity_keyword_specs() {
  std::vector<KeywordSpec> specs;
  specs.push_back(behavior_suboption_spec(
      "CONNECTOR PLASTICITY", {component_param_spec()},
      [] { return std::unique_ptr<KeywordHandler>(new PlasticityHandler()); }, DataMode::None));
  std::vector<ParamSpec> params = {
      ParamSpec{"TYPE", ParamKind::Enum, false, {"ISOTROPIC", "KINEMATIC"}},
      ParamSpec{"DEFINITION",
                ParamKind::Enum,
                false,
                {"TABULAR", "EXPONENTIAL LAW", "HALF CYCLE", "STABILIZED", "PARAMETERS"}},
      ParamSpec{"DEPENDENCIES", ParamKind::Value},
      extrapolation_param_spec(),
  };
  for (ParamSpec& p : rate_param_specs()) params.push_back(std::move(p));
  for (ParamSpec& p : regularize_param_specs()) params.push_back(std::move(p));
  specs.push_back(behavior_suboption_spec("CONNECTOR HARDENING", std::move(params), [] {
    return std::unique_ptr<KeywordHandler>(new HardeningHandler());
  }));
  return specs;
}

}  // namespace clinch
