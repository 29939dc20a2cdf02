// *CONNECTOR BEHAVIOR (behaviors.md §2), *CONNECTOR CONSTITUTIVE REFERENCE (§3) and
// *CONNECTOR DAMPING (§8), and the behaviour keyword family: the other sub-options live in
// elasticity.cpp, stop_lock.cpp, plasticity.cpp and damage.cpp. The reader opens the behaviour
// block (ReaderPosition::in_behavior); the handler here creates the ConnectorBehavior that the
// sub-options of the block fill.
#include <fmt/format.h>

#include <numbers>

#include "parser/block_context.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keywords/behavior_option_common.hpp"
#include "parser/keywords/keyword_families.hpp"

namespace clinch {
namespace {

class BehaviorHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    BehaviorModel& model = ctx.model().behaviors;
    warn_explicit_only(ctx, {"INTEGRATION", "REGULARIZE", "RTOL"});
    ConnectorBehavior behavior;
    behavior.loc = ctx.keyword().loc;
    std::string_view extrapolation = ctx.params().enum_value("EXTRAPOLATION");
    if (!extrapolation.empty()) behavior.extrapolation = std::string(extrapolation);
    std::optional<Name> name = ctx.name_param("NAME");
    if (!name) {
      // The sub-options of the block are still read and checked, but nothing can use them.
      behavior.referable = false;
    } else {
      behavior.name = *name;
      auto found = model.by_key.find(name->key);
      // -1: a block of that name was refused (its parameters failed); this one defines it.
      if (found != model.by_key.end() && found->second >= 0) {
        const ConnectorBehavior& first = model.behaviors[static_cast<std::size_t>(found->second)];
        Diagnostic& d =
            ctx.report(DiagCode::duplicate_name, *ctx.params().value("NAME"),
                       fmt::format("connector behavior '{}' is already defined", name->display));
        d.notes.push_back({first.name.loc, "previous definition is here"});
        behavior.referable = false;
      } else {
        model.by_key[name->key] = static_cast<std::int32_t>(model.behaviors.size());
      }
    }
    model.behaviors.push_back(std::move(behavior));
  }
};

class ReferenceHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    behavior_ = current_behavior(ctx);
    if (!behavior_) return;
    if (behavior_->reference) {
      // Not specified: clinch keeps the later definition and says so.
      Diagnostic& d = ctx.report(DiagCode::keyword_ignored, behavior_->reference->loc,
                                 "*CONNECTOR CONSTITUTIVE REFERENCE is given again later in "
                                 "this behavior; this one is ignored");
      d.notes.push_back({ctx.keyword().loc, "the later definition is here"});
    }
    behavior_->reference.emplace();
    behavior_->reference->loc = ctx.keyword().loc;
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (!behavior_) return;
    if (++rows_ > 1) {
      if (rows_ == 2) report_extra_line(ctx, line, "one reference value per component");
      return;
    }
    ConstitutiveReference& ref = *behavior_->reference;
    ctx.check_field_count(line, fields, 6, "reference values of components 1-6");
    for (std::size_t k = 0; k < fields.size() && k < 6; ++k) {
      bool bad = false;
      std::optional<double> v =
          optional_real(ctx, fields, k, fmt::format("reference of component {}", k + 1), &bad);
      if (!v) continue;
      // §3: fields 4–6 are angles in degrees; clinch works in radians.
      ref.value[k] = k >= 3 ? *v * std::numbers::pi / 180.0 : *v;
      ref.value_loc[k] = fields[k].loc;
    }
  }

  void end(BlockContext& ctx) override {
    if (behavior_ && rows_ == 0) report_missing_data(ctx, "reference values");
  }

 private:
  ConnectorBehavior* behavior_ = nullptr;
  std::size_t rows_ = 0;
};

// §8: viscous damping acts in *STATIC with velocities Δu/Δt; TYPE=STRUCTURAL has no effect
// there, and the forms v1 does not support are refused at their parameter.
class DampingHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    behavior_ = current_behavior(ctx);
    if (!behavior_) return;
    const ParamSet& params = ctx.params();
    warn_explicit_only(ctx, {"REGULARIZE", "RTOL"});
    ConnectorDamping damping;
    damping.loc = ctx.keyword().loc;
    std::optional<int> component = component_param(ctx);
    damping.component = component.value_or(0);
    damping.component_loc = params.loc("COMPONENT", true);
    damping.extrapolation = option_extrapolation(ctx, *behavior_);
    valid_ = component.has_value();
    const bool has_component = params.has("COMPONENT");
    if (params.has("INDEPENDENT COMPONENTS")) {
      // Its first data line lists components: not a table row (behaviors.md §8).
      ctx.report(DiagCode::unsupported_option, params.loc("INDEPENDENT COMPONENTS"),
                 "INDEPENDENT COMPONENTS on *CONNECTOR DAMPING is not supported in this "
                 "version; give the damping against the component's own velocity");
      valid_ = false;
    }
    if (params.enum_value("TYPE") == "STRUCTURAL") {
      ctx.report(DiagCode::damping_structural_ignored, params.loc("TYPE"),
                 "TYPE=STRUCTURAL connector damping acts only in steady-state dynamics; it has "
                 "no effect in *STATIC and *DYNAMIC steps and is ignored");
      damping.structural = true;
    }
    if (params.enum_value("TYPE") == "RAYLEIGH") {
      damping.kind = ConnectorDamping::Kind::Rayleigh;
      ctx.report(DiagCode::unsupported_option, params.loc("TYPE"),
                 "TYPE=RAYLEIGH connector damping is not supported in this version; give the "
                 "damping coefficient with TYPE=VISCOUS");
      valid_ = false;
    } else if (params.has("NONLINEAR")) {
      damping.kind = ConnectorDamping::Kind::Nonlinear;
      if (!has_component) {
        ctx.report(DiagCode::missing_parameter, params.loc("NONLINEAR"),
                   "NONLINEAR connector damping needs COMPONENT");
        valid_ = false;
      }
    } else {
      damping.kind =
          has_component ? ConnectorDamping::Kind::Linear : ConnectorDamping::Kind::Coupled;
    }
    // §0: v1 rejects these options; the rest of the block is then ignored.
    if (params.has("UNSYMM")) {
      ctx.report(DiagCode::unsupported_option, params.loc("UNSYMM"),
                 "UNSYMM connector damping is not supported by clinch");
      valid_ = false;
    }
    if (params.enum_value("FREQUENCY DEPENDENCE") == "ON") {
      ctx.report(DiagCode::unsupported_option, params.loc("FREQUENCY DEPENDENCE", true),
                 "FREQUENCY DEPENDENCE=ON is not supported by clinch");
      valid_ = false;
    }
    if (!check_dependencies(ctx, "connector damping")) valid_ = false;
    behavior_->dampings.push_back(damping);
    index_ = behavior_->dampings.size() - 1;
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (!behavior_ || !valid_) return;
    ConnectorDamping& damping = behavior_->dampings[index_];
    ++rows_;
    if (damping.kind == ConnectorDamping::Kind::Coupled) return coupled_line(ctx, line, fields);
    // Numbers only.
    for (const Field& f : fields) {
      if (!f.empty() && !ctx.real(f, "damping data")) return;
    }
    switch (damping.kind) {
      case ConnectorDamping::Kind::Linear:
      case ConnectorDamping::Kind::Rayleigh: {
        if (rows_ > 1 && !(fields.size() > 2 && !fields[2].empty())) {
          if (rows_ == 2) report_extra_line(ctx, line, "damping coefficient, ...");
          return;
        }
        if (rows_ > 1) {
          // A second row with a temperature: the coefficient varies with it (§0: v1 rejects).
          if (rows_ == 2) {
            ctx.report(DiagCode::unsupported_dependencies, fields[2],
                       "connector damping that varies with temperature is not supported in "
                       "this version");
          }
          return;
        }
        ctx.check_field_count(line, fields, 8, "c, frequency, temperature, field1..field5");
        std::optional<double> c = required_real(ctx, line, fields, 0, "damping coefficient");
        if (c) damping.coefficient = *c;
        if (damping.kind == ConnectorDamping::Kind::Rayleigh) {
          damping.alpha = damping.coefficient;
          bool bad = false;
          damping.beta = optional_real(ctx, fields, 1, "beta", &bad).value_or(0.0);
        }
        return;
      }
      case ConnectorDamping::Kind::Nonlinear: {
        ctx.check_field_count(line, fields, 8, "force, velocity, temperature, field1..field5");
        std::optional<double> f = required_real(ctx, line, fields, 0, "force");
        std::optional<double> v = required_real(ctx, line, fields, 1, "velocity");
        if (!f || !v) return;
        if (!damping.table.empty() && !(*v > damping.table.back().at)) {
          if (!increasing_reported_) {
            ctx.report(DiagCode::table_not_increasing, fields[1],
                       fmt::format("relative velocities must increase ({} after {})",
                                   fields[1].text, last_at_text_));
          }
          increasing_reported_ = true;
          return;
        }
        damping.table.push_back({*f, *v, fields[0].loc});
        last_at_text_ = fields[1].text;
        return;
      }
      case ConnectorDamping::Kind::Coupled:
        return;
    }
  }

  void end(BlockContext& ctx) override {
    if (!behavior_ || !valid_) return;
    const ConnectorDamping& damping = behavior_->dampings[index_];
    if (rows_ == 0) {
      report_missing_data(ctx, "damping data");
    } else if (damping.kind == ConnectorDamping::Kind::Nonlinear && damping.table.size() < 2 &&
               !increasing_reported_ && damping.table.size() == rows_) {
      ctx.report(DiagCode::table_too_short, ctx.keyword().loc,
                 fmt::format("nonlinear connector damping needs at least 2 points, got {}",
                             damping.table.size()));
    } else if (damping.kind == ConnectorDamping::Kind::Coupled && rows_ < 3) {
      ctx.missing(last_line_end_, "damping term");
    }
  }

 private:
  void coupled_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    ConnectorDamping& damping = behavior_->dampings[index_];
    last_line_end_ = BlockContext::end_of_line(line);
    if (rows_ > 3) {
      if (rows_ == 4) {
        report_extra_line(ctx, line, "21 damping terms on three data lines");
      }
      return;
    }
    ctx.check_field_count(line, fields, 8, "damping terms");
    const std::size_t first = rows_ == 1 ? 0 : rows_ == 2 ? 8 : 16;
    const std::size_t count = rows_ == 3 ? 5 : 8;
    for (std::size_t k = 0; k < count; ++k) {
      std::optional<double> v = required_real(ctx, line, fields, k, "damping term");
      if (!v) {
        if (k >= fields.size()) break;
        continue;
      }
      damping.coupled_terms[first + k] = *v;
    }
  }

  ConnectorBehavior* behavior_ = nullptr;
  std::size_t index_ = 0;
  std::size_t rows_ = 0;
  bool valid_ = true;
  bool increasing_reported_ = false;
  std::string last_at_text_;
  SourceLoc last_line_end_;
};

}  // namespace

std::vector<KeywordSpec> behavior_keyword_specs() {
  std::vector<KeywordSpec> specs;
  KeywordSpec behavior;
  behavior.name = "CONNECTOR BEHAVIOR";
  behavior.level = KeywordLevel::Model;
  behavior.data = DataMode::None;
  behavior.params = {
      ParamSpec{"NAME", ParamKind::Value, true},
      extrapolation_param_spec(),
      ParamSpec{"INTEGRATION", ParamKind::Enum, false, {"IMPLICIT", "EXPLICIT"}},
  };
  for (ParamSpec& p : regularize_param_specs()) behavior.params.push_back(std::move(p));
  behavior.make_handler = [] { return std::unique_ptr<KeywordHandler>(new BehaviorHandler()); };
  specs.push_back(std::move(behavior));

  specs.push_back(behavior_suboption_spec("CONNECTOR CONSTITUTIVE REFERENCE", {}, [] {
    return std::unique_ptr<KeywordHandler>(new ReferenceHandler());
  }));

  std::vector<ParamSpec> damping_params = {
      component_param_spec(),
      ParamSpec{"NONLINEAR", ParamKind::Flag},
      ParamSpec{"TYPE", ParamKind::Enum, false, {"VISCOUS", "STRUCTURAL", "RAYLEIGH"}},
      ParamSpec{"DEPENDENCIES", ParamKind::Value},
      extrapolation_param_spec(),
      ParamSpec{"FREQUENCY DEPENDENCE", ParamKind::Enum, false, {"OFF", "ON"}},
      ParamSpec{
          "INDEPENDENT COMPONENTS", ParamKind::Enum, false, {"POSITION", "CONSTITUTIVE MOTION"}},
      ParamSpec{"UNSYMM", ParamKind::Flag},
  };
  for (ParamSpec& p : regularize_param_specs()) damping_params.push_back(std::move(p));
  specs.push_back(behavior_suboption_spec("CONNECTOR DAMPING", std::move(damping_params), [] {
    return std::unique_ptr<KeywordHandler>(new DampingHandler());
  }));

  for (auto* family : {&elasticity_keyword_specs, &stop_lock_keyword_specs,
                       &plasticity_keyword_specs, &damage_keyword_specs}) {
    for (KeywordSpec& spec : family()) specs.push_back(std::move(spec));
  }
  return specs;
}

}  // namespace clinch
