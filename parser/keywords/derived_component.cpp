// *CONNECTOR DERIVED COMPONENT (derived-components-and-potentials.md §1): one term of a named
// scalar function of the intrinsic components. The handler reads the parameters and the two
// positional data lines (component numbers, coefficients) into a DerivedComponentTerm of the open
// behaviour block; names are resolved and types checked once the model is complete
// (resolve_potentials.cpp).
#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "parser/block_context.hpp"
#include "parser/expression.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keywords/behavior_option_common.hpp"
#include "parser/keywords/potential_friction_specs.hpp"

namespace clinch {
namespace {

constexpr std::size_t kMaxComponents = 6;  // n ≤ 6: each list fits on one line (§1.2)

// A NAME that parses as an integer could not be told from a component number on a potential
// data line (§1.1, dc-numeric-name).
bool looks_numeric(const Field& field) {
  if (field.parameter) return field.parameter->is_number();
  std::int64_t value = 0;
  return parse_integer_text(field.text, value);
}

class DerivedComponentHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    behavior_ = current_behavior(ctx);
    const ParamSet& params = ctx.params();
    term_.loc = ctx.keyword().loc;

    if (const Field* name = params.value("NAME")) {
      if (looks_numeric(*name)) {
        ctx.report(DiagCode::dc_numeric_name, *name,
                   fmt::format("derived component name '{}' is a number; a potential data line "
                               "could not tell it from a component number",
                               name->text));
      } else if (auto parsed = ctx.name(*name, "NAME")) {
        term_.name = *parsed;
        name_ok_ = true;
      }
    }

    if (const Field* op = params.value("OPERATOR")) {
      term_.operator_loc = params.loc("OPERATOR");
      read_operator(ctx, *op);
    }
    if (params.enum_value("SIGN") == "NEGATIVE") {
      term_.sign = -1;
      term_.sign_loc = params.loc("SIGN");
    } else if (params.has("SIGN")) {
      term_.sign_loc = params.loc("SIGN");
    }
    // v1-reject items (§1.1): their data-line layout differs, so the lines are not read.
    if (params.has("INDEPENDENT COMPONENTS")) {
      ctx.report(DiagCode::unsupported_option, params.loc("INDEPENDENT COMPONENTS"),
                 "INDEPENDENT COMPONENTS on *CONNECTOR DERIVED COMPONENT is not supported in "
                 "this version");
      data_ok_ = false;
      skip_data_ = true;
    }
    if (!check_dependencies(ctx, "derived component coefficient")) {
      data_ok_ = false;
      skip_data_ = params.value("DEPENDENCIES") != nullptr;
    }
    warn_explicit_only(ctx, {"REGULARIZE", "RTOL"});
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    ++lines_;
    if (skip_data_) return;
    if (lines_ == 1) {
      read_components(ctx, line, fields);
    } else if (lines_ == 2) {
      read_coefficients(ctx, line, fields);
    } else if (lines_ == 3) {
      // A repeated coefficient line is a temperature table (§1.2): v1-reject.
      ctx.report(DiagCode::unsupported_dependencies, fields.empty() ? line.loc : fields[0].loc,
                 "temperature-dependent derived component coefficients are not supported");
      data_ok_ = false;
    }
  }

  void end(BlockContext& ctx) override {
    if (!skip_data_) {
      if (lines_ == 0) {
        ctx.report(DiagCode::missing_data_line, term_.loc,
                   "*CONNECTOR DERIVED COMPONENT needs a line of component numbers and a line "
                   "of coefficients");
        data_ok_ = false;
      } else if (lines_ == 1) {
        // Not confirmed whether Abaqus defaults the coefficients to 1.0 (§1.2, §6.2): clinch
        // refuses to guess.
        ctx.report(DiagCode::dc_missing_coefficients, term_.loc,
                   fmt::format("derived component '{}' has no coefficient line; give one "
                               "coefficient per listed component",
                               name_ok_ ? term_.name.display : std::string("?")));
        data_ok_ = false;
      }
    }
    if (!behavior_ || !name_ok_) return;
    term_.complete = data_ok_ && op_ok_ && lines_ >= 2;
    behavior_->derived_terms.push_back(std::move(term_));
  }

 private:
  void read_operator(BlockContext& ctx, const Field& op) {
    const std::string folded = fold_name(op.text);
    if (folded == "NORM") return;
    if (folded == "SQRTSUMSQUARES" || folded == "RSS") {
      // Not confirmed whether Abaqus accepts these spellings (§1.1, §6.1).
      ctx.report(DiagCode::operator_alias, op,
                 fmt::format("OPERATOR={} read as NORM", op.text));
      return;
    }
    static constexpr std::string_view kOperators[] = {"NORM", "MACAULEY SUM", "SUM"};
    auto word = ctx.word(op, kOperators, "OPERATOR");
    if (!word) {
      op_ok_ = false;
      return;
    }
    if (*word == "MACAULEY SUM") term_.op = DerivedOperator::MacauleySum;
    if (*word == "SUM") term_.op = DerivedOperator::Sum;
  }

  void read_components(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    if (fields.empty()) {
      ctx.missing(line.loc, "component number");
      data_ok_ = false;
      return;
    }
    if (!ctx.check_field_count(line, fields, kMaxComponents, "component numbers 1-6")) {
      data_ok_ = false;
    }
    const std::size_t n = std::min(fields.size(), kMaxComponents);
    listed_ = n;
    for (std::size_t j = 0; j < n; ++j) {
      const Field& field = fields[j];
      if (field.empty()) {
        ctx.missing(field.loc, "component number");
        data_ok_ = false;
        continue;
      }
      auto k = ctx.integer(field, "component number");
      if (!k) {
        data_ok_ = false;
        continue;
      }
      if (*k < 1 || *k > 6) {
        ctx.report(DiagCode::dc_bad_component, field,
                   fmt::format("component {} does not exist; components are numbered 1-6", *k));
        data_ok_ = false;
        continue;
      }
      bool repeated = false;
      for (std::size_t i = 0; i < term_.components.size(); ++i) {
        if (term_.components[i] == *k) {
          // The gradient formulas of §1.4 assume distinct components.
          Diagnostic& d = ctx.report(
              DiagCode::dc_duplicate_component, field,
              fmt::format("component {} is listed twice in one derived-component term", *k));
          d.notes.push_back({term_.component_locs[i], "first listed here"});
          repeated = true;
          break;
        }
      }
      if (repeated) {
        data_ok_ = false;
        continue;
      }
      term_.components.push_back(static_cast<int>(*k));
      term_.component_locs.push_back(field.loc);
    }
  }

  void read_coefficients(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    // One coefficient per listed component; the field after them is a temperature, which v1
    // ignores (behaviors.md §1.2); field variables need DEPENDENCIES > 0.
    if (fields.size() > listed_ + 1) {
      ctx.check_field_count(line, fields, listed_ + 1,
                            fmt::format("{} coefficient{} and a temperature", listed_,
                                        listed_ == 1 ? "" : "s"));
      data_ok_ = false;
    }
    if (!term_.components.empty() && term_.components.size() != listed_) {
      data_ok_ = false;  // a component field was bad: coefficients cannot be matched
    }
    for (std::size_t j = 0; j < listed_; ++j) {
      const bool present = j < fields.size() && !fields[j].empty();
      if (!present) {
        // A blank coefficient reads as 0.0 (general blank-field rule), which is almost never
        // meant (§1.2).
        SourceLoc where = j < fields.size() ? fields[j].loc : BlockContext::end_of_line(line);
        ctx.report(DiagCode::dc_zero_coefficient, where,
                   fmt::format("coefficient {} is blank and reads as 0.0", j + 1));
        term_.coefficients.push_back(0.0);
        continue;
      }
      auto c = ctx.real(fields[j], "coefficient");
      if (!c) {
        data_ok_ = false;
        term_.coefficients.push_back(0.0);
        continue;
      }
      term_.coefficients.push_back(*c);
    }
    if (fields.size() == listed_ + 1 && !fields[listed_].empty()) {
      ctx.report(DiagCode::temperature_ignored, fields[listed_],
                 "temperature of a derived component coefficient line ignored (clinch has no "
                 "temperature field)");
    }
    if (term_.coefficients.size() != term_.components.size()) {
      term_.coefficients.resize(term_.components.size(), 0.0);
    }
  }

  ConnectorBehavior* behavior_ = nullptr;
  DerivedComponentTerm term_;
  bool name_ok_ = false;
  bool op_ok_ = true;
  bool data_ok_ = true;
  bool skip_data_ = false;
  std::size_t lines_ = 0;   // positional data lines seen (blank lines count: input-syntax §3.4)
  std::size_t listed_ = 0;  // fields on the component line
};

}  // namespace

KeywordSpec derived_component_keyword_spec() {
  KeywordSpec spec;
  spec.name = "CONNECTOR DERIVED COMPONENT";
  spec.level = KeywordLevel::Model;
  spec.data = DataMode::Fields;
  spec.behavior_suboption = true;
  spec.params = {
      {"NAME", ParamKind::Value, true},
      // Checked by the handler: the aliases of NORM need a warning, not E0208.
      {"OPERATOR", ParamKind::Value},
      {"SIGN", ParamKind::Enum, false, {"POSITIVE", "NEGATIVE"}},
      {"INDEPENDENT COMPONENTS", ParamKind::Enum, false, {"POSITION", "CONSTITUTIVE MOTION"}},
      {"DEPENDENCIES", ParamKind::Value},
      {"EXTRAPOLATION", ParamKind::Enum, false, {"CONSTANT", "LINEAR"}},
      {"REGULARIZE", ParamKind::Value},
      {"RTOL", ParamKind::Value},
  };
  spec.make_handler = [] {
    return std::unique_ptr<KeywordHandler>(new DerivedComponentHandler);
  };
  return spec;
}

}  // namespace clinch
