// *CONNECTOR FRICTION and *FRICTION inside a connector behaviour (friction.md §2–§3). The
// friction keyword records a FrictionDefinition and registers itself as a potential owner
// (derived-components-and-potentials.md §2.7); *FRICTION attaches its law to the nearest
// preceding friction definition of the block. Checks that need the connection type or the
// derived components run in resolve_potentials.cpp.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "parser/block_context.hpp"
#include "parser/expression.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keywords/behavior_option_common.hpp"
#include "parser/keywords/potential_friction_specs.hpp"

namespace clinch {
namespace {

bool is_number_field(const Field& field) {
  if (field.parameter) return field.parameter->is_number();
  if (field.quoted || field.text.empty()) return false;
  const char c = field.text[0];
  return (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.';
}

// A component number 1…6 given as a parameter value (value-out-of-range at the value otherwise,
// behaviors.md §1.1).
std::optional<int> component_value(BlockContext& ctx, const Field& value, std::string_view what) {
  auto k = ctx.integer(value, what);
  if (!k) return std::nullopt;
  if (*k < 1 || *k > 6) {
    ctx.report(DiagCode::value_out_of_range, value,
               fmt::format("{} {} is out of range (1-6)", what, *k));
    return std::nullopt;
  }
  return static_cast<int>(*k);
}

class ConnectorFrictionHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    behavior_ = current_behavior(ctx);
    const ParamSet& params = ctx.params();
    def_.loc = ctx.keyword().loc;
    if (behavior_) def_.extrapolation = behavior_->extrapolation;

    def_.predefined = params.has("PREDEFINED");
    def_.predefined_loc = params.loc("PREDEFINED");
    if (def_.predefined) {
      // The three forms exclude each other (§2.1).
      for (std::string_view other : {"COMPONENT", "CONTACT FORCE", "INDEPENDENT COMPONENTS"}) {
        if (!params.has(other)) continue;
        ctx.report(DiagCode::friction_exclusive, params.loc(other),
                   fmt::format("{} cannot be combined with PREDEFINED: predefined friction takes "
                               "its friction components and contact force from the connection "
                               "type",
                               other));
      }
    } else {
      if (const Field* value = params.value("COMPONENT")) {
        def_.component_loc = params.loc("COMPONENT");
        if (auto k = component_value(ctx, *value, "COMPONENT")) def_.component = *k;
      }
      if (const Field* value = params.value("CONTACT FORCE")) read_contact_force(ctx, *value);
      if (params.has("INDEPENDENT COMPONENTS")) {
        ctx.report(DiagCode::unsupported_option, params.loc("INDEPENDENT COMPONENTS"),
                   "INDEPENDENT COMPONENTS on *CONNECTOR FRICTION is not supported in this "
                   "version");
        read_data_ = false;
      }
    }
    if (const Field* value = params.value("STICK STIFFNESS")) {
      def_.stick_stiffness_loc = value->loc;
      if (auto k = ctx.real(*value, "STICK STIFFNESS")) {
        if (*k <= 0.0) {
          ctx.report(DiagCode::friction_stick_stiffness, *value,
                     fmt::format("STICK STIFFNESS must be positive, got {}", value->text));
        } else {
          def_.stick_stiffness = *k;
        }
      }
    }
    if (!check_dependencies(ctx, "friction")) read_data_ = false;
    if (params.has("EXTRAPOLATION")) def_.extrapolation = params.enum_value("EXTRAPOLATION");
    warn_explicit_only(ctx, {"REGULARIZE", "RTOL"});

    if (behavior_ && def_.predefined) {
      // At most one predefined friction per behaviour (§2).
      for (const FrictionDefinition& other : behavior_->frictions) {
        if (!other.predefined) continue;
        Diagnostic& d = ctx.report(DiagCode::friction_predefined_duplicate, def_.loc,
                                   "second predefined *CONNECTOR FRICTION in this behavior; a "
                                   "behavior takes at most one");
        d.notes.push_back({other.loc, "first predefined friction is here"});
        break;
      }
    }
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (line.blank || fields.empty() || !read_data_) return;  // table rows: blanks skipped
    if (!ctx.check_field_count(line, fields, 3, "F_int, accumulated slip, temperature")) {
      data_ok_ = false;
    }
    const Field& f_int = fields[0];
    double internal = 0.0;
    if (f_int.empty()) {
      ctx.missing(f_int.loc, "internal contact force");
      data_ok_ = false;
    } else if (auto v = ctx.real(f_int, "internal contact force")) {
      internal = *v;
      if (internal < 0.0) {
        // F_N = |g + F_int| grows again once F_int < −g (§2.2).
        ctx.report(DiagCode::friction_negative_internal, f_int,
                   fmt::format("internal contact force {} is negative; the friction capacity "
                               "|g + F_int| grows again when it exceeds the contact measure",
                               f_int.text));
      }
    } else {
      data_ok_ = false;
    }
    double slip = 0.0;
    SourceLoc slip_loc = f_int.loc;
    if (fields.size() > 1 && !fields[1].empty()) {
      slip_loc = fields[1].loc;
      if (auto v = ctx.real(fields[1], "accumulated slip")) {
        slip = *v;
      } else {
        data_ok_ = false;
      }
    }
    if (fields.size() > 2 && !fields[2].empty()) read_temperature(ctx, fields[2]);
    if (!def_.slip.empty() && slip <= def_.slip.back()) {
      ctx.report(DiagCode::table_not_increasing, slip_loc,
                 fmt::format("accumulated slip {} does not increase (previous row: {}); the "
                             "internal contact force table needs strictly increasing slip",
                             fmt::format("{}", slip), fmt::format("{}", def_.slip.back())));
      data_ok_ = false;
    }
    def_.internal_force.push_back(internal);
    def_.slip.push_back(slip);
  }

  void end(BlockContext& ctx) override {
    // User-defined friction without a contact measure and without internal force never acts
    // (§8, friction-zero-contact).
    if (!def_.predefined && def_.contact == FrictionDefinition::Contact::None && data_ok_ &&
        read_data_) {
      bool any_force = false;
      for (double f : def_.internal_force) any_force = any_force || f != 0.0;
      if (!any_force) {
        ctx.report(DiagCode::friction_zero_contact, def_.loc,
                   "friction can never act: no CONTACT FORCE and no internal contact force");
      }
    }
    if (!behavior_) return;
    PotentialOwner owner;
    owner.kind = PotentialOwner::Kind::Friction;
    owner.index = static_cast<std::int32_t>(behavior_->frictions.size());
    owner.loc = def_.loc;
    // DCP §2.7: coupled user-defined friction needs a potential; COMPONENT= and PREDEFINED
    // forbid one.
    const bool has_component = ctx.params().has("COMPONENT") && !def_.predefined;
    owner.allows_potential = !def_.predefined && !has_component;
    owner.requires_potential = owner.allows_potential;
    if (def_.predefined) {
      owner.why_not_allowed = "PREDEFINED";
    } else if (has_component) {
      const Field* value = ctx.params().value("COMPONENT");
      owner.why_not_allowed = "COMPONENT=" + (value ? value->text : std::string());
    }
    def_.owner = static_cast<std::int32_t>(behavior_->potential_owners.size());
    behavior_->potential_owners.push_back(std::move(owner));
    behavior_->frictions.push_back(std::move(def_));
  }

 private:
  void read_contact_force(BlockContext& ctx, const Field& value) {
    def_.contact_loc = ctx.params().loc("CONTACT FORCE");
    if (is_number_field(value)) {
      if (auto k = component_value(ctx, value, "CONTACT FORCE component")) {
        def_.contact = FrictionDefinition::Contact::Component;
        def_.contact_component = *k;
      }
    } else if (auto name = ctx.name(value, "CONTACT FORCE")) {
      def_.contact = FrictionDefinition::Contact::Derived;
      def_.contact_name = *name;
    }
  }

  // Temperature columns: constant ones are ignored with a warning, varying ones rejected
  // (§2.4, behaviors.md §1.2).
  void read_temperature(BlockContext& ctx, const Field& field) {
    auto t = ctx.real(field, "temperature");
    if (!t) {
      data_ok_ = false;
      return;
    }
    if (!temperature_) {
      temperature_ = *t;
      ctx.report(DiagCode::temperature_ignored, field,
                 "temperature of the internal contact force ignored (clinch has no temperature "
                 "field)");
    } else if (*t != *temperature_) {
      ctx.report(DiagCode::unsupported_dependencies, field,
                 "temperature-dependent internal contact force is not supported");
      data_ok_ = false;
    }
  }

  ConnectorBehavior* behavior_ = nullptr;
  FrictionDefinition def_;
  bool read_data_ = true;
  bool data_ok_ = true;
  std::optional<double> temperature_;
};

// *FRICTION as the law of a connector friction definition (§3).
class FrictionLawHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    ConnectorBehavior* behavior = current_behavior(ctx);
    const ParamSet& params = ctx.params();
    law_.loc = ctx.keyword().loc;
    if (behavior) {
      if (behavior->frictions.empty()) {
        ctx.report(DiagCode::wrong_level, law_.loc,
                   "'*FRICTION' in a *CONNECTOR BEHAVIOR must follow *CONNECTOR FRICTION");
      } else if (behavior->frictions.back().has_law) {
        Diagnostic& d = ctx.report(DiagCode::friction_law_duplicate, law_.loc,
                                   "second *FRICTION for one *CONNECTOR FRICTION; each friction "
                                   "definition takes exactly one");
        d.notes.push_back({behavior->frictions.back().law.loc, "first *FRICTION is here"});
      } else {
        target_ = &behavior->frictions.back();
      }
    }

    law_.exponential_decay = params.has("EXPONENTIAL DECAY");
    if (params.has("TEST DATA")) {
      ctx.report(DiagCode::unsupported_option, params.loc("TEST DATA"),
                 "EXPONENTIAL DECAY with TEST DATA is not supported in this version; give "
                 "mu_s, mu_k and d_c");
      read_data_ = false;
    }
    if (const Field* value = params.value("TAUMAX")) {
      if (auto cap = ctx.real(*value, "TAUMAX")) {
        if (*cap < 0.0) {
          ctx.report(DiagCode::value_out_of_range, *value,
                     fmt::format("TAUMAX must not be negative, got {}", value->text));
        } else {
          law_.taumax = *cap;
        }
      }
    }
    if (!check_dependencies(ctx, "friction coefficient")) read_data_ = false;
    for (std::string_view penalty : {"SLIP TOLERANCE", "ELASTIC SLIP"}) {
      if (params.has(penalty)) {
        ctx.report(DiagCode::friction_option_ignored, params.loc(penalty),
                   fmt::format("{} controls surface-contact penalty friction and is ignored in "
                               "a connector; STICK STIFFNESS controls the stick",
                               penalty));
      }
    }
    warn_explicit_only(ctx, {"REGULARIZE", "RTOL"});
    for (std::string_view rejected : {"ROUGH", "LAGRANGE", "USER"}) {
      if (params.has(rejected)) {
        ctx.report(DiagCode::unsupported_option, params.loc(rejected),
                   fmt::format("*FRICTION, {} is not supported for connector friction",
                               rejected));
        read_data_ = false;
      }
    }
    if (params.has("ANISOTROPIC")) {
      ctx.report(DiagCode::unsupported_option, params.loc("ANISOTROPIC"),
                 "*FRICTION, ANISOTROPIC is not supported for connector friction; use a "
                 "*CONNECTOR POTENTIAL for directional friction");
      read_data_ = false;
    }
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (line.blank || fields.empty() || !read_data_) return;
    ++rows_;
    if (law_.exponential_decay) {
      read_decay(ctx, line, fields);
    } else {
      read_row(ctx, line, fields);
    }
  }

  void end(BlockContext& ctx) override {
    if (read_data_ && rows_ == 0) {
      ctx.report(DiagCode::missing_data_line, law_.loc,
                 law_.exponential_decay
                     ? "*FRICTION, EXPONENTIAL DECAY needs a data line (mu_s, mu_k, d_c)"
                     : "*FRICTION needs a data line with the friction coefficient");
      data_ok_ = false;
    }
    if (read_data_ && !law_.exponential_decay && rows_ > 1) check_table(ctx);
    law_.complete = read_data_ && data_ok_;
    if (target_) {
      target_->law = std::move(law_);
      target_->has_law = true;
    }
  }

 private:
  // μ, slip rate, contact force, temperature (§3.2).
  void read_row(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    if (!ctx.check_field_count(line, fields, 4, "mu, slip rate, contact force, temperature")) {
      data_ok_ = false;
    }
    double mu = 0.0, rate = 0.0, force = 0.0;
    if (fields[0].empty()) {
      ctx.missing(fields[0].loc, "friction coefficient");
      data_ok_ = false;
    } else if (auto v = ctx.real(fields[0], "friction coefficient")) {
      mu = *v;
      if (mu < 0.0) {
        ctx.report(DiagCode::friction_negative_mu, fields[0],
                   fmt::format("friction coefficient {} is negative", fields[0].text));
        data_ok_ = false;
      }
    } else {
      data_ok_ = false;
    }
    SourceLoc rate_loc = line.loc, force_loc = line.loc;
    if (fields.size() > 1 && !fields[1].empty()) {
      rate_loc = fields[1].loc;
      if (auto v = ctx.real(fields[1], "slip rate")) rate = *v; else data_ok_ = false;
    }
    if (fields.size() > 2 && !fields[2].empty()) {
      force_loc = fields[2].loc;
      if (auto v = ctx.real(fields[2], "contact force")) force = *v; else data_ok_ = false;
    }
    if (fields.size() > 3 && !fields[3].empty()) {
      auto t = ctx.real(fields[3], "temperature");
      if (!t) {
        data_ok_ = false;
      } else if (!temperature_) {
        temperature_ = *t;
        ctx.report(DiagCode::temperature_ignored, fields[3],
                   "temperature of the friction coefficient ignored (clinch has no temperature "
                   "field)");
      } else if (*t != *temperature_) {
        ctx.report(DiagCode::unsupported_dependencies, fields[3],
                   "temperature-dependent friction coefficients are not supported");
        data_ok_ = false;
      }
    }
    law_.mu.push_back(mu);
    law_.slip_rate.push_back(rate);
    law_.contact_force.push_back(force);
    rate_locs_.push_back(rate_loc);
    force_locs_.push_back(force_loc);
  }

  // μ_s, μ_k, d_c (§3.2): one line.
  void read_decay(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    if (rows_ > 1) {
      if (rows_ == 2) {
        ctx.report(DiagCode::unexpected_data_line, line.loc,
                   "*FRICTION, EXPONENTIAL DECAY takes one data line (mu_s, mu_k, d_c)");
      }
      data_ok_ = false;
      return;
    }
    if (!ctx.check_field_count(line, fields, 3, "mu_s, mu_k, d_c")) data_ok_ = false;
    static constexpr std::string_view kWhat[] = {"static friction coefficient mu_s",
                                                 "kinetic friction coefficient mu_k",
                                                 "decay coefficient d_c"};
    double values[3] = {0.0, 0.0, 0.0};
    bool have[3] = {false, false, false};
    for (std::size_t i = 0; i < 3; ++i) {
      if (i >= fields.size() || fields[i].empty()) {
        ctx.missing(i < fields.size() ? fields[i].loc : BlockContext::end_of_line(line),
                    kWhat[i]);
        data_ok_ = false;
        continue;
      }
      auto v = ctx.real(fields[i], kWhat[i]);
      if (!v) {
        data_ok_ = false;
        continue;
      }
      if (*v < 0.0) {
        ctx.report(DiagCode::friction_negative_mu, fields[i],
                   fmt::format("{} {} is negative", kWhat[i], fields[i].text));
        data_ok_ = false;
        continue;
      }
      values[i] = *v;
      have[i] = true;
    }
    law_.mu_static = values[0];
    law_.mu_kinetic = values[1];
    law_.decay = values[2];
    if (have[0] && have[1] && values[1] > values[0]) {
      ctx.report(DiagCode::friction_decay_increasing, line.loc,
                 fmt::format("mu_k={} is larger than mu_s={}: the friction coefficient grows "
                             "with the slip rate",
                             fields[1].text, fields[0].text));
    }
  }

  // v1: μ depends on one of slip rate or contact force, whose values increase strictly (§3.2).
  void check_table(BlockContext& ctx) {
    bool rate_varies = false, force_varies = false;
    for (std::size_t i = 1; i < law_.mu.size(); ++i) {
      rate_varies = rate_varies || law_.slip_rate[i] != law_.slip_rate[0];
      force_varies = force_varies || law_.contact_force[i] != law_.contact_force[0];
    }
    if (rate_varies && force_varies) {
      ctx.report(DiagCode::unsupported_dependencies, law_.loc,
                 "friction coefficient table depends on both slip rate and contact force; v1 "
                 "supports one of them");
      data_ok_ = false;
      return;
    }
    if (!rate_varies && !force_varies) {
      // Several rows that vary in neither column do not define a function.
      ctx.report(DiagCode::table_not_increasing,
                 rate_locs_.size() > 1 ? rate_locs_[1] : law_.loc,
                 "friction coefficient table rows repeat the same slip rate and contact force");
      data_ok_ = false;
      return;
    }
    const std::vector<double>& column = rate_varies ? law_.slip_rate : law_.contact_force;
    const std::vector<SourceLoc>& locs = rate_varies ? rate_locs_ : force_locs_;
    for (std::size_t i = 1; i < column.size(); ++i) {
      if (column[i] <= column[i - 1]) {
        ctx.report(DiagCode::table_not_increasing, locs[i],
                   fmt::format("{} {} does not increase (previous row: {})",
                               rate_varies ? "slip rate" : "contact force",
                               fmt::format("{}", column[i]), fmt::format("{}", column[i - 1])));
        data_ok_ = false;
        return;
      }
    }
    law_.variable = rate_varies ? FrictionLaw::Variable::SlipRate
                                : FrictionLaw::Variable::ContactForce;
  }

  FrictionDefinition* target_ = nullptr;
  FrictionLaw law_;
  bool read_data_ = true;
  bool data_ok_ = true;
  std::size_t rows_ = 0;
  std::optional<double> temperature_;
  std::vector<SourceLoc> rate_locs_;
  std::vector<SourceLoc> force_locs_;
};

}  // namespace

std::vector<KeywordSpec> friction_keyword_specs() {
  std::vector<KeywordSpec> specs;

  KeywordSpec friction;
  friction.name = "CONNECTOR FRICTION";
  friction.level = KeywordLevel::Model;
  friction.data = DataMode::Fields;
  friction.behavior_suboption = true;
  friction.params = {
      {"PREDEFINED", ParamKind::Flag},
      {"STICK STIFFNESS", ParamKind::Value},
      {"COMPONENT", ParamKind::Value},
      {"CONTACT FORCE", ParamKind::Value},
      {"INDEPENDENT COMPONENTS", ParamKind::Enum, false, {"POSITION", "CONSTITUTIVE MOTION"}},
      {"DEPENDENCIES", ParamKind::Value},
      {"EXTRAPOLATION", ParamKind::Enum, false, {"CONSTANT", "LINEAR"}},
      {"REGULARIZE", ParamKind::Value},
      {"RTOL", ParamKind::Value},
  };
  friction.make_handler = [] {
    return std::unique_ptr<KeywordHandler>(new ConnectorFrictionHandler);
  };
  specs.push_back(std::move(friction));

  KeywordSpec law;
  law.name = "FRICTION";
  law.level = KeywordLevel::Model;
  law.data = DataMode::Fields;
  law.behavior_suboption = true;
  // Outside a behaviour *FRICTION is surface-contact friction: E0202 from the reader.
  law.unsupported_outside_behavior = true;
  law.params = {
      {"EXPONENTIAL DECAY", ParamKind::Flag},
      {"TEST DATA", ParamKind::Flag},
      {"TAUMAX", ParamKind::Value},
      {"DEPENDENCIES", ParamKind::Value},
      {"SLIP TOLERANCE", ParamKind::Value},
      {"ELASTIC SLIP", ParamKind::Value},
      {"REGULARIZE", ParamKind::Value},
      {"RTOL", ParamKind::Value},
      {"ROUGH", ParamKind::Flag},
      {"LAGRANGE", ParamKind::Flag},
      {"USER", ParamKind::OptionalValue},
      {"ANISOTROPIC", ParamKind::OptionalValue},
  };
  law.make_handler = [] { return std::unique_ptr<KeywordHandler>(new FrictionLawHandler); };
  specs.push_back(std::move(law));
  return specs;
}

}  // namespace clinch
