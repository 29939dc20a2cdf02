// *INITIAL CONDITIONS (model data): TYPE=VELOCITY and TYPE=ROTATING VELOCITY, the nodal velocities
// a *DYNAMIC step starts from (docs/dynamics.md). VELOCITY data lines: node or node set, DOF (1–6),
// velocity. ROTATING VELOCITY takes pairs of lines: node or node set, ω, the first point on the
// axis; then the second point, optionally followed by a translational velocity (docs/decisions.md).
// Every other TYPE sets a field clinch has no use for yet, and is refused at its value.
#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "parser/keywords/history_keywords.hpp"

namespace clinch {
namespace {

class InitialConditionsHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    const ParamSet& params = ctx.params();
    skip_ = report_unsupported_params(ctx, {"USER", "FILE", "STEP", "INC", "INTERPOLATE"});
    const std::string_view type = params.enum_value("TYPE");
    rotating_ = type == "ROTATING VELOCITY";
    if (type != "VELOCITY" && !rotating_) {
      ctx.report(DiagCode::unsupported_option, params.loc("TYPE", true),
                 fmt::format("TYPE={} on *INITIAL CONDITIONS is not supported by clinch (only "
                             "TYPE=VELOCITY and TYPE=ROTATING VELOCITY)",
                             params.value("TYPE") ? params.value("TYPE")->text : type));
      skip_ = true;
    }
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (skip_ || line.blank) return;
    if (rotating_) {
      if (pending_) {
        axis_line(ctx, line, fields);
      } else {
        first_line(ctx, line, fields);
      }
      return;
    }
    ctx.check_field_count(line, fields, 3, "node or node set, DOF, velocity");
    if (fields.empty() || fields[0].empty()) {
      ctx.missing(fields.empty() ? line.loc : fields[0].loc, "node or node set");
      return;
    }
    auto target = ctx.target(fields[0], "node");
    if (fields.size() < 2 || fields[1].empty()) {
      ctx.missing(fields.size() < 2 ? BlockContext::end_of_line(line) : fields[1].loc, "DOF");
      return;
    }
    auto dof = ctx.integer(fields[1], "DOF");
    if (dof && (*dof < 1 || *dof > 6)) {
      ctx.report(DiagCode::invalid_dof, fields[1],
                 fmt::format("DOF {} is not valid (DOFs are 1-6)", *dof));
      return;
    }
    std::optional<double> value = 0.0;
    if (fields.size() > 2 && !fields[2].empty()) value = ctx.real(fields[2], "the velocity");
    if (!target || !dof || !value) return;
    InitialVelocity velocity;
    velocity.target = std::move(*target);
    velocity.dof = static_cast<int>(*dof);
    velocity.value = *value;
    velocity.loc = line.loc;
    velocity.dof_loc = fields[1].loc;
    ctx.model().history.initial_velocities.push_back(std::move(velocity));
  }

  void end(BlockContext& ctx) override {
    if (!pending_) return;
    ctx.report(DiagCode::missing_data_line, pending_->loc,
               "*INITIAL CONDITIONS, TYPE=ROTATING VELOCITY: this line needs a second data line "
               "with the second point on the axis of rotation");
    pending_.reset();
  }

 private:
  // First line: node or node set, ω, the first point on the axis.
  void first_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    ctx.check_field_count(line, fields, 5, "node or node set, angular velocity, x, y, z of the "
                                           "first point on the axis");
    RotatingVelocity rotating;
    rotating.loc = line.loc;
    bool ok = true;
    if (fields.empty() || fields[0].empty()) {
      ctx.missing(fields.empty() ? line.loc : fields[0].loc, "node or node set");
      ok = false;
    } else if (auto target = ctx.target(fields[0], "node")) {
      rotating.target = std::move(*target);
    } else {
      ok = false;
    }
    ok = read_real(ctx, line, fields, 1, "angular velocity", rotating.omega) && ok;
    for (std::size_t i = 0; i < 3; ++i) {
      ok = read_real(ctx, line, fields, 2 + i, kFirstPoint[i], rotating.a[i]) && ok;
    }
    // The second line is read as the axis whatever happened here, so that it is not taken for a
    // first line; `valid_` says whether the pair is kept.
    pending_ = std::move(rotating);
    valid_ = ok;
  }

  // Second line: the second point on the axis, then an optional translational velocity.
  void axis_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    RotatingVelocity rotating = std::move(*pending_);
    pending_.reset();
    ctx.check_field_count(line, fields, 6, "x, y, z of the second point on the axis, then "
                                           "optionally the translational velocity vx, vy, vz");
    bool ok = valid_;
    for (std::size_t i = 0; i < 3; ++i) {
      ok = read_real(ctx, line, fields, i, kSecondPoint[i], rotating.b[i]) && ok;
    }
    for (std::size_t i = 0; i < 3; ++i) {
      if (fields.size() <= 3 + i || fields[3 + i].empty()) continue;
      const auto v = ctx.real(fields[3 + i], kTranslation[i]);
      if (!v) ok = false;
      else rotating.translation[i] = *v;
    }
    if (!ok) return;
    const double length = std::hypot(rotating.b[0] - rotating.a[0], rotating.b[1] - rotating.a[1],
                                     rotating.b[2] - rotating.a[2]);
    const double scale = std::max({1.0, std::abs(rotating.a[0]), std::abs(rotating.a[1]),
                                   std::abs(rotating.a[2]), std::abs(rotating.b[0]),
                                   std::abs(rotating.b[1]), std::abs(rotating.b[2])});
    // Two points closer than the geometric tolerance's relative size leave no axis.
    if (!(length > 1e-8 * scale)) {
      ctx.report(DiagCode::degenerate_geometry, line.loc,
                 fmt::format("the second point on the axis of rotation ({}, {}, {}) coincides with "
                             "the first ({}, {}, {}): two distinct points define the axis",
                             rotating.b[0], rotating.b[1], rotating.b[2], rotating.a[0],
                             rotating.a[1], rotating.a[2]));
      return;
    }
    ctx.model().history.rotating_velocities.push_back(std::move(rotating));
  }

  // A required real field; E0305 at the end of a short line.
  static bool read_real(BlockContext& ctx, const DataLine& line, const std::vector<Field>& fields,
                        std::size_t i, std::string_view what, double& out) {
    if (fields.size() <= i || fields[i].empty()) {
      ctx.missing(fields.size() <= i ? BlockContext::end_of_line(line) : fields[i].loc, what);
      return false;
    }
    const auto value = ctx.real(fields[i], what);
    if (value) out = *value;
    return value.has_value();
  }

  static constexpr std::string_view kFirstPoint[3] = {"x of the first point on the axis",
                                                      "y of the first point on the axis",
                                                      "z of the first point on the axis"};
  static constexpr std::string_view kSecondPoint[3] = {"x of the second point on the axis",
                                                       "y of the second point on the axis",
                                                       "z of the second point on the axis"};
  static constexpr std::string_view kTranslation[3] = {"translational velocity vx",
                                                       "translational velocity vy",
                                                       "translational velocity vz"};

  bool skip_ = false;
  bool rotating_ = false;
  std::optional<RotatingVelocity> pending_;  // a first line waiting for its axis line
  bool valid_ = true;
};

}  // namespace

std::vector<KeywordSpec> initial_condition_keyword_specs() {
  KeywordSpec spec;
  spec.name = "INITIAL CONDITIONS";
  spec.level = KeywordLevel::Model;
  spec.params = {
      {"TYPE",
       ParamKind::Enum,
       true,
       {"VELOCITY", "ROTATING VELOCITY", "STRESS", "TEMPERATURE", "FIELD", "SOLUTION",
        "PLASTIC STRAIN", "HARDENING", "RATIO", "SATURATION", "PORE PRESSURE", "DENSITY",
        "INITIAL GAP", "CONTACT", "REF COORDINATE", "SPECIFIC ENERGY", "MASS FLOW RATE",
        "NODE REF COORDINATE", "CONCENTRATION", "ACOUSTIC STATIC PRESSURE", "FLUID PRESSURE"}},
      unsupported_param("USER"),
      unsupported_param("FILE"),
      unsupported_param("STEP"),
      unsupported_param("INC"),
      unsupported_param("INTERPOLATE"),
  };
  spec.make_handler = &make<InitialConditionsHandler>;
  return {std::move(spec)};
}

}  // namespace clinch
