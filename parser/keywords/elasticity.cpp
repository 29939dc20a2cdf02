// *CONNECTOR ELASTICITY (behaviors.md §4): linear and nonlinear uncoupled, coupled linear (21
// terms), RIGID. Reads the data into ConnectorElasticity and reports what one option can know on
// its own; the per-component rules (duplicates, plasticity) and everything that needs the
// connection type are checked by check_behaviors.
#include <fmt/format.h>

#include <cmath>

#include "parser/block_context.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keywords/behavior_option_common.hpp"

namespace clinch {
namespace {

// The 21 coupled terms in input order: the upper triangle column by column (§4.3; the order
// is not confirmed against Abaqus, behaviors.md §9.1).
constexpr std::array<std::string_view, 21> kCoupledTermNames = {
    "D11", "D12", "D22", "D13", "D23", "D33", "D14", "D24", "D34", "D44", "D15",
    "D25", "D35", "D45", "D55", "D16", "D26", "D36", "D46", "D56", "D66"};

// Force of a piecewise-linear table at `u` with the extrapolation rule of §1.2 / §4.2.
double table_value(const std::vector<TablePoint>& table, double u, Extrapolation extrapolation) {
  if (table.empty()) return 0;
  if (table.size() == 1) return table.front().value;
  auto segment = [&](std::size_t k) {
    const TablePoint& a = table[k];
    const TablePoint& b = table[k + 1];
    return a.value + (b.value - a.value) * (u - a.at) / (b.at - a.at);
  };
  if (u <= table.front().at) {
    return extrapolation == Extrapolation::Linear ? segment(0) : table.front().value;
  }
  if (u >= table.back().at) {
    return extrapolation == Extrapolation::Linear ? segment(table.size() - 2) : table.back().value;
  }
  for (std::size_t k = 0; k + 1 < table.size(); ++k) {
    if (u <= table[k + 1].at) return segment(k);
  }
  return table.back().value;
}

class ElasticityHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    behavior_ = current_behavior(ctx);
    if (!behavior_) return;
    warn_explicit_only(ctx, {"REGULARIZE", "RTOL"});
    ConnectorElasticity el;
    el.loc = ctx.keyword().loc;
    const ParamSet& params = ctx.params();
    std::optional<int> component = component_param(ctx);
    if (!component) el.valid = false;
    el.component = component.value_or(0);
    el.component_loc = params.loc("COMPONENT", true);
    const bool has_component = params.has("COMPONENT");
    const bool nonlinear = params.has("NONLINEAR");
    const bool rigid = params.has("RIGID");
    // §0: v1 rejects these options; the rest of the block is then ignored.
    if (params.has("UNSYMM")) {
      ctx.report(DiagCode::unsupported_option, params.loc("UNSYMM"),
                 "UNSYMM connector elasticity is not supported by clinch");
      el.valid = false;
      ignore_data_ = true;
    }
    if (params.enum_value("FREQUENCY DEPENDENCE") == "ON") {
      ctx.report(DiagCode::unsupported_option, params.loc("FREQUENCY DEPENDENCE", true),
                 "FREQUENCY DEPENDENCE=ON is not supported by clinch");
      el.valid = false;
      ignore_data_ = true;
    }
    if (params.has("INDEPENDENT COMPONENTS")) {
      ctx.report(DiagCode::unsupported_option, params.loc("INDEPENDENT COMPONENTS"),
                 "INDEPENDENT COMPONENTS is not supported by clinch");
      el.valid = false;
      ignore_data_ = true;
    }
    if (!check_dependencies(ctx, "connector elasticity")) {
      el.valid = false;
      ignore_data_ = true;
    }
    if (nonlinear && rigid) {
      ctx.report(DiagCode::conflicting_parameters, params.loc("RIGID"),
                 "NONLINEAR and RIGID cannot be used together on *CONNECTOR ELASTICITY");
      el.valid = false;
      ignore_data_ = true;
    } else if (nonlinear && !has_component) {
      ctx.report(DiagCode::missing_parameter, params.loc("NONLINEAR"),
                 "NONLINEAR connector elasticity needs COMPONENT");
      el.valid = false;
      ignore_data_ = true;
    }
    if (rigid) {
      el.kind = ConnectorElasticity::Kind::Rigid;
      el.rigid_all = !has_component;
      if (has_component && component && *component > 0) {
        el.rigid_components = component_bit_of(*component);
      }
    } else if (nonlinear) {
      el.kind = ConnectorElasticity::Kind::Nonlinear;
    } else if (has_component) {
      el.kind = ConnectorElasticity::Kind::Linear;
    } else {
      el.kind = ConnectorElasticity::Kind::Coupled;
    }
    el.extrapolation = option_extrapolation(ctx, *behavior_);
    behavior_->elasticities.push_back(std::move(el));
    index_ = behavior_->elasticities.size() - 1;
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (!behavior_ || ignore_data_) return;
    ConnectorElasticity& el = behavior_->elasticities[index_];
    ++rows_;
    if (rows_ == 1) el.data_loc = fields.empty() ? line.loc : fields.front().loc;
    switch (el.kind) {
      case ConnectorElasticity::Kind::Linear:
        return linear_line(ctx, line, fields, el);
      case ConnectorElasticity::Kind::Nonlinear:
        return nonlinear_line(ctx, line, fields, el);
      case ConnectorElasticity::Kind::Coupled:
        return coupled_line(ctx, line, fields, el);
      case ConnectorElasticity::Kind::Rigid:
        return rigid_line(ctx, line, fields, el);
    }
  }

  void end(BlockContext& ctx) override {
    if (!behavior_ || ignore_data_) return;
    ConnectorElasticity& el = behavior_->elasticities[index_];
    deps_.finish(ctx);
    if (deps_.rejected()) el.valid = false;
    switch (el.kind) {
      case ConnectorElasticity::Kind::Linear:
        if (rows_ == 0) {
          report_missing_data(ctx, "k");
          el.valid = false;
        }
        break;
      case ConnectorElasticity::Kind::Nonlinear:
        finish_nonlinear(ctx, el);
        break;
      case ConnectorElasticity::Kind::Coupled:
        finish_coupled(ctx, el);
        break;
      case ConnectorElasticity::Kind::Rigid:
        // §4.4: without COMPONENT, an omitted or blank line means all available components.
        if (!ctx.params().has("COMPONENT")) el.rigid_all = listed_ == 0;
        break;
    }
  }

 private:
  static std::uint8_t component_bit_of(int component) {
    return static_cast<std::uint8_t>(1u << (component - 1));
  }

  void linear_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields,
                   ConnectorElasticity& el) {
    if (!deps_.check_row(ctx, fields)) {
      el.valid = false;
      return;
    }
    if (rows_ > 1) {
      if (!extra_reported_) report_extra_line(ctx, line, "k, frequency, temperature, fields");
      extra_reported_ = true;
      return;
    }
    ctx.check_field_count(line, fields, 8, "k, frequency, temperature, field1..field5");
    std::optional<double> k = required_real(ctx, line, fields, 0, "k");
    if (!k) {
      el.valid = false;
      return;
    }
    el.stiffness = *k;
    el.stiffness_loc = fields[0].loc;
    if (*k <= 0) {
      ctx.report(DiagCode::stiffness_not_positive, fields[0],
                 fmt::format("connector stiffness must be positive, got {}", fields[0].text));
    }
  }

  void nonlinear_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields,
                      ConnectorElasticity& el) {
    if (!deps_.check_row(ctx, fields)) {
      el.valid = false;
      return;
    }
    ctx.check_field_count(line, fields, 8, "force, motion, temperature, field1..field5");
    std::optional<double> f = required_real(ctx, line, fields, 0, "force");
    std::optional<double> u = required_real(ctx, line, fields, 1, "motion");
    if (!f || !u) {
      el.valid = false;
      return;
    }
    if (!el.table.empty() && !(*u > el.table.back().at) && !increasing_reported_) {
      increasing_reported_ = true;
      el.valid = false;
      ctx.report(DiagCode::table_not_increasing, fields[1],
                 fmt::format("constitutive motions must increase ({} after {})", fields[1].text,
                             last_at_text_));
      return;
    }
    if (increasing_reported_) return;
    el.table.push_back({*f, *u, fields[0].loc});
    last_at_text_ = fields[1].text;
  }

  void coupled_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields,
                    ConnectorElasticity& el) {
    if (rows_ > 3) {
      if (!extra_reported_) {
        extra_reported_ = true;
        el.valid = false;
        if (third_line_temperature_) {
          ctx.report(DiagCode::unsupported_dependencies, line.loc,
                     "temperature-dependent coupled connector elasticity data is not supported");
        } else {
          ctx.report(DiagCode::unexpected_data_line, line.loc,
                     "coupled *CONNECTOR ELASTICITY takes 21 values on three data lines");
        }
      }
      return;
    }
    const std::size_t first = rows_ == 1 ? 0 : rows_ == 2 ? 8 : 16;
    const std::size_t count = rows_ == 3 ? 5 : 8;
    if (rows_ == 3) {
      ctx.check_field_count(line, fields, 8,
                            "D26, D36, D46, D56, D66, temperature, field1, "
                            "field2");
      DependenceColumns third(5, 2, "coupled connector elasticity");
      third_line_temperature_ = fields.size() > 5 && !fields[5].empty();
      deps_ = third;
      if (!deps_.check_row(ctx, fields)) el.valid = false;
    } else {
      ctx.check_field_count(line, fields, 8, "eight stiffness terms");
    }
    for (std::size_t k = 0; k < count; ++k) {
      std::optional<double> v = required_real(ctx, line, fields, k, kCoupledTermNames[first + k]);
      if (!v) {
        el.valid = false;
        if (k >= fields.size()) break;  // one E0305 for the missing tail of the line
        continue;
      }
      el.coupled_terms[first + k] = *v;
    }
    last_line_end_ = BlockContext::end_of_line(line);
  }

  void rigid_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields,
                  ConnectorElasticity& el) {
    if (el.component != 0 || ctx.params().has("COMPONENT") || rows_ > 1) {
      if (line.blank && rows_ == 1 && ctx.params().has("COMPONENT")) return;
      if (!extra_reported_) {
        extra_reported_ = true;
        ctx.report(DiagCode::unexpected_data_line, line.loc,
                   ctx.params().has("COMPONENT")
                       ? "RIGID connector elasticity with COMPONENT takes no data line"
                       : "RIGID connector elasticity takes at most one data line (the rigid "
                         "components)");
      }
      return;
    }
    ctx.check_field_count(line, fields, 6, "rigid components");
    for (std::size_t k = 0; k < fields.size() && k < 6; ++k) {
      if (fields[k].empty()) continue;
      std::optional<int> c = component_field(ctx, fields[k], "rigid component");
      if (!c) {
        el.valid = false;
        continue;
      }
      ++listed_;
      el.rigid_components |= component_bit_of(*c);
    }
  }

  void finish_nonlinear(BlockContext& ctx, ConnectorElasticity& el) {
    if (rows_ == 0) {
      report_missing_data(ctx, "force, motion");
      el.valid = false;
      return;
    }
    if (!el.valid) return;
    if (el.table.size() < 2) {
      ctx.report(DiagCode::table_too_short, el.data_loc,
                 fmt::format("nonlinear connector elasticity needs at least 2 points, got {}",
                             el.table.size()));
      el.valid = false;
      return;
    }
    // §4.2: a table with F(0) ≠ 0 carries a force in the initial state (a built-in preload).
    double f0 = table_value(el.table, 0.0, el.extrapolation);
    double scale = 0;
    for (const TablePoint& p : el.table) scale = std::max(scale, std::fabs(p.value));
    if (std::fabs(f0) > 1e-12 * scale) {
      ctx.report(DiagCode::nonlinear_elasticity_offset, el.data_loc,
                 fmt::format("connector elasticity table gives force {} at zero motion "
                             "(a preload in the initial state)",
                             f0));
    }
    if (el.extrapolation == Extrapolation::Constant) {
      ctx.report(DiagCode::zero_tangent_extrapolation, ctx.keyword().loc,
                 fmt::format("CONSTANT extrapolation: the nonlinear elasticity of component {} "
                             "has zero stiffness beyond its table (force held at the end values)",
                             el.component));
    }
  }

  void finish_coupled(BlockContext& ctx, ConnectorElasticity& el) {
    if (rows_ == 0) {
      report_missing_data(ctx, "21 stiffness terms on three data lines");
      el.valid = false;
      return;
    }
    if (rows_ < 3) {
      const std::size_t next = rows_ == 1 ? 8 : 16;
      ctx.missing(last_line_end_, kCoupledTermNames[next]);
      el.valid = false;
      return;
    }
    el.coupled = expand_coupled_terms(el.coupled_terms);
  }

  ConnectorBehavior* behavior_ = nullptr;
  std::size_t index_ = 0;
  bool ignore_data_ = false;
  std::size_t rows_ = 0;
  std::size_t listed_ = 0;
  bool extra_reported_ = false;
  bool increasing_reported_ = false;
  bool third_line_temperature_ = false;
  std::string last_at_text_;
  SourceLoc last_line_end_;
  DependenceColumns deps_{2, 5, "connector elasticity"};
};

}  // namespace

std::vector<KeywordSpec> elasticity_keyword_specs() {
  std::vector<ParamSpec> params = {
      component_param_spec(),
      ParamSpec{"NONLINEAR", ParamKind::Flag},
      ParamSpec{"RIGID", ParamKind::Flag},
      extrapolation_param_spec(),
      ParamSpec{"DEPENDENCIES", ParamKind::Value},
      ParamSpec{"FREQUENCY DEPENDENCE", ParamKind::Enum, false, {"OFF", "ON"}},
      ParamSpec{
          "INDEPENDENT COMPONENTS", ParamKind::Enum, false, {"POSITION", "CONSTITUTIVE MOTION"}},
      ParamSpec{"UNSYMM", ParamKind::Flag},
  };
  for (ParamSpec& p : regularize_param_specs()) params.push_back(std::move(p));
  std::vector<KeywordSpec> specs;
  specs.push_back(behavior_suboption_spec("CONNECTOR ELASTICITY", std::move(params), [] {
    return std::unique_ptr<KeywordHandler>(new ElasticityHandler());
  }));
  return specs;
}

}  // namespace clinch
