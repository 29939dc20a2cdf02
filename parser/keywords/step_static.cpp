// *STEP, *END STEP, *STATIC and *CONTROLS (keywords.md §14–§16). The reader does the structural
// bookkeeping (open/close, E0601–E0604, E0606); these handlers create and close the Step in
// model().history, resolve the *STATIC increments with their defaults and keep the effective
// controls, which carry over to later steps (§13).
#include <fmt/format.h>

#include <cmath>

#include "parser/keywords/history_keywords.hpp"

namespace clinch {
namespace {

// "2.0", "0.1", "1e-05": a real as a reader of the deck would write it.
std::string format_real(double value) {
  std::string text = fmt::format("{}", value);
  if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
  return text;
}

// ---- *STEP ------------------------------------------------------------------------------------

class StepHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    HistoryModel& history = ctx.model().history;
    const std::int32_t index = ctx.position().step < 0 ? 0 : ctx.position().step;
    if (index > 0) current_step_before(ctx, index);
    Step step;
    step.loc = ctx.keyword().loc;
    if (index > 0 && static_cast<std::int32_t>(history.steps.size()) >= index) {
      const Step& previous = history.steps[static_cast<std::size_t>(index - 1)];
      step.nlgeom = previous.nlgeom;
      step.controls = previous.controls;
    }
    read_parameters(ctx, step, index);
    if (static_cast<std::int32_t>(history.steps.size()) > index) {
      history.steps[static_cast<std::size_t>(index)] = std::move(step);
    } else {
      history.steps.push_back(std::move(step));
    }
    index_ = index;
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>&) override {
    // The first data line is the step description (free text, keywords.md §14).
    if (line.blank || described_) return;
    described_ = true;
    std::vector<Step>& steps = ctx.model().history.steps;
    if (index_ >= 0 && static_cast<std::size_t>(index_) < steps.size()) {
      steps[static_cast<std::size_t>(index_)].description = std::string(line.text);
    }
  }

 private:
  // Placeholders for earlier steps whose *STEP line had errors (their handler never ran).
  static void current_step_before(BlockContext& ctx, std::int32_t index) {
    std::vector<Step>& steps = ctx.model().history.steps;
    while (static_cast<std::int32_t>(steps.size()) < index) {
      Step step;
      const std::string name = fmt::format("Step-{}", steps.size() + 1);
      step.name = Name{name_key(name, false), name, ctx.keyword().loc};
      step.loc = ctx.keyword().loc;
      step.placeholder = true;
      step.closed = true;
      if (!steps.empty()) {
        step.nlgeom = steps.back().nlgeom;
        step.controls = steps.back().controls;
      }
      steps.push_back(std::move(step));
    }
  }

  void read_parameters(BlockContext& ctx, Step& step, std::int32_t index) {
    const ParamSet& params = ctx.params();
    HistoryModel& history = ctx.model().history;
    report_unsupported_params(ctx, {"PERTURBATION", "SOLVER", "MONOTONIC", "INCF"});

    // NAME (default Step-<n>); duplicates are E0511.
    if (auto name = ctx.name_param("NAME")) {
      step.name = *name;
    } else {
      const std::string generated = fmt::format("Step-{}", index + 1);
      step.name = Name{name_key(generated, false), generated, step.loc};
    }
    auto [it, inserted] = history.step_by_key.emplace(step.name.key, index);
    if (!inserted && it->second != index) {
      const SourceLoc at = params.has("NAME") ? params.loc("NAME", true) : step.loc;
      ctx.report(DiagCode::duplicate_name, at,
                 fmt::format("step '{}' is already defined", step.name.display))
          .notes.push_back({history.steps[static_cast<std::size_t>(it->second)].loc,
                            "previous definition is here"});
    }

    // NLGEOM: once on, it stays on (§13).
    if (params.has("NLGEOM")) {
      const bool on = params.flag("NLGEOM");
      if (!on && step.nlgeom) {
        ctx.report(DiagCode::nlgeom_stays_on, params.loc("NLGEOM", true),
                   "NLGEOM was on in an earlier step and stays on");
      }
      step.nlgeom = step.nlgeom || on;
    }

    if (params.has("INC")) {
      step.inc_loc = params.loc("INC", true);
      if (auto inc = ctx.integer_param("INC")) {
        if (*inc < 1 || *inc > 2147483647) {
          ctx.report(DiagCode::value_out_of_range, *params.value("INC"),
                     fmt::format("INC must be a positive integer, got {}", *inc));
        } else {
          step.max_increments = static_cast<int>(*inc);
        }
      }
    }
    if (params.enum_value("AMPLITUDE") == "STEP") step.amplitude = StepAmplitude::Step;
    step.amplitude_given = params.has("AMPLITUDE");
    if (params.has("UNSYMM")) {
      step.unsymmetric = params.enum_value("UNSYMM") == "YES" ? Unsymmetric::Yes : Unsymmetric::No;
      step.unsymmetric_loc = params.loc("UNSYMM", true);
    }
    const std::string_view extrapolation = params.enum_value("EXTRAPOLATION");
    if (extrapolation == "PARABOLIC") {
      ctx.report(DiagCode::unsupported_option, params.loc("EXTRAPOLATION", true),
                 "EXTRAPOLATION=PARABOLIC is not supported by clinch (use LINEAR or NO)");
    }
    step.extrapolation = extrapolation != "NO";
    if (params.has("CONVERT SDI")) {
      ctx.report(DiagCode::parameter_ignored, params.loc("CONVERT SDI"),
                 "CONVERT SDI has no effect in clinch");
    }
  }

  std::int32_t index_ = -1;
  bool described_ = false;
};

// ---- *END STEP --------------------------------------------------------------------------------

class EndStepHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    if (ctx.position().step < 0) return;  // E0604 already reported by the reader
    Step& step = current_step(ctx);
    if (step.closed) return;  // a second *END STEP: E0604 from the reader
    step.closed = true;
    step.end_loc = ctx.keyword().loc;
    // input-syntax.md §8: exactly one procedure per step (the second one is reported where it
    // stands, by *STATIC, *DYNAMIC or *FREQUENCY).
    if (!step.has_procedure()) {
      ctx.report(DiagCode::step_procedure, ctx.keyword().loc,
                 fmt::format("step '{}' has no procedure (expected *STATIC, *DYNAMIC or "
                             "*FREQUENCY)",
                             step.name.display))
          .notes.push_back({step.loc, "step defined here"});
    }
  }
};

// ---- *STATIC and *DYNAMIC -----------------------------------------------------------------------

// The time data both procedures share: DIRECT, the data line (initial increment, period, minimum,
// maximum) and its rules (§15). *DYNAMIC adds its integration operator (DynamicHandler).
class StaticHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    const ParamSet& params = ctx.params();
    report_unsupported(ctx);
    procedure_.loc = ctx.keyword().loc;
    if (params.has("RIKS")) procedure_.riks.emplace();
    if (params.has("DIRECT")) {
      procedure_.direct = true;
      // The only value is NO STOP; no abbreviation (DIRECT=NO must not read as NO STOP).
      if (const Field* value = params.value("DIRECT"); value && !value->empty()) {
        if (fold_name(value->text) == "NOSTOP") {
          procedure_.no_stop = true;
        } else {
          ctx.report(DiagCode::invalid_value, *value,
                     fmt::format("invalid value '{}' for DIRECT (expected NO STOP, or DIRECT "
                                 "without a value)",
                                 value->text));
        }
      }
    }
    duplicate_ = report_second_procedure(ctx, current_step(ctx));
    read_operator(ctx);
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (line.blank) return;
    if (has_data_) {
      if (!extra_reported_) {
        extra_reported_ = true;
        ctx.report(DiagCode::unexpected_data_line, line.loc,
                   procedure_.riks
                       ? std::string("*STATIC, RIKS takes one data line (arc lengths, LPF and "
                                     "the monitored node)")
                       : fmt::format("{} takes one data line (initial increment, step period, "
                                     "minimum and maximum increment)",
                                     ctx.keyword_display()));
      }
      return;
    }
    has_data_ = true;
    procedure_.data_loc = line.loc;
    if (procedure_.riks) return riks_line(ctx, line, fields);
    ctx.check_field_count(line, fields, 4,
                          "initial increment, step period, minimum increment, "
                          "maximum increment");
    static constexpr const char* kWhat[] = {"the initial increment", "the step period",
                                            "the minimum increment", "the maximum increment"};
    for (std::size_t i = 0; i < 4 && i < fields.size(); ++i) {
      auto value = ctx.real(fields[i], kWhat[i]);
      if (!value) continue;
      // A step of no time has nothing to increment: a zero period is an error at its field, not
      // the default (§15: T > 0).
      if (*value < 0 || (i == 1 && *value == 0)) {
        ctx.report(DiagCode::value_out_of_range, fields[i],
                   fmt::format("{} must be positive, got {}", kWhat[i], fields[i].text));
        continue;
      }
      // Any other zero takes the default, like a blank field (§15).
      if (*value == 0) continue;
      values_[i] = *value;
      procedure_.field_loc[i] = fields[i].loc;
    }
  }

  void end(BlockContext& ctx) override {
    if (procedure_.riks) return end_riks(ctx);
    // Defaults and rules of keywords.md §15.
    StaticProcedure& p = procedure_;
    p.period = values_[1].value_or(1.0);
    p.initial_increment = values_[0].value_or(p.period);
    if (p.initial_increment > p.period) {
      ctx.report(DiagCode::initial_increment_reduced,
                 p.field_loc[0].valid() ? p.field_loc[0] : p.data_loc,
                 fmt::format("initial increment {} reduced to the step period {}",
                             format_real(p.initial_increment), format_real(p.period)));
      p.initial_increment = p.period;
    }
    p.min_increment = values_[2].value_or(std::min(p.initial_increment, 1e-5 * p.period));
    p.max_increment = values_[3].value_or(p.period);
    Step& step = current_step(ctx);
    if (!p.direct) {
      if (p.min_increment > p.initial_increment) {
        ctx.report(DiagCode::invalid_increments, p.field_loc[2],
                   fmt::format("minimum increment {} is larger than the initial increment {}",
                               format_real(p.min_increment), format_real(p.initial_increment)));
      }
      if (p.max_increment < p.initial_increment) {
        ctx.report(DiagCode::invalid_increments, p.field_loc[3],
                   fmt::format("maximum increment {} is smaller than the initial increment {}",
                               format_real(p.max_increment), format_real(p.initial_increment)));
      }
    } else {
      // ⌈T/Δt₀⌉ with a shortened last increment; a ratio within 1e-9 of an integer is that
      // integer (§15).
      const double ratio = p.period / p.initial_increment;
      double needed = std::round(ratio);
      if (std::fabs(ratio - needed) > 1e-9 * ratio) needed = std::ceil(ratio);
      if (needed > static_cast<double>(step.max_increments)) {
        ctx.report(DiagCode::too_many_direct_increments, p.loc,
                   fmt::format("DIRECT incrementation needs {:.0f} increments but INC={}", needed,
                               step.max_increments))
            .notes.push_back(
                {step.inc_loc.valid() ? step.inc_loc : step.loc, "INC of the step is set here"});
      }
    }
    if (!duplicate_) {
      step.procedure = p;
      keep_operator(step);
    }
  }

 protected:
  // The procedure's parameters clinch refuses (E0210), reported here so that the list lives as
  // long as the call.
  virtual void report_unsupported(BlockContext& ctx) const {
    report_unsupported_params(ctx, {"LONG TERM", "ADAPTIVE"});
  }
  // What a procedure adds to the time data, read from the keyword line and kept with the step.
  virtual void read_operator(BlockContext& ctx) {
    procedure_.stabilize = read_stabilization(ctx, procedure_.riks.has_value());
  }
  virtual void keep_operator(Step&) const {}

 private:
  // The manual's data line for the Riks method: Δl_in, l_period, Δl_min, Δl_max, λ_end, node,
  // DOF, displacement (docs/riks.md).
  void riks_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    RiksSettings& r = *procedure_.riks;
    ctx.check_field_count(line, fields, 8,
                          "initial arc length, total arc length, minimum and maximum arc "
                          "length, maximum LPF, node, DOF, displacement");
    static constexpr const char* kWhat[] = {"the initial arc length", "the total arc length",
                                            "the minimum arc length", "the maximum arc length",
                                            "the maximum LPF"};
    for (std::size_t i = 0; i < fields.size() && i < 8; ++i) {
      if (fields[i].empty()) continue;
      r.field_loc[i] = fields[i].loc;
      if (i < 5) {
        auto value = ctx.real(fields[i], kWhat[i]);
        if (!value) continue;
        if (i < 4 && *value < 0) {
          ctx.report(DiagCode::value_out_of_range, fields[i],
                     fmt::format("{} must be positive, got {}", kWhat[i], fields[i].text));
          continue;
        }
        if (*value == 0) continue;  // the default, as a blank field
        riks_values_[i] = *value;
      } else if (i == 5) {
        r.node = ctx.target(fields[i], "node");
      } else if (i == 6) {
        auto dof = ctx.integer(fields[i], "the monitored DOF");
        if (dof && (*dof < 1 || *dof > 6)) {
          ctx.report(DiagCode::value_out_of_range, fields[i],
                     fmt::format("the monitored DOF must be 1 to 6, got {}", *dof));
        } else if (dof) {
          r.dof = static_cast<int>(*dof);
        }
      } else if (auto value = ctx.real(fields[i], "the finishing displacement")) {
        r.displacement = *value;
      }
    }
  }

  void end_riks(BlockContext& ctx) {
    RiksSettings& r = *procedure_.riks;
    r.arc_period = riks_values_[1].value_or(1.0);
    r.initial_arc = riks_values_[0].value_or(r.arc_period);
    r.min_arc = riks_values_[2].value_or(std::min(r.initial_arc, 1e-5 * r.arc_period));
    r.max_arc = riks_values_[3];
    r.max_lpf = riks_values_[4];
    if (!procedure_.direct && r.min_arc > r.initial_arc) {
      ctx.report(DiagCode::invalid_increments, r.field_loc[2],
                 fmt::format("minimum arc length {} is larger than the initial arc length {}",
                             format_real(r.min_arc), format_real(r.initial_arc)));
    }
    if (!procedure_.direct && r.max_arc && *r.max_arc < r.initial_arc) {
      ctx.report(DiagCode::invalid_increments, r.field_loc[3],
                 fmt::format("maximum arc length {} is smaller than the initial arc length {}",
                             format_real(*r.max_arc), format_real(r.initial_arc)));
    }
    // The node, its DOF and the displacement go together (the manual's fields 6–8).
    const bool node = r.field_loc[5].valid(), dof = r.field_loc[6].valid();
    if (node != dof) {
      ctx.report(DiagCode::missing_field, node ? r.field_loc[5] : r.field_loc[6],
                 "the monitored node (field 6) needs its DOF (field 7), and the DOF its node");
      r.node.reset();
    }
    if (!node || !dof) r.node.reset();
    Step& step = current_step(ctx);
    if (!duplicate_) step.procedure = procedure_;
  }

  StaticProcedure procedure_;
  std::optional<double> riks_values_[5];
  std::optional<double> values_[4];
  bool has_data_ = false;
  bool extra_reported_ = false;
  bool duplicate_ = false;
};

// *DYNAMIC (implicit): the Hilber–Hughes–Taylor operator, or backward Euler for
// APPLICATION=QUASI-STATIC, with the defaults of each APPLICATION (docs/decisions.md "Implicit
// dynamics"): ALPHA −0.05 (TRANSIENT FIDELITY) or −0.41421 (MODERATE DISSIPATION), and from it
// BETA = (1 − ALPHA)²/4 and GAMMA = 1/2 − ALPHA unless given.
class DynamicHandler final : public StaticHandler {
 protected:
  void report_unsupported(BlockContext& ctx) const override {
    report_unsupported_params(ctx, {"EXPLICIT",          "SUBSPACE",     "ADIABATIC",
            "NOHAF",             "TIME INTEGRATOR", "STABILIZE",
            "ALLSDTOL",          "CONTINUE",     "FACTOR",
            "ELEMENT BY ELEMENT", "FIXED TIME INCREMENTATION", "IMPROVED DT METHOD",
            "SCALE FACTOR",      "DIRECT USER CONTROL"});
  }

  void read_operator(BlockContext& ctx) override {
    using Application = DynamicProcedure::Application;
    const ParamSet& params = ctx.params();
    DynamicProcedure& d = dynamic_;
    d.loc = ctx.keyword().loc;
    const std::string_view application = params.enum_value("APPLICATION");
    d.application = application == "MODERATE DISSIPATION" ? Application::ModerateDissipation
                    : application == "QUASI-STATIC"       ? Application::QuasiStatic
                                                          : Application::TransientFidelity;
    d.backward_euler = d.application == Application::QuasiStatic;
    d.explicit_integration = params.has("EXPLICIT");
    d.initial_acceleration = params.has("INITIAL") ? params.enum_value("INITIAL") == "YES"
                                                   : !d.backward_euler;
    d.alpha = d.application == Application::ModerateDissipation ? -0.41421 : -0.05;
    if (d.backward_euler) {
      d.alpha = 0.0;
      for (std::string_view name : {"ALPHA", "BETA", "GAMMA"}) {
        if (!params.has(name)) continue;
        ctx.report(DiagCode::parameter_ignored, params.loc(name),
                   fmt::format("{} has no effect with APPLICATION=QUASI-STATIC (backward Euler)",
                               name));
      }
    } else {
      if (auto alpha = bounded(ctx, "ALPHA", -0.5, 0.0, "between -0.5 and 0")) d.alpha = *alpha;
      d.beta = 0.25 * (1.0 - d.alpha) * (1.0 - d.alpha);
      d.gamma = 0.5 - d.alpha;
      if (auto beta = bounded(ctx, "BETA", 0.0, 1.0, "positive and at most 1")) d.beta = *beta;
      if (auto gamma = bounded(ctx, "GAMMA", 0.0, 1.5, "positive and at most 1.5")) {
        d.gamma = *gamma;
      }
    }
    if (params.has("HAFTOL")) {
      d.haftol_loc = params.loc("HAFTOL", true);
      if (auto haftol = ctx.real_param("HAFTOL")) {
        if (*haftol > 0) {
          d.haftol = *haftol;
        } else {
          ctx.report(DiagCode::value_out_of_range, *params.value("HAFTOL"),
                     fmt::format("HAFTOL must be positive, got {}", *haftol));
        }
      }
      if (params.has("DIRECT")) {
        ctx.report(DiagCode::parameter_ignored, params.loc("HAFTOL"),
                   "HAFTOL has no effect with DIRECT (fixed increments are not checked by the "
                   "half-increment residual)");
      }
    }
  }

  void keep_operator(Step& step) const override {
    step.dynamic = dynamic_;
    // Loads of a dynamic step are applied at once unless the step says otherwise, as in
    // CalculiX; QUASI-STATIC ramps them like *STATIC (docs/decisions.md "Implicit dynamics").
    if (!step.amplitude_given && !dynamic_.backward_euler) step.amplitude = StepAmplitude::Step;
  }

 private:
  // A real parameter in [low, high] (low excluded when it is 0 and the value must be positive).
  std::optional<double> bounded(BlockContext& ctx, std::string_view name, double low, double high,
                                std::string_view expected) {
    if (!ctx.params().has(name)) return std::nullopt;
    auto value = ctx.real_param(name);
    if (!value) return std::nullopt;
    const bool positive_only = low == 0.0 && name != "ALPHA";
    if (*value > high || *value < low || (positive_only && *value == 0.0)) {
      ctx.report(DiagCode::value_out_of_range, *ctx.params().value(name),
                 fmt::format("{} must be {}, got {}", name, expected, *value));
      return std::nullopt;
    }
    return value;
  }

  DynamicProcedure dynamic_;
};

// ---- *CONTROLS --------------------------------------------------------------------------------

class ControlsHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    const ParamSet& params = ctx.params();
    Controls& controls = current_step(ctx).controls;
    // RESET happens before the PARAMETERS of the same line (§16).
    if (params.has("RESET")) controls = Controls{};
    if (params.has("ANALYSIS")) {
      controls.time.i0 = 8;
      controls.time.ir = 10;
    }
    parameters_ = params.enum_value("PARAMETERS");
    if (parameters_ == "CONSTRAINTS" || parameters_ == "DIRECT CYCLIC") {
      ctx.report(DiagCode::unsupported_option, params.loc("PARAMETERS", true),
                 fmt::format("PARAMETERS={} is not supported by clinch", parameters_));
      parameters_ = "";
      skip_ = true;
    }
    const std::string_view field = params.enum_value("FIELD");
    if (params.has("FIELD") && parameters_ != "FIELD") {
      ctx.report(DiagCode::parameter_ignored, params.loc("FIELD"),
                 "FIELD has no effect without PARAMETERS=FIELD");
    }
    use_translation_ = field != "ROTATION";
    use_rotation_ = field != "DISPLACEMENT";
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (skip_) return;
    if (parameters_.empty()) {
      if (!line.blank && !extra_reported_) {
        extra_reported_ = true;
        ctx.report(DiagCode::unexpected_data_line, line.loc,
                   "*CONTROLS takes data lines only with PARAMETERS=");
      }
      return;
    }
    ++line_;
    Controls& controls = current_step(ctx).controls;
    if (parameters_ == "FIELD") {
      field_line(ctx, fields, controls);
    } else if (parameters_ == "TIME INCREMENTATION") {
      time_line(ctx, fields, controls.time);
    } else {
      line_search_line(ctx, fields, controls.line_search);
    }
  }

 private:
  // A value clinch reads loosely and ignores: a number or blank, one W0202 per block (§16).
  void ignored(BlockContext& ctx, const Field& field, std::string_view what) {
    if (field.empty()) return;
    if (!ctx.real(field, what)) return;
    if (ignored_reported_) return;
    ignored_reported_ = true;
    ctx.report(
        DiagCode::parameter_ignored, field,
        fmt::format("{} of *CONTROLS, PARAMETERS={} has no effect in clinch", what, parameters_));
  }

  std::optional<double> positive(BlockContext& ctx, const Field& field, std::string_view what) {
    auto value = ctx.real(field, what);
    if (value && !(*value > 0)) {
      ctx.report(DiagCode::value_out_of_range, field,
                 fmt::format("{} must be positive, got {}", what, field.text));
      return std::nullopt;
    }
    return value;
  }

  // Factor in (0, 1), or > 1 for the growth factor D_D.
  std::optional<double> factor(BlockContext& ctx, const Field& field, std::string_view what,
                               bool growth) {
    auto value = ctx.real(field, what);
    if (!value) return std::nullopt;
    const bool ok = growth ? *value > 1 : (*value > 0 && *value < 1);
    if (!ok) {
      ctx.report(DiagCode::value_out_of_range, field,
                 fmt::format("{} must {}, got {}", what,
                             growth ? "be greater than 1" : "lie between 0 and 1", field.text));
      return std::nullopt;
    }
    return value;
  }

  std::optional<int> count(BlockContext& ctx, const Field& field, std::string_view what,
                           std::int64_t minimum) {
    auto value = ctx.integer(field, what);
    if (!value) return std::nullopt;
    if (*value < minimum || *value > 1000000) {
      ctx.report(
          DiagCode::value_out_of_range, field,
          fmt::format("{} must be an integer of at least {}, got {}", what, minimum, *value));
      return std::nullopt;
    }
    return static_cast<int>(*value);
  }

  void field_line(BlockContext& ctx, std::vector<Field>& fields, Controls& controls) {
    if (line_ > 1) {
      for (const Field& f : fields) ignored(ctx, f, "a second data line");
      return;
    }
    static constexpr const char* kNames[] = {"R_n", "C_n",     "q0",        "q_u",
                                             "R_p", "epsilon", "C_epsilon", "epsilon_l"};
    for (std::size_t i = 0; i < fields.size(); ++i) {
      if (i >= 8) {
        ignored(ctx, fields[i], fmt::format("field {}", i + 1));
        continue;
      }
      auto value = positive(ctx, fields[i], kNames[i]);
      if (!value) continue;
      for (FieldControls* target : {use_translation_ ? &controls.translation : nullptr,
                                    use_rotation_ ? &controls.rotation : nullptr}) {
        if (!target) continue;
        switch (i) {
          case 0:
            target->residual = *value;
            break;
          case 1:
            target->correction = *value;
            break;
          case 2:
            target->initial_flux = *value;
            break;
          case 3:
            target->user_flux = *value;
            break;
          case 4:
            target->alternate_residual = *value;
            break;
          case 5:
            target->zero_flux = *value;
            break;
          case 6:
            target->zero_flux_correction = *value;
            break;
          default:
            target->linear_residual = *value;
            break;
        }
      }
    }
  }

  void time_line(BlockContext& ctx, std::vector<Field>& fields, TimeIncrementationControls& t) {
    if (line_ == 1) {
      static constexpr const char* kNames[] = {"I_0", "I_R", "I_P", "I_C",
                                               "I_L", "I_G", "I_S", "I_A"};
      int* targets[] = {&t.i0, &t.ir, &t.ip, &t.ic, &t.il, &t.ig, nullptr, &t.ia};
      for (std::size_t i = 0; i < fields.size(); ++i) {
        if (i >= 8 || !targets[i]) {
          ignored(ctx, fields[i], i < 8 ? kNames[i] : "I_J, I_T and later fields");
          continue;
        }
        if (auto v = count(ctx, fields[i], kNames[i], 1)) *targets[i] = *v;
      }
    } else if (line_ == 2) {
      static constexpr const char* kNames[] = {"D_f", "D_C", "D_B", "D_A", "D_S", "D_H", "D_D"};
      double* targets[] = {&t.df, &t.dc, &t.db, nullptr, nullptr, nullptr, &t.dd};
      for (std::size_t i = 0; i < fields.size(); ++i) {
        if (i >= 7 || !targets[i]) {
          ignored(ctx, fields[i], i < 7 ? kNames[i] : "W_G and later fields");
          continue;
        }
        if (auto v = factor(ctx, fields[i], kNames[i], i == 6)) *targets[i] = *v;
      }
    } else {
      for (const Field& f : fields) ignored(ctx, f, "the third data line");
    }
  }

  void line_search_line(BlockContext& ctx, std::vector<Field>& fields, LineSearchControls& ls) {
    if (line_ > 1) {
      for (const Field& f : fields) ignored(ctx, f, "a second data line");
      return;
    }
    ls.given = true;
    for (std::size_t i = 0; i < fields.size(); ++i) {
      switch (i) {
        case 0:
          if (auto v = count(ctx, fields[i], "N_ls", 0)) ls.max_iterations = *v;
          break;
        case 1:
          if (auto v = positive(ctx, fields[i], "s_max")) ls.s_max = *v;
          break;
        case 2:
          if (auto v = positive(ctx, fields[i], "s_min")) ls.s_min = *v;
          break;
        case 3:
          if (auto v = factor(ctx, fields[i], "f_s", false)) ls.f_s = *v;
          break;
        case 4:
          if (auto v = factor(ctx, fields[i], "eta_ls", false)) ls.eta = *v;
          break;
        default:
          ignored(ctx, fields[i], fmt::format("field {}", i + 1));
      }
    }
  }

  std::string parameters_;
  bool skip_ = false;
  bool use_translation_ = true, use_rotation_ = true;
  bool extra_reported_ = false;
  bool ignored_reported_ = false;
  int line_ = 0;
};

}  // namespace

std::vector<KeywordSpec> step_keyword_specs() {
  std::vector<KeywordSpec> specs;

  KeywordSpec step;
  step.name = "STEP";
  step.level = KeywordLevel::Block;
  step.data = DataMode::Raw;
  step.params = {
      {"NAME"},
      {"NLGEOM", ParamKind::FlagOrYesNo},
      {"INC"},
      {"AMPLITUDE", ParamKind::Enum, false, {"RAMP", "STEP"}},
      {"UNSYMM", ParamKind::Enum, false, {"YES", "NO"}},
      {"EXTRAPOLATION", ParamKind::Enum, false, {"LINEAR", "NO", "PARABOLIC"}},
      {"CONVERT SDI", ParamKind::Enum, false, {"YES", "NO"}},
      unsupported_param("PERTURBATION"),
      unsupported_param("SOLVER"),
      unsupported_param("MONOTONIC"),
      unsupported_param("INCF"),
  };
  step.make_handler = &make<StepHandler>;
  specs.push_back(std::move(step));

  KeywordSpec end_step;
  end_step.name = "END STEP";
  end_step.level = KeywordLevel::Block;
  end_step.data = DataMode::None;
  end_step.make_handler = &make<EndStepHandler>;
  specs.push_back(std::move(end_step));

  KeywordSpec stat;
  stat.name = "STATIC";
  stat.level = KeywordLevel::History;
  stat.params = {
      {"DIRECT", ParamKind::OptionalValue},
      {"STABILIZE", ParamKind::OptionalValue},
      {"ALLSDTOL", ParamKind::Value},
      {"CONTINUE", ParamKind::Enum, false, {"YES", "NO"}},
      {"FACTOR", ParamKind::Value},
      {"RIKS", ParamKind::Flag},
      unsupported_param("LONG TERM"),
      unsupported_param("ADAPTIVE"),
  };
  stat.make_handler = &make<StaticHandler>;
  specs.push_back(std::move(stat));

  KeywordSpec dynamic;
  dynamic.name = "DYNAMIC";
  dynamic.level = KeywordLevel::History;
  dynamic.params = {
      {"APPLICATION",
       ParamKind::Enum,
       false,
       {"TRANSIENT FIDELITY", "MODERATE DISSIPATION", "QUASI-STATIC"}},
      {"ALPHA", ParamKind::Value},
      {"BETA", ParamKind::Value},
      {"GAMMA", ParamKind::Value},
      {"INITIAL", ParamKind::Enum, false, {"YES", "NO"}},
      {"HAFTOL", ParamKind::Value},
      {"DIRECT", ParamKind::OptionalValue},
  };
  for (std::string_view name :
       {"EXPLICIT", "SUBSPACE", "ADIABATIC", "NOHAF", "TIME INTEGRATOR", "STABILIZE", "ALLSDTOL",
        "CONTINUE", "FACTOR", "ELEMENT BY ELEMENT", "FIXED TIME INCREMENTATION",
        "IMPROVED DT METHOD", "SCALE FACTOR", "DIRECT USER CONTROL"}) {
    dynamic.params.push_back(unsupported_param(name));
  }
  dynamic.make_handler = &make<DynamicHandler>;
  specs.push_back(std::move(dynamic));

  KeywordSpec controls;
  controls.name = "CONTROLS";
  controls.level = KeywordLevel::History;
  controls.params = {
      {"PARAMETERS",
       ParamKind::Enum,
       false,
       {"FIELD", "TIME INCREMENTATION", "LINE SEARCH", "CONSTRAINTS", "DIRECT CYCLIC"}},
      {"FIELD", ParamKind::Enum, false, {"GLOBAL", "DISPLACEMENT", "ROTATION"}},
      {"RESET", ParamKind::Flag},
      {"ANALYSIS", ParamKind::Enum, false, {"DISCONTINUOUS"}},
  };
  controls.make_handler = &make<ControlsHandler>;
  specs.push_back(std::move(controls));
  return specs;
}

}  // namespace clinch
