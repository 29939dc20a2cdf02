// *AMPLITUDE (keywords.md §8): a model-wide named time function, in model or history data.
// The data are read as (time, value) pairs, as equally spaced values, or as the constants of a
// formula (amplitude_formula.cpp), checked (E0803) and stored after SCALEX/SCALEY/SHIFTX/SHIFTY.
// Whether anything uses it (W0501) and undefined references (E0507) are decided in
// resolve_history.
#include <fmt/format.h>

#include "parser/keywords/amplitude_formula.hpp"
#include "parser/keywords/history_keywords.hpp"

namespace clinch {
namespace {

// Why a definition clinch refuses has no meaning here (keywords.md §8).
const char* refusal_reason(std::string_view definition) {
  if (definition == "SOLUTION DEPENDENT") {
    return "it is driven by the creep strain rate of a superplastic forming analysis";
  }
  if (definition == "BUBBLE") return "it is a loading of underwater shock analysis";
  if (definition == "USER") return "user subroutines UAMP and VUAMP cannot be called";
  return "it needs a co-simulation with a logical modeling program";  // ACTUATOR
}

class AmplitudeHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    const ParamSet& params = ctx.params();
    amplitude_.loc = ctx.keyword().loc;
    amplitude_.step = ctx.position().in_step ? ctx.position().step : -1;
    auto name = ctx.name_param("NAME");
    if (!name) {
      skip_ = true;
      return;
    }
    amplitude_.name = *name;

    const std::string_view definition = params.enum_value("DEFINITION");
    if (definition == "SMOOTH STEP") {
      amplitude_.definition = AmplitudeDefinition::SmoothStep;
    } else if (definition == "EQUALLY SPACED") {
      amplitude_.definition = AmplitudeDefinition::EquallySpaced;
    } else if (definition == "PERIODIC") {
      amplitude_.definition = AmplitudeDefinition::Periodic;
    } else if (definition == "MODULATED") {
      amplitude_.definition = AmplitudeDefinition::Modulated;
    } else if (definition == "DECAY") {
      amplitude_.definition = AmplitudeDefinition::Decay;
    } else if (!definition.empty() && definition != "TABULAR") {
      ctx.report(DiagCode::unsupported_option, params.loc("DEFINITION", true),
                 fmt::format("DEFINITION={} is not supported by clinch: {} (TABULAR, SMOOTH "
                             "STEP, EQUALLY SPACED, PERIODIC, MODULATED and DECAY are)",
                             definition, refusal_reason(definition)));
      skip_ = true;
    }
    amplitude_.total_time = params.enum_value("TIME") == "TOTAL TIME";
    amplitude_.absolute = params.enum_value("VALUE") == "ABSOLUTE";
    const bool equally_spaced = amplitude_.definition == AmplitudeDefinition::EquallySpaced;

    if (params.has("FIXED INTERVAL")) {
      if (auto dt = ctx.real_param("FIXED INTERVAL")) {
        if (*dt > 0) {
          amplitude_.fixed_interval = *dt;
        } else {
          ctx.report(DiagCode::value_out_of_range, *params.value("FIXED INTERVAL"),
                     fmt::format("FIXED INTERVAL must be positive, got {}",
                                 params.value("FIXED INTERVAL")->text));
          skip_ = true;
        }
      } else {
        skip_ = true;
      }
      if (!equally_spaced) {
        ctx.report(DiagCode::parameter_ignored, params.loc("FIXED INTERVAL"),
                   "FIXED INTERVAL has no effect unless DEFINITION=EQUALLY SPACED");
      }
    } else if (equally_spaced) {
      ctx.report(DiagCode::missing_parameter, ctx.keyword().loc,
                 "*AMPLITUDE with DEFINITION=EQUALLY SPACED requires parameter 'FIXED "
                 "INTERVAL'");
      skip_ = true;
    }
    if (params.has("BEGIN")) {
      if (auto begin = ctx.real_param("BEGIN")) amplitude_.begin = *begin;
      if (!equally_spaced) {
        ctx.report(DiagCode::parameter_ignored, params.loc("BEGIN"),
                   "BEGIN has no effect unless DEFINITION=EQUALLY SPACED");
      }
    }
    if (params.has("SMOOTH")) {
      // It smooths time derivatives only, which a static step never uses (§8).
      if (auto smooth = ctx.real_param("SMOOTH")) {
        if (*smooth < 0 || *smooth > 0.5) {
          ctx.report(
              DiagCode::value_out_of_range, *params.value("SMOOTH"),
              fmt::format("SMOOTH must lie in [0, 0.5], got {}", params.value("SMOOTH")->text));
        } else {
          ctx.report(DiagCode::parameter_ignored, params.loc("SMOOTH"),
                     "SMOOTH has no effect in a static analysis");
        }
      }
    }
    for (auto [param, target] :
         {std::pair{"SCALEX", &amplitude_.scale_x}, std::pair{"SCALEY", &amplitude_.scale_y},
          std::pair{"SHIFTX", &amplitude_.shift_x}, std::pair{"SHIFTY", &amplitude_.shift_y}}) {
      if (!params.has(param)) continue;
      if (auto value = ctx.real_param(param)) {
        *target = *value;
      } else {
        skip_ = true;
      }
    }
    // A formula's time constants are scaled by SCALEX (amplitude_formula.cpp): a reversed or
    // collapsed time axis has no formula.
    if (is_formula(amplitude_.definition) && params.has("SCALEX") && !skip_ &&
        !(amplitude_.scale_x > 0)) {
      ctx.report(DiagCode::value_out_of_range, *params.value("SCALEX"),
                 fmt::format("SCALEX must be positive for DEFINITION={}, got {}", definition,
                             params.value("SCALEX")->text));
      skip_ = true;
    }
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (skip_ || line.blank) return;
    const bool formula = is_formula(amplitude_.definition);
    const bool paired = amplitude_.definition == AmplitudeDefinition::Tabular ||
                        amplitude_.definition == AmplitudeDefinition::SmoothStep;
    // Abaqus reads 4 pairs (8 values) per line (§8).
    if (fields.size() > 8) {
      ctx.report(DiagCode::too_many_entries, fields[8],
                 fmt::format("{} entries on one line; Abaqus accepts at most 8", fields.size()));
    }
    for (const Field& field : fields) {
      const bool is_time = paired && numbers_.size() % 2 == 0;
      const char* what = formula ? "amplitude constant" : is_time ? "time" : "amplitude value";
      if (field.empty()) {
        ctx.missing(field.loc, what);
        failed_ = true;
        numbers_.push_back({0, field.loc, lines_});  // keep the pairing of later fields
        continue;
      }
      auto value = ctx.real(field, fmt::format("an {}", what));
      if (!value) failed_ = true;
      numbers_.push_back({value.value_or(0), field.loc, lines_});
    }
    ++lines_;
  }

  void end(BlockContext& ctx) override {
    if (skip_) {
      // Refused with its name known: references to it stay silent (input-syntax.md §10).
      if (!amplitude_.name.empty()) {
        ctx.model().history.amplitude_by_key.emplace(amplitude_.name.key, -1);
      }
      return;
    }
    Amplitude& a = amplitude_;
    const std::string& name = a.name.display;
    if (numbers_.empty()) {
      ctx.report(DiagCode::invalid_amplitude, a.loc,
                 fmt::format("amplitude '{}' has no data points", name));
      a.valid = false;
    } else if (is_formula(a.definition)) {
      if (!failed_ && !read_amplitude_formula(ctx, a, numbers_)) a.valid = false;
    } else if (a.definition == AmplitudeDefinition::EquallySpaced) {
      for (std::size_t i = 0; i < numbers_.size(); ++i) {
        a.times.push_back(a.begin + static_cast<double>(i) * a.fixed_interval);
        a.values.push_back(numbers_[i].value);
      }
    } else if (numbers_.size() % 2 != 0) {
      ctx.report(
          DiagCode::invalid_amplitude, a.loc,
          fmt::format("amplitude '{}' has an odd number of values ({})", name, numbers_.size()));
      a.valid = false;
    } else {
      const bool strict = a.definition == AmplitudeDefinition::SmoothStep;
      for (std::size_t i = 0; i + 1 < numbers_.size(); i += 2) {
        const double t = numbers_[i].value;
        if (!failed_ && !a.times.empty() && (strict ? t <= a.times.back() : t < a.times.back())) {
          ctx.report(DiagCode::invalid_amplitude, numbers_[i].loc,
                     fmt::format("amplitude times must {} ({} after {})",
                                 strict ? "increase" : "not decrease", t, a.times.back()))
              .notes.push_back({a.loc, fmt::format("in amplitude '{}'", name)});
          a.valid = false;
          break;
        }
        a.times.push_back(t);
        a.values.push_back(numbers_[i + 1].value);
      }
    }
    if (failed_) a.valid = false;
    // Scaling then shifting (§8; not confirmed: the order of the two).
    for (double& t : a.times) t = a.scale_x * t + a.shift_x;
    for (double& v : a.values) v = a.scale_y * v + a.shift_y;

    HistoryModel& history = ctx.model().history;
    const auto index = static_cast<std::int32_t>(history.amplitudes.size());
    auto [it, inserted] = history.amplitude_by_key.emplace(a.name.key, index);
    if (!inserted && it->second < 0) {
      it->second = index;  // an earlier block of that name was refused
    } else if (!inserted) {
      ctx.report(DiagCode::duplicate_name, ctx.params().loc("NAME", true),
                 fmt::format("amplitude '{}' is already defined", name))
          .notes.push_back({history.amplitudes[static_cast<std::size_t>(it->second)].loc,
                            "previous definition is here"});
      return;
    }
    history.amplitudes.push_back(std::move(a));
  }

 private:
  Amplitude amplitude_;
  std::vector<AmplitudeNumber> numbers_;
  int lines_ = 0;  // non-blank data lines read
  bool skip_ = false;
  bool failed_ = false;
};

}  // namespace

std::vector<KeywordSpec> amplitude_keyword_specs() {
  KeywordSpec amplitude;
  amplitude.name = "AMPLITUDE";
  amplitude.level = KeywordLevel::ModelOrHistory;
  amplitude.params = {
      {"NAME", ParamKind::Value, true},
      {"DEFINITION",
       ParamKind::Enum,
       false,
       {"TABULAR", "SMOOTH STEP", "EQUALLY SPACED", "PERIODIC", "MODULATED", "DECAY",
        "SOLUTION DEPENDENT", "BUBBLE", "USER", "ACTUATOR"}},
      {"TIME", ParamKind::Enum, false, {"STEP TIME", "TOTAL TIME"}},
      {"VALUE", ParamKind::Enum, false, {"RELATIVE", "ABSOLUTE"}},
      {"FIXED INTERVAL"},
      {"BEGIN"},
      {"SMOOTH"},
      {"SCALEX"},
      {"SCALEY"},
      {"SHIFTX"},
      {"SHIFTY"},
  };
  amplitude.make_handler = &make<AmplitudeHandler>;
  std::vector<KeywordSpec> specs;
  specs.push_back(std::move(amplitude));
  return specs;
}

}  // namespace clinch
