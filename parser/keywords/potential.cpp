// *CONNECTOR POTENTIAL (derived-components-and-potentials.md §2): parameters, the six-field data
// lines (and the manual's short layout, with a warning), the checks that need only the line
// itself (§2.2, §2.3), and the attachment to the nearest preceding owner keyword of the same
// behaviour block (§2.7). The plasticity/friction rules need the derived-component types and run
// in resolve_potentials.cpp.
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "parser/block_context.hpp"
#include "parser/expression.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keywords/behavior_option_common.hpp"
#include "parser/keywords/potential_friction_specs.hpp"
#include "src/model/potential_queries.hpp"

namespace clinch {
namespace {

constexpr std::string_view kFunctions[] = {"ABS", "MACAULEY", "NONE"};

// Field 1 is a component number when it looks like a number (a name starts with a letter, '_'
// or a quote: input-syntax.md §4).
bool is_number_field(const Field& field) {
  if (field.parameter) return field.parameter->is_number();
  if (field.quoted || field.text.empty()) return false;
  const char c = field.text[0];
  return (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.';
}

// Field 3 holds a word instead of an exponent: the manual's short layout (§2.2).
bool is_function_word(const Field& field) {
  if (field.parameter) return false;
  if (field.quoted || field.empty()) return false;
  const std::string folded = fold_name(field.text);
  return folded == "ABS" || folded == "MACAULEY" || folded == "NONE";
}

std::string format_number(double v) { return fmt::format("{}", v); }

class PotentialHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    behavior_ = current_behavior(ctx);
    const ParamSet& params = ctx.params();
    potential_.loc = ctx.keyword().loc;

    if (const Field* op = params.value("OPERATOR")) read_operator(ctx, *op);
    if (const Field* exponent = params.value("EXPONENT")) {
      if (auto beta = ctx.real(*exponent, "EXPONENT")) {
        potential_.exponent_loc = exponent->loc;
        potential_.exponent_text = exponent->text;
        if (*beta <= 0.0) {
          ctx.report(DiagCode::value_out_of_range, *exponent,
                     fmt::format("EXPONENT must be positive, got {}", exponent->text));
        } else {
          potential_.exponent = *beta;
          potential_.exponent_given = true;
        }
      }
      if (potential_.op == PotentialOperator::Max) {
        ctx.report(DiagCode::potential_exponent_ignored, params.loc("EXPONENT"),
                   "EXPONENT has no meaning with OPERATOR=MAX and is ignored");
      }
    }
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (line.blank || fields.empty()) return;  // repeated lines: blank lines are skipped
    PotentialContribution c;
    c.loc = line.loc;
    c.alpha = potential_.exponent;
    bool ok = true;

    // Short layout `name, R, H, a, s` when field 3 is a function word (§2.2).
    const bool short_layout = fields.size() >= 3 && is_function_word(fields[2]);
    const std::size_t max_fields = short_layout ? 5 : 6;
    if (!ctx.check_field_count(line, fields, max_fields,
                               short_layout ? "short layout: name, R, H, a, s"
                                            : "component or name, R, alpha, H, a, s")) {
      ok = false;
    }
    auto field = [&](std::size_t i) -> const Field* {
      return i < fields.size() && !fields[i].empty() ? &fields[i] : nullptr;
    };

    // Field 1: intrinsic component or derived component name.
    const Field& source = fields[0];
    c.source_loc = source.loc;
    if (source.empty()) {
      ctx.missing(source.loc, "component or derived component name");
      ok = false;
    } else if (is_number_field(source)) {
      if (auto k = ctx.integer(source, "component number")) {
        if (*k < 1 || *k > 6) {
          ctx.report(DiagCode::value_out_of_range, source,
                     fmt::format("component {} is out of range (1-6)", *k));
          ok = false;
        } else {
          c.component = static_cast<int>(*k);
        }
      } else {
        ok = false;
      }
    } else if (auto name = ctx.name(source, "derived component name")) {
      c.derived = true;
      c.derived_name = *name;
    } else {
      ok = false;
    }

    // Field 2: R_i, default 1.0; zero is an error, a negative value is allowed.
    if (const Field* f = field(1)) {
      c.scale_loc = f->loc;
      if (auto r = ctx.real(*f, "scaling factor R")) {
        if (*r == 0.0) {
          ctx.report(DiagCode::potential_zero_scale, *f,
                     "scaling factor R of a potential contribution must not be zero");
          ok = false;
        } else {
          c.scale = *r;
        }
      } else {
        ok = false;
      }
    }

    std::size_t next = 2;  // index of the H field
    if (short_layout) {
      const Field& h = fields[2];
      std::string example = fmt::format("{}, {}, , {}", source.text,
                                        fields[1].empty() ? std::string() : fields[1].text,
                                        fold_name(h.text));
      ctx.report(DiagCode::potential_short_layout, h,
                 fmt::format("field 3 read as H function; write '{}' to silence", example));
    } else {
      // Field 3: α_i, default β.
      if (const Field* f = field(2)) {
        c.alpha_loc = f->loc;
        c.alpha_text = f->text;
        if (auto alpha = ctx.real(*f, "exponent alpha")) {
          if (*alpha <= 0.0) {
            ctx.report(DiagCode::value_out_of_range, *f,
                       fmt::format("exponent alpha must be positive, got {}", f->text));
            ok = false;
          } else {
            c.alpha = *alpha;
            c.alpha_given = true;
            if (potential_.op == PotentialOperator::Max) {
              ctx.report(DiagCode::potential_exponent_ignored, *f,
                         "exponent alpha has no meaning with OPERATOR=MAX and is ignored");
            }
          }
        } else {
          ok = false;
        }
      }
      next = 3;
    }

    // H_i, default ABS.
    if (const Field* f = field(next)) {
      c.function_loc = f->loc;
      if (!f->parameter && fold_name(f->text) == "IDENTITY") {
        Diagnostic& d = ctx.report(
            DiagCode::invalid_value, *f,
            fmt::format("invalid value '{}' for H function (expected ABS, MACAULEY or NONE)",
                        f->text));
        d.notes.push_back({f->loc, "did you mean NONE?"});
        ok = false;
      } else if (auto word = ctx.word(*f, kFunctions, "H function")) {
        c.function_given = true;
        if (*word == "MACAULEY") c.function = PotentialFunction::Macauley;
        if (*word == "NONE") c.function = PotentialFunction::None;
      } else {
        ok = false;
      }
    }
    // a_i, default 0.
    if (const Field* f = field(next + 1)) {
      if (auto a = ctx.real(*f, "shift a")) {
        c.shift = *a;
      } else {
        ok = false;
      }
    }
    // s_i: exactly +1 or −1 after <param> substitution.
    if (const Field* f = field(next + 2)) {
      c.sign_loc = f->loc;
      if (auto s = ctx.real(*f, "sign s")) {
        if (*s != 1.0 && *s != -1.0) {
          ctx.report(DiagCode::potential_bad_sign, *f,
                     fmt::format("sign s={} of a potential contribution must be 1.0 or -1.0",
                                 f->text));
          ok = false;
        } else {
          c.sign = *s;
        }
      } else {
        ok = false;
      }
    }

    // H = NONE needs α = β = 1 (§2.3), whatever the owner. With OPERATOR=MAX the exponents are
    // ignored (P = max s_i P_i), so the rule concerns SUM potentials only (clinch reading).
    if (c.function == PotentialFunction::None && potential_.op == PotentialOperator::Sum &&
        (c.alpha != 1.0 || potential_.exponent != 1.0)) {
      ctx.report(DiagCode::potential_identity_exponent, c.function_loc,
                 fmt::format("H=NONE requires alpha = beta = 1 (here alpha={}, EXPONENT={})",
                             c.alpha_given ? c.alpha_text : format_number(c.alpha),
                             potential_.exponent_given ? potential_.exponent_text
                                                       : format_number(potential_.exponent)));
      ok = false;
    }
    c.valid = ok;
    potential_.contributions.push_back(std::move(c));
  }

  void end(BlockContext& ctx) override {
    if (potential_.contributions.empty()) {
      ctx.report(DiagCode::potential_empty, potential_.loc,
                 "*CONNECTOR POTENTIAL needs at least one data line (a contribution)");
    }
    if (!behavior_) return;
    attach(ctx);
    warn_negative_base(ctx);
    behavior_->potentials.push_back(std::move(potential_));
  }

 private:
  void read_operator(BlockContext& ctx, const Field& op) {
    const std::string folded = fold_name(op.text);
    if (folded == "MAXIMUM") {
      // Not confirmed whether Abaqus accepts MAXIMUM (§2.1, §6.1); clinch asks for MAX.
      Diagnostic& d = ctx.report(DiagCode::invalid_value, op,
                                 fmt::format("invalid value '{}' for OPERATOR (expected SUM or "
                                             "MAX)", op.text));
      d.notes.push_back({op.loc, "did you mean MAX?"});
      return;
    }
    static constexpr std::string_view kOperators[] = {"SUM", "MAX"};
    if (auto word = ctx.word(op, kOperators, "OPERATOR")) {
      if (*word == "MAX") potential_.op = PotentialOperator::Max;
    }
  }

  // §2.7: the potential belongs to the nearest preceding owner keyword of the block.
  void attach(BlockContext& ctx) {
    auto& owners = behavior_->potential_owners;
    if (owners.empty()) {
      ctx.report(DiagCode::potential_no_owner, potential_.loc,
                 "*CONNECTOR POTENTIAL must follow *CONNECTOR PLASTICITY, *CONNECTOR FRICTION, "
                 "*CONNECTOR DAMAGE INITIATION or *CONNECTOR DAMAGE EVOLUTION in the same "
                 "*CONNECTOR BEHAVIOR");
      return;
    }
    PotentialOwner& owner = owners.back();
    const char* keyword = owner_keyword(owner.kind);
    if (!owner.allows_potential) {
      Diagnostic& d = ctx.report(
          DiagCode::potential_not_allowed, potential_.loc,
          owner.why_not_allowed.empty()
              ? fmt::format("*CONNECTOR POTENTIAL is not allowed after this {}", keyword)
              : fmt::format("*CONNECTOR POTENTIAL is not allowed after {} with {}", keyword,
                            owner.why_not_allowed));
      d.notes.push_back({owner.loc, fmt::format("the {} is here", keyword)});
      return;
    }
    if (owner.potential >= 0 &&
        static_cast<std::size_t>(owner.potential) < behavior_->potentials.size()) {
      Diagnostic& d = ctx.report(
          DiagCode::potential_duplicate, potential_.loc,
          fmt::format("second *CONNECTOR POTENTIAL for the {}; each owner takes one", keyword));
      d.notes.push_back(
          {behavior_->potentials[static_cast<std::size_t>(owner.potential)].loc,
           "first potential is here"});
      return;
    }
    owner.potential = static_cast<std::int32_t>(behavior_->potentials.size());
    potential_.owner = static_cast<std::int32_t>(owners.size() - 1);
  }

  // §2.3: with SUM, β ≠ 1 and a negative sign the base can turn negative. Plasticity and friction
  // potentials cannot get there: their own rules (§2.6) already reject such a potential.
  void warn_negative_base(BlockContext& ctx) {
    if (potential_.op != PotentialOperator::Sum || potential_.exponent == 1.0) return;
    if (potential_.owner >= 0) {
      const PotentialOwner& owner =
          behavior_->potential_owners[static_cast<std::size_t>(potential_.owner)];
      if (owner.kind == PotentialOwner::Kind::Plasticity ||
          owner.kind == PotentialOwner::Kind::Friction) {
        return;
      }
    }
    for (const PotentialContribution& c : potential_.contributions) {
      if (c.sign < 0.0) {
        ctx.report(DiagCode::potential_may_be_complex, c.sign_loc,
                   fmt::format("with EXPONENT={} a negative sign can make the sum negative; "
                               "clinch then uses sgn(S)*|S|^(1/beta)",
                               format_number(potential_.exponent)));
        return;
      }
    }
  }

  ConnectorBehavior* behavior_ = nullptr;
  Potential potential_;
};

}  // namespace

KeywordSpec potential_keyword_spec() {
  KeywordSpec spec;
  spec.name = "CONNECTOR POTENTIAL";
  spec.level = KeywordLevel::Model;
  spec.data = DataMode::Fields;
  spec.behavior_suboption = true;
  spec.params = {
      // Checked by the handler: MAXIMUM gets a "did you mean MAX?" note (§2.1).
      {"OPERATOR", ParamKind::Value},
      {"EXPONENT", ParamKind::Value},
  };
  spec.make_handler = [] { return std::unique_ptr<KeywordHandler>(new PotentialHandler); };
  return spec;
}

}  // namespace clinch
