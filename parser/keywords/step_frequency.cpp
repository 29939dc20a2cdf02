// *FREQUENCY: a linear perturbation step that extracts natural frequencies and mode shapes about
// the base state (docs/dynamics.md "Natural frequencies"). Every EIGENSOLVER is read as a request
// for eigenpairs, which clinch computes one way (docs/decisions.md "Natural frequencies"). The
// data line is the Abaqus Keywords Reference's for that eigensolver: the number of eigenvalues,
// the frequency range of interest (cycles/time) and the shift point ((cycles/time)²) are read;
// the fields that tune Abaqus's own iteration are ignored with a warning.
#include <fmt/format.h>

#include <cstdint>

#include "parser/keywords/history_keywords.hpp"

namespace clinch {
namespace {

// Parameters that tune Abaqus's (or CalculiX's) solver, acoustics or frequency-dependent
// properties, none of which clinch has.
constexpr std::string_view kIgnoredParams[] = {"ACOUSTIC COUPLING", "DAMPING PROJECTION",
                                               "SIM",               "BIAS",
                                               "NUMBER INTERVAL",   "PROPERTY EVALUATION",
                                               "STORAGE",           "SOLVER"};

// What each field of the data line is, per eigensolver (the Abaqus Keywords Reference, *FREQUENCY).
enum class Meaning : std::uint8_t { Count, Minimum, Maximum, Shift, Tuning };

struct Layout {
  std::vector<Meaning> fields;
  std::vector<std::string_view> names;
};

Layout layout_of(std::string_view eigensolver) {
  using F = Meaning;
  if (eigensolver == "SUBSPACE") {
    return {{F::Count, F::Maximum, F::Shift, F::Tuning, F::Tuning},
            {"the number of eigenvalues", "the maximum frequency", "the shift point",
             "the number of vectors used in the iteration", "the maximum number of iterations"}};
  }
  if (eigensolver == "AMS") {
    return {{F::Count, F::Minimum, F::Maximum},
            {"the number of eigenvalues", "the minimum frequency", "the maximum frequency"}};
  }
  return {{F::Count, F::Minimum, F::Maximum, F::Shift, F::Tuning, F::Tuning},
          {"the number of eigenvalues", "the minimum frequency", "the maximum frequency",
           "the shift point", "the block size", "the maximum number of block Lanczos steps"}};
}

class FrequencyHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    const ParamSet& params = ctx.params();
    report_unsupported_params(ctx, {"RESIDUAL MODES"});
    for (std::string_view name : kIgnoredParams) {
      if (!params.has(name)) continue;
      ctx.report(DiagCode::parameter_ignored, params.loc(name),
                 fmt::format("{} has no effect in clinch (docs/decisions.md, \"Natural "
                             "frequencies\")",
                             name));
    }
    procedure_.loc = ctx.keyword().loc;
    if (params.has("EIGENSOLVER")) procedure_.eigensolver = params.enum_value("EIGENSOLVER");
    if (params.enum_value("NORMALIZATION") == "MASS") {
      procedure_.normalization = FrequencyProcedure::Normalization::Mass;
    }
    duplicate_ = report_second_procedure(ctx, current_step(ctx));
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (line.blank) return;
    if (has_data_) {
      if (!extra_reported_) {
        extra_reported_ = true;
        ctx.report(DiagCode::parameter_ignored, line.loc,
                   fmt::format("data lines after the first of *FREQUENCY, EIGENSOLVER={} have "
                               "no effect in clinch",
                               procedure_.eigensolver));
      }
      return;
    }
    has_data_ = true;
    data_loc_ = line.loc;
    const Layout layout = layout_of(procedure_.eigensolver);
    if (fields.size() > layout.fields.size()) {
      ctx.report(DiagCode::parameter_ignored, fields[layout.fields.size()],
                 fmt::format("fields after {} of *FREQUENCY, EIGENSOLVER={} have no effect in "
                             "clinch",
                             layout.names.back(), procedure_.eigensolver));
    }
    for (std::size_t i = 0; i < fields.size() && i < layout.fields.size(); ++i) {
      if (fields[i].empty()) continue;
      read_field(ctx, fields[i], layout.fields[i], layout.names[i]);
    }
  }

  void end(BlockContext& ctx) override {
    FrequencyProcedure& p = procedure_;
    const bool subspace = p.eigensolver == "SUBSPACE";
    if (!p.eigenvalues && (subspace || !p.max_frequency) && valid_) {
      ctx.report(DiagCode::missing_data_line, has_data_ ? data_loc_ : ctx.keyword().loc,
                 subspace
                     ? std::string("*FREQUENCY, EIGENSOLVER=SUBSPACE needs the number of "
                                   "eigenvalues (field 1 of its data line)")
                     : fmt::format("*FREQUENCY, EIGENSOLVER={} needs the number of eigenvalues "
                                   "or the maximum frequency of interest (fields 1 and 3 of its "
                                   "data line)",
                                   p.eigensolver));
    }
    if (p.min_frequency && p.max_frequency && *p.max_frequency <= *p.min_frequency) {
      ctx.report(DiagCode::value_out_of_range, max_loc_,
                 fmt::format("the maximum frequency ({}) must exceed the minimum frequency ({})",
                             *p.max_frequency, *p.min_frequency));
      p.max_frequency.reset();
    }
    if (duplicate_) return;
    current_step(ctx).frequency = p;
  }

 private:
  void read_field(BlockContext& ctx, const Field& field, Meaning kind, std::string_view what) {
    if (kind == Meaning::Tuning) {
      ctx.report(DiagCode::parameter_ignored, field,
                 fmt::format("{} tunes Abaqus's eigensolver and has no effect in clinch", what));
      return;
    }
    if (kind == Meaning::Count) {
      const auto count = ctx.integer(field, what);
      if (!count) {
        valid_ = false;
      } else if (*count < 1 || *count > 100000) {
        ctx.report(DiagCode::value_out_of_range, field,
                   fmt::format("{} must be a positive integer, got {}", what, *count));
        valid_ = false;
      } else {
        procedure_.eigenvalues = static_cast<int>(*count);
      }
      return;
    }
    const auto value = ctx.real(field, what);
    if (!value) {
      valid_ = false;
      return;
    }
    if (kind == Meaning::Shift) {
      procedure_.shift = *value;
      return;
    }
    if (*value < 0) {
      ctx.report(DiagCode::value_out_of_range, field,
                 fmt::format("{} must not be negative, got {}", what, field.text));
      valid_ = false;
      return;
    }
    // A minimum of 0 is no minimum, as a blank field (docs/decisions.md "Natural frequencies").
    if (kind == Meaning::Minimum) {
      if (*value > 0) procedure_.min_frequency = *value;
    } else if (*value == 0) {
      ctx.report(DiagCode::value_out_of_range, field, "the maximum frequency must be positive");
      valid_ = false;
    } else {
      procedure_.max_frequency = *value;
      max_loc_ = field.loc;
    }
  }

  FrequencyProcedure procedure_;
  SourceLoc data_loc_, max_loc_;
  bool has_data_ = false;
  bool extra_reported_ = false;
  bool duplicate_ = false;
  bool valid_ = true;  // no field was in error (then a missing count is not reported again)
};

}  // namespace

std::vector<KeywordSpec> frequency_keyword_specs() {
  KeywordSpec spec;
  spec.name = "FREQUENCY";
  spec.level = KeywordLevel::History;
  spec.params = {
      {"EIGENSOLVER", ParamKind::Enum, false, {"LANCZOS", "SUBSPACE", "AMS"}},
      {"NORMALIZATION", ParamKind::Enum, false, {"DISPLACEMENT", "MASS"}},
      unsupported_param("RESIDUAL MODES"),
  };
  for (std::string_view name : kIgnoredParams) {
    spec.params.push_back(ParamSpec{name, ParamKind::OptionalValue});
  }
  spec.make_handler = &make<FrequencyHandler>;
  return {std::move(spec)};
}

}  // namespace clinch
