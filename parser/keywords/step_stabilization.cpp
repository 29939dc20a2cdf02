// *STATIC, STABILIZE with FACTOR, ALLSDTOL and CONTINUE (docs/stabilization.md; the defaults in
// docs/decisions.md "Automatic stabilization").
#include <fmt/format.h>

#include "parser/keywords/history_keywords.hpp"

namespace clinch {
namespace {

// A positive value of `name` (ALLSDTOL may be 0: the constant factor); nullopt when absent or
// wrong, reported at its value.
std::optional<double> positive_param(BlockContext& ctx, std::string_view name, bool zero_allowed) {
  if (!ctx.params().has(name)) return std::nullopt;
  const std::optional<double> value = ctx.real_param(name);
  if (!value) return std::nullopt;
  if (*value < 0.0 || (*value == 0.0 && !zero_allowed)) {
    ctx.report(DiagCode::value_out_of_range, *ctx.params().value(name),
               fmt::format("{} must be {}, got {}", name,
                           zero_allowed ? "zero or positive" : "positive", *value));
    return std::nullopt;
  }
  return value;
}

}  // namespace

std::optional<StaticStabilization> read_stabilization(BlockContext& ctx, bool riks) {
  const ParamSet& params = ctx.params();
  if (!params.has("STABILIZE")) {
    for (std::string_view name : {"FACTOR", "ALLSDTOL", "CONTINUE"}) {
      if (!params.has(name)) continue;
      ctx.report(DiagCode::invalid_value, params.loc(name),
                 fmt::format("{} belongs to automatic stabilization: give STABILIZE too", name));
    }
    return std::nullopt;
  }
  if (riks) {
    ctx.report(DiagCode::unsupported_option, params.loc("STABILIZE", true),
               "STABILIZE cannot be used with RIKS: the arc length already passes the limit "
               "points that stabilization damps");
    return std::nullopt;
  }
  StaticStabilization s;
  s.loc = params.loc("STABILIZE", true);
  if (const Field* value = params.value("STABILIZE"); value && !value->empty()) {
    if (const std::optional<double> f = ctx.real(*value, "the dissipated energy fraction")) {
      if (*f <= 0.0 || *f >= 1.0) {
        ctx.report(DiagCode::value_out_of_range, *value,
                   fmt::format("the dissipated energy fraction must lie between 0 and 1, got {}",
                               value->text));
      } else {
        s.energy_fraction = *f;
      }
    }
  }
  s.factor = positive_param(ctx, "FACTOR", false);
  if (const std::optional<double> tol = positive_param(ctx, "ALLSDTOL", true)) {
    s.allsdtol = *tol;
    s.allsdtol_given = true;
  }
  s.continue_previous = params.has("CONTINUE") && params.enum_value("CONTINUE") == "YES";
  return s;
}

}  // namespace clinch
