// *CONNECTOR DAMAGE INITIATION and *CONNECTOR DAMAGE EVOLUTION (behaviors.md §7.1, §7.2). Both
// are owners of a following *CONNECTOR POTENTIAL (derived-components-and-potentials.md §2.7); an
// evolution attaches to the nearest preceding initiation that has no evolution yet (§2). Rules
// that need the plasticities or the connection type are checked by check_behaviors.
#include <fmt/format.h>

#include "parser/block_context.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keywords/behavior_option_common.hpp"

namespace clinch {
namespace {

class InitiationHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    behavior_ = current_behavior(ctx);
    if (!behavior_) return;
    const ParamSet& params = ctx.params();
    warn_explicit_only(ctx, {"RATE FILTER FACTOR", "RATE INTERPOLATION", "REGULARIZE", "RTOL"});
    DamageInitiation init;
    init.loc = ctx.keyword().loc;
    std::optional<int> component = component_param(ctx);
    const bool has_component = params.has("COMPONENT");
    init.valid = component.has_value();
    init.component = has_component ? component.value_or(-1) : 0;
    init.component_loc = params.loc("COMPONENT", true);
    std::string_view criterion = params.enum_value("CRITERION");
    init.criterion = criterion == "MOTION"           ? DamageInitiation::Criterion::Motion
                     : criterion == "PLASTIC MOTION" ? DamageInitiation::Criterion::PlasticMotion
                                                     : DamageInitiation::Criterion::Force;
    init.criterion_loc = params.has("CRITERION") ? params.loc("CRITERION", true) : init.loc;
    init.extrapolation = option_extrapolation(ctx, *behavior_);
    if (!check_dependencies(ctx, "connector damage initiation")) {
      init.valid = false;
      ignore_data_ = true;
    }
    plastic_ = init.criterion == DamageInitiation::Criterion::PlasticMotion;
    deps_ = plastic_ ? DependenceColumns(3, 4, "connector damage initiation")
                     : DependenceColumns(2, 5, "connector damage initiation");
    behavior_->damage_initiations.push_back(init);
    index_ = behavior_->damage_initiations.size() - 1;

    PotentialOwner owner;
    owner.kind = PotentialOwner::Kind::DamageInitiation;
    owner.index = static_cast<std::int32_t>(index_);
    owner.loc = init.loc;
    // derived-components-and-potentials.md §2.7: required for a coupled FORCE/MOTION criterion,
    // forbidden with COMPONENT= and with CRITERION=PLASTIC MOTION.
    owner.requires_potential = !has_component && !plastic_;
    owner.allows_potential = owner.requires_potential;
    if (has_component) {
      const Field* value = params.value("COMPONENT");
      owner.why_not_allowed = fmt::format("COMPONENT={}", value ? value->text : std::string());
    } else if (plastic_) {
      owner.why_not_allowed = "CRITERION=PLASTIC MOTION";
    }
    behavior_->potential_owners.push_back(std::move(owner));
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (!behavior_ || ignore_data_) return;
    DamageInitiation& init = behavior_->damage_initiations[index_];
    ++rows_;
    if (!deps_.check_row(ctx, fields)) {
      init.valid = false;
      return;
    }
    if (rows_ > 1) {
      if (rows_ == 2) {
        if (plastic_) {
          // §0 / §7.1: v1 reads one row; more rows carry mode-mix or rate dependence.
          ctx.report(DiagCode::unsupported_dependencies, line.loc,
                     "plastic-motion damage initiation data with more than one row (mode-mix "
                     "or rate dependence) is not supported");
        } else {
          report_extra_line(ctx, line, "lower limit, upper limit, temperature, fields");
        }
      }
      init.valid = false;
      return;
    }
    init.data_loc = line.loc;
    plastic_ ? plastic_line(ctx, line, fields, init) : limits_line(ctx, line, fields, init);
  }

  void end(BlockContext& ctx) override {
    if (!behavior_ || ignore_data_) return;
    DamageInitiation& init = behavior_->damage_initiations[index_];
    deps_.finish(ctx);
    if (rows_ == 0) {
      report_missing_data(ctx, plastic_ ? "equivalent plastic motion"
                                        : "lower limit, "
                                          "upper limit");
      init.valid = false;
    }
  }

 private:
  void limits_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields,
                   DamageInitiation& init) {
    ctx.check_field_count(line, fields, 8,
                          "lower limit, upper limit, temperature, "
                          "field1..field5");
    const bool force = init.criterion == DamageInitiation::Criterion::Force;
    bool bad_lower = false, bad_upper = false;
    init.lower = optional_real(ctx, fields, 0, "lower limit", &bad_lower);
    init.upper = optional_real(ctx, fields, 1, "upper limit", &bad_upper);
    if (bad_lower || bad_upper) {
      init.valid = false;
      return;
    }
    if (!init.lower && !init.upper) {
      ctx.report(DiagCode::damage_no_limit, line.loc,
                 fmt::format("*CONNECTOR DAMAGE INITIATION needs a lower or an upper {} limit",
                             force ? "force" : "motion"));
      init.valid = false;
      return;
    }
    // §7.1: the lower limit bounds compression (negative), the upper one tension (positive);
    // r = value/limit on each side, so a limit of the wrong sign (or 0) can never be a ratio
    // that grows towards 1.
    if (init.lower && !(*init.lower < 0)) {
      ctx.report(DiagCode::value_out_of_range, fields[0],
                 fmt::format("the lower damage initiation limit must be negative, got {}",
                             fields[0].text));
      init.valid = false;
    }
    if (init.upper && !(*init.upper > 0)) {
      ctx.report(DiagCode::value_out_of_range, fields[1],
                 fmt::format("the upper damage initiation limit must be positive, got {}",
                             fields[1].text));
      init.valid = false;
    }
  }

  void plastic_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields,
                    DamageInitiation& init) {
    ctx.check_field_count(line, fields, 8,
                          "u^pl_0, mode-mix, rate, temperature, "
                          "field1..field4");
    std::optional<double> u = required_real(ctx, line, fields, 0, "equivalent plastic motion");
    if (!u) {
      init.valid = false;
      return;
    }
    init.plastic_motion = *u;
    if (*u <= 0) {
      ctx.report(DiagCode::value_out_of_range, fields[0],
                 fmt::format("the equivalent plastic motion at damage initiation must be "
                             "positive, got {}",
                             fields[0].text));
      init.valid = false;
    }
  }

  ConnectorBehavior* behavior_ = nullptr;
  std::size_t index_ = 0;
  std::size_t rows_ = 0;
  bool plastic_ = false;
  bool ignore_data_ = false;
  DependenceColumns deps_{2, 5, "connector damage initiation"};
};

class EvolutionHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    behavior_ = current_behavior(ctx);
    if (!behavior_) return;
    const ParamSet& params = ctx.params();
    warn_explicit_only(ctx, {"REGULARIZE", "RTOL"});
    DamageEvolution evo;
    evo.loc = ctx.keyword().loc;
    evo.type = params.enum_value("TYPE") == "ENERGY" ? DamageEvolution::Type::Energy
                                                     : DamageEvolution::Type::Motion;
    std::string_view softening = params.enum_value("SOFTENING");
    evo.softening = softening == "EXPONENTIAL" ? DamageEvolution::Softening::Exponential
                    : softening == "TABULAR"   ? DamageEvolution::Softening::Tabular
                                               : DamageEvolution::Softening::Linear;
    evo.degradation = params.enum_value("DEGRADATION") == "MULTIPLICATIVE"
                          ? DamageEvolution::Degradation::Multiplicative
                          : DamageEvolution::Degradation::Maximum;
    evo.extrapolation = option_extrapolation(ctx, *behavior_);
    affected_ = params.has("AFFECTED COMPONENTS");
    if (evo.type == DamageEvolution::Type::Energy &&
        evo.softening == DamageEvolution::Softening::Tabular) {
      ctx.report(DiagCode::conflicting_parameters, params.loc("SOFTENING", true),
                 "SOFTENING=TABULAR is only valid with TYPE=MOTION");
      evo.valid = false;
      ignore_data_ = true;
    }
    if (!check_dependencies(ctx, "connector damage evolution")) {
      evo.valid = false;
      ignore_data_ = true;
    }
    // §2: the nearest preceding initiation that has no evolution yet.
    auto& inits = behavior_->damage_initiations;
    for (std::size_t k = inits.size(); k-- > 0;) {
      if (inits[k].evolution < 0) {
        evo.initiation = static_cast<std::int32_t>(k);
        break;
      }
    }
    const std::int32_t own_index = static_cast<std::int32_t>(behavior_->damage_evolutions.size());
    PotentialOwner owner;
    owner.kind = PotentialOwner::Kind::DamageEvolution;
    owner.index = own_index;
    owner.loc = evo.loc;
    if (evo.initiation < 0) {
      ctx.report(DiagCode::evolution_no_initiation, evo.loc,
                 "*CONNECTOR DAMAGE EVOLUTION must follow a *CONNECTOR DAMAGE INITIATION that "
                 "has no evolution yet");
      evo.valid = false;
      // The orphan still owns a following potential, so that no second error is reported.
    } else {
      DamageInitiation& init = inits[static_cast<std::size_t>(evo.initiation)];
      init.evolution = own_index;
      // derived-components-and-potentials.md §2.7: optional, coupled FORCE/MOTION case only.
      if (!init.coupled()) {
        owner.allows_potential = false;
        owner.why_not_allowed =
            init.component > 0
                ? fmt::format("COMPONENT={} on its damage initiation", init.component)
                : "COMPONENT= on its damage initiation";
      } else if (init.criterion == DamageInitiation::Criterion::PlasticMotion) {
        owner.allows_potential = false;
        owner.why_not_allowed = "CRITERION=PLASTIC MOTION on its damage initiation";
      }
    }
    switch (evo.type == DamageEvolution::Type::Energy ? DamageEvolution::Softening::Linear
                                                      : evo.softening) {
      case DamageEvolution::Softening::Linear:
        deps_ = DependenceColumns(2, 5, "connector damage evolution");
        break;
      case DamageEvolution::Softening::Exponential:
      case DamageEvolution::Softening::Tabular:
        deps_ = DependenceColumns(3, 4, "connector damage evolution");
        break;
    }
    behavior_->damage_evolutions.push_back(evo);
    index_ = behavior_->damage_evolutions.size() - 1;
    behavior_->potential_owners.push_back(std::move(owner));
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (!behavior_ || ignore_data_) return;
    DamageEvolution& evo = behavior_->damage_evolutions[index_];
    if (affected_ && !affected_read_) {
      affected_read_ = true;
      affected_line(ctx, line, fields, evo);
      return;
    }
    ++rows_;
    if (!deps_.check_row(ctx, fields)) {
      evo.valid = false;
      return;
    }
    const bool tabular = evo.type == DamageEvolution::Type::Motion &&
                         evo.softening == DamageEvolution::Softening::Tabular;
    if (tabular) return tabular_line(ctx, line, fields, evo);
    if (rows_ > 1) {
      if (rows_ == 2) report_extra_line(ctx, line, layout(evo));
      evo.valid = false;
      return;
    }
    evo.data_loc = line.loc;
    ctx.check_field_count(line, fields, 8, layout(evo));
    if (evo.type == DamageEvolution::Type::Energy) {
      std::optional<double> g = required_real(ctx, line, fields, 0, "fracture energy");
      if (!g) {
        evo.valid = false;
        return;
      }
      evo.fracture_energy = *g;
      if (*g <= 0) positive_error(ctx, fields[0], "the damage evolution energy G_f", evo);
      return;
    }
    std::optional<double> du = required_real(ctx, line, fields, 0, "motion at failure");
    if (!du) {
      evo.valid = false;
      return;
    }
    evo.failure_motion = *du;
    if (*du <= 0) positive_error(ctx, fields[0], "the motion at ultimate failure", evo);
    if (evo.softening == DamageEvolution::Softening::Exponential) {
      std::optional<double> a = required_real(ctx, line, fields, 1, "exponential law parameter");
      if (!a) {
        evo.valid = false;
        return;
      }
      evo.exponent = *a;
      if (*a <= 0) positive_error(ctx, fields[1], "the exponential law parameter a", evo);
    }
  }

  void end(BlockContext& ctx) override {
    if (!behavior_ || ignore_data_) return;
    DamageEvolution& evo = behavior_->damage_evolutions[index_];
    deps_.finish(ctx);
    if (affected_ && !affected_read_) {
      report_missing_data(ctx, "the affected components, then the damage evolution data");
      evo.valid = false;
      return;
    }
    if (rows_ == 0) {
      report_missing_data(ctx, layout(evo));
      evo.valid = false;
      return;
    }
    if (evo.softening == DamageEvolution::Softening::Tabular && evo.valid && !evo.table.empty()) {
      const TablePoint& first = evo.table.front();
      if (first.value != 0 || first.at != 0) {
        ctx.report(DiagCode::damage_table_first_point, first.loc,
                   "the first row of a TABULAR damage evolution should be 0, 0 (no damage at "
                   "initiation)");
      }
    }
  }

 private:
  static std::string_view layout(const DamageEvolution& evo) {
    if (evo.type == DamageEvolution::Type::Energy) {
      return "G_f, mode-mix, temperature, field1..field5";
    }
    switch (evo.softening) {
      case DamageEvolution::Softening::Linear:
        return "motion at failure, mode-mix, temperature, field1..field5";
      case DamageEvolution::Softening::Exponential:
        return "motion at failure, a, mode-mix, temperature, field1..field4";
      case DamageEvolution::Softening::Tabular:
        return "d, motion, mode-mix, temperature, field1..field4";
    }
    return "";
  }

  static void positive_error(BlockContext& ctx, const Field& field, std::string_view what,
                             DamageEvolution& evo) {
    ctx.report(DiagCode::value_out_of_range, field,
               fmt::format("{} must be positive, got {}", what, field.text));
    evo.valid = false;
  }

  void affected_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields,
                     DamageEvolution& evo) {
    ctx.check_field_count(line, fields, 6, "affected components");
    evo.affected_loc = fields.empty() ? line.loc : fields.front().loc;
    for (std::size_t k = 0; k < fields.size() && k < 6; ++k) {
      if (fields[k].empty()) continue;
      std::optional<int> c = component_field(ctx, fields[k], "affected component");
      if (!c) {
        evo.valid = false;
        continue;
      }
      evo.affected |= static_cast<std::uint8_t>(1u << (*c - 1));
    }
    if (evo.affected == 0 && evo.valid) {
      ctx.missing(fields.empty() ? line.loc : fields.front().loc, "affected component");
      evo.valid = false;
    }
  }

  void tabular_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields,
                    DamageEvolution& evo) {
    ctx.check_field_count(line, fields, 8, layout(evo));
    if (rows_ == 1) evo.data_loc = line.loc;
    std::optional<double> d = required_real(ctx, line, fields, 0, "damage");
    bool bad = false;
    std::optional<double> delta = optional_real(ctx, fields, 1, "motion", &bad);
    if (!d || bad) {
      evo.valid = false;
      return;
    }
    const double at = delta.value_or(0.0);  // a blank field is 0
    if (*d < 0 || *d > 1) {
      ctx.report(DiagCode::value_out_of_range, fields[0],
                 fmt::format("damage must lie between 0 and 1, got {}", fields[0].text));
      evo.valid = false;
    }
    const Field& at_field = fields.size() > 1 && !fields[1].empty() ? fields[1] : fields[0];
    if (!evo.table.empty() && !(at > evo.table.back().at)) {
      if (!increasing_reported_) {
        ctx.report(DiagCode::table_not_increasing, at_field,
                   fmt::format("post-initiation motions must increase ({} after {})",
                               delta ? at_field.text : "0", last_at_text_));
      }
      increasing_reported_ = true;
      evo.valid = false;
      return;
    }
    evo.table.push_back({*d, at, fields[0].loc});
    last_at_text_ = delta ? at_field.text : "0";
  }

  ConnectorBehavior* behavior_ = nullptr;
  std::size_t index_ = 0;
  std::size_t rows_ = 0;
  bool affected_ = false;
  bool affected_read_ = false;
  bool ignore_data_ = false;
  bool increasing_reported_ = false;
  std::string last_at_text_;
  DependenceColumns deps_{2, 5, "connector damage evolution"};
};

}  // namespace

std::vector<KeywordSpec> damage_keyword_specs() {
  std::vector<KeywordSpec> specs;
  std::vector<ParamSpec> init_params = {
      component_param_spec(),
      ParamSpec{"CRITERION", ParamKind::Enum, false, {"FORCE", "MOTION", "PLASTIC MOTION"}},
      ParamSpec{"DEPENDENCIES", ParamKind::Value},
      extrapolation_param_spec(),
  };
  for (ParamSpec& p : rate_param_specs()) init_params.push_back(std::move(p));
  for (ParamSpec& p : regularize_param_specs()) init_params.push_back(std::move(p));
  specs.push_back(behavior_suboption_spec(
      "CONNECTOR DAMAGE INITIATION", std::move(init_params),
      [] { return std::unique_ptr<KeywordHandler>(new InitiationHandler()); }));
  std::vector<ParamSpec> evo_params = {
      ParamSpec{"TYPE", ParamKind::Enum, true, {"MOTION", "ENERGY"}},
      ParamSpec{"SOFTENING", ParamKind::Enum, false, {"LINEAR", "EXPONENTIAL", "TABULAR"}},
      ParamSpec{"DEGRADATION", ParamKind::Enum, false, {"MAXIMUM", "MULTIPLICATIVE"}},
      ParamSpec{"AFFECTED COMPONENTS", ParamKind::Flag},
      ParamSpec{"DEPENDENCIES", ParamKind::Value},
      extrapolation_param_spec(),
  };
  for (ParamSpec& p : regularize_param_specs()) evo_params.push_back(std::move(p));
  specs.push_back(behavior_suboption_spec("CONNECTOR DAMAGE EVOLUTION", std::move(evo_params), [] {
    return std::unique_ptr<KeywordHandler>(new EvolutionHandler());
  }));
  return specs;
}

}  // namespace clinch
