// *KINEMATIC COUPLING, and *COUPLING with its method *KINEMATIC or *DISTRIBUTING
// (docs/constraints.md "Couplings"). The definitions are kept as written; resolve_rigid_bodies
// follows their references and builds the constraints.
#include <fmt/format.h>

#include "parser/block_context.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keywords/constraint_params.hpp"
#include "parser/keywords/keyword_families.hpp"

namespace clinch {
namespace {

// A DOF field 1…6; nullopt after a report (or for an empty field, without one).
std::optional<int> dof_field(BlockContext& ctx, const Field& field, std::string_view what) {
  auto value = ctx.integer(field, what);
  if (!value) return std::nullopt;
  if (*value < 1 || *value > 6) {
    ctx.report(DiagCode::value_out_of_range, field,
               fmt::format("DOF {} is out of range (1-6)", *value));
    return std::nullopt;
  }
  return static_cast<int>(*value);
}

// `first DOF[, last DOF]` from fields[offset…]: the last defaults to the first (the manual's
// data lines of *KINEMATIC COUPLING, *KINEMATIC and *DISTRIBUTING).
std::optional<DofRange> dof_range(BlockContext& ctx, const std::vector<Field>& fields,
                                  std::size_t offset) {
  DofRange range;
  range.loc = fields[offset].loc;
  auto first = dof_field(ctx, fields[offset], "first DOF");
  if (!first) return std::nullopt;
  range.first = range.last = *first;
  if (fields.size() > offset + 1 && !fields[offset + 1].empty()) {
    auto last = dof_field(ctx, fields[offset + 1], "last DOF");
    if (!last) return std::nullopt;
    if (*last < *first) {
      ctx.report(DiagCode::invalid_value, fields[offset + 1],
                 fmt::format("the last DOF {} is below the first DOF {}", *last, *first));
      return std::nullopt;
    }
    range.last = *last;
  }
  return range;
}

void read_orientation(BlockContext& ctx, CouplingDefinition& coupling) {
  if (!ctx.params().has("ORIENTATION")) return;
  coupling.orientation = ctx.name_param("ORIENTATION");
  coupling.orientation_loc = ctx.params().loc("ORIENTATION");
}

// *KINEMATIC COUPLING, REF NODE=: data lines `node or node set, first DOF[, last DOF]`.
class KinematicCouplingHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    CouplingDefinition coupling;
    coupling.kind = CouplingDefinition::Kind::KinematicCoupling;
    coupling.keyword_loc = ctx.keyword().loc;
    coupling.part = ctx.position().part;
    coupling.ref_node = node_param(ctx, "REF NODE");
    if (!coupling.ref_node) return;
    read_orientation(ctx, coupling);
    auto& couplings = ctx.model().constraints.couplings;
    couplings.push_back(std::move(coupling));
    index_ = static_cast<std::int32_t>(couplings.size()) - 1;
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (index_ < 0 || line.blank || fields.empty()) return;
    auto& coupling = ctx.model().constraints.couplings[static_cast<std::size_t>(index_)];
    lines_seen_ = true;
    if (!read_line(ctx, line, fields, coupling)) coupling.refused = true;
  }

  void end(BlockContext& ctx) override {
    if (index_ < 0) return;
    auto& coupling = ctx.model().constraints.couplings[static_cast<std::size_t>(index_)];
    if (!lines_seen_) {
      ctx.report(DiagCode::missing_field, coupling.keyword_loc,
                 "*KINEMATIC COUPLING needs data lines 'node or node set, first DOF, last DOF'");
      coupling.refused = true;
    }
  }

 private:
  static bool read_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields,
                        CouplingDefinition& coupling) {
    if (!ctx.check_field_count(line, fields, 3, "node or node set, first DOF, last DOF")) {
      return false;
    }
    if (fields[0].empty()) {
      ctx.missing(fields[0].loc, "node or node set");
      return false;
    }
    if (fields.size() < 2 || fields[1].empty()) {
      ctx.missing(fields.size() < 2 ? BlockContext::end_of_line(line) : fields[1].loc,
                  "first DOF");
      return false;
    }
    auto target = ctx.target(fields[0], "node");
    if (!target) return false;
    auto range = dof_range(ctx, fields, 1);
    if (!range) return false;
    coupling.node_lines.push_back({*target, *range});
    return true;
  }

  std::int32_t index_ = -1;
  bool lines_seen_ = false;
};

// *COUPLING, CONSTRAINT NAME=, REF NODE=, SURFACE=: the method follows.
class CouplingHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    const ParamSet& params = ctx.params();
    CouplingDefinition coupling;
    coupling.kind = CouplingDefinition::Kind::Kinematic;  // until the method line says
    coupling.keyword_loc = ctx.keyword().loc;
    coupling.part = ctx.position().part;
    if (const Field* name = params.value("CONSTRAINT NAME")) coupling.constraint_name = name->text;
    coupling.ref_node = node_param(ctx, "REF NODE");
    coupling.surface = ctx.name_param("SURFACE");
    if (params.has("INFLUENCE RADIUS")) {
      auto radius = ctx.real_param("INFLUENCE RADIUS");
      if (!radius) return;
      if (*radius <= 0) {
        ctx.report(DiagCode::value_out_of_range, params.loc("INFLUENCE RADIUS", true),
                   fmt::format("INFLUENCE RADIUS must be positive, got {}", *radius));
        return;
      }
      coupling.influence_radius = *radius;
    }
    read_orientation(ctx, coupling);
    if (!coupling.ref_node || !coupling.surface) return;
    ctx.model().constraints.couplings.push_back(std::move(coupling));
  }
};

// The *COUPLING just read (the reader lets the method keyword stand only right after it), or
// nullptr when that *COUPLING line was refused.
CouplingDefinition* open_coupling(BlockContext& ctx) {
  auto& couplings = ctx.model().constraints.couplings;
  if (couplings.empty()) return nullptr;
  CouplingDefinition& last = couplings.back();
  if (last.kind == CouplingDefinition::Kind::KinematicCoupling || last.method_given) {
    return nullptr;
  }
  return &last;
}

// *KINEMATIC and *DISTRIBUTING: data lines `first DOF[, last DOF]` (blank or none: all DOFs).
class CouplingMethodHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    coupling_ = open_coupling(ctx);
    if (!coupling_) return;
    coupling_->method_given = true;
    coupling_->method_loc = ctx.keyword().loc;
    if (ctx.spec().name == "KINEMATIC") {
      coupling_->kind = CouplingDefinition::Kind::Kinematic;
      return;
    }
    coupling_->kind = CouplingDefinition::Kind::Distributing;
    const ParamSet& params = ctx.params();
    // COUPLING=STRUCTURAL also couples the rotations of the coupling nodes (the manual's
    // *DISTRIBUTING); clinch builds the continuum form only.
    if (params.enum_value("COUPLING") == "STRUCTURAL") {
      ctx.report(DiagCode::unsupported_option, params.loc("COUPLING", true),
                 "*DISTRIBUTING, COUPLING=STRUCTURAL is not supported by clinch (it couples the "
                 "rotations of the coupling nodes too); COUPLING=CONTINUUM is");
      ctx.model().constraints.couplings.pop_back();  // the open *COUPLING: nothing to resolve
      coupling_ = nullptr;
      return;
    }
    const std::string_view method = params.enum_value("WEIGHTING METHOD");
    using W = CouplingDefinition::Weighting;
    coupling_->weighting = method == "LINEAR"      ? W::Linear
                           : method == "QUADRATIC" ? W::Quadratic
                           : method == "CUBIC"     ? W::Cubic
                                                   : W::Uniform;
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (!coupling_ || line.blank || fields.empty()) return;
    if (!ctx.check_field_count(line, fields, 2, "first DOF, last DOF")) {
      coupling_->refused = true;
      return;
    }
    if (fields[0].empty()) {
      // A blank first field: every DOF (the manual's *DISTRIBUTING data line).
      coupling_->dof_ranges.push_back({1, 6, fields[0].loc});
      return;
    }
    if (auto range = dof_range(ctx, fields, 0)) {
      coupling_->dof_ranges.push_back(*range);
    } else {
      coupling_->refused = true;
    }
  }

 private:
  CouplingDefinition* coupling_ = nullptr;
};

template <typename H>
std::unique_ptr<KeywordHandler> make() {
  return std::unique_ptr<KeywordHandler>(new H);
}

}  // namespace

std::vector<KeywordSpec> coupling_keyword_specs() {
  constexpr auto kGeometry = KeywordLevel::ModelGeometry;
  std::vector<KeywordSpec> specs(4);
  specs[0].name = "KINEMATIC COUPLING";
  specs[0].level = kGeometry;
  specs[0].params = {{"REF NODE", ParamKind::Value, true}, {"ORIENTATION", ParamKind::Value}};
  specs[0].make_handler = &make<KinematicCouplingHandler>;
  specs[1].name = "COUPLING";
  specs[1].level = kGeometry;
  specs[1].data = DataMode::None;
  specs[1].params = {{"CONSTRAINT NAME", ParamKind::Value, true},
                     {"REF NODE", ParamKind::Value, true},
                     {"SURFACE", ParamKind::Value, true},
                     {"INFLUENCE RADIUS", ParamKind::Value},
                     {"ORIENTATION", ParamKind::Value}};
  specs[1].make_handler = &make<CouplingHandler>;
  specs[2].name = "KINEMATIC";
  specs[2].level = kGeometry;
  specs[2].coupling_suboption = true;
  specs[2].make_handler = &make<CouplingMethodHandler>;
  specs[3].name = "DISTRIBUTING";
  specs[3].level = kGeometry;
  specs[3].coupling_suboption = true;
  specs[3].params = {
      {"COUPLING", ParamKind::Enum, false, {"CONTINUUM", "STRUCTURAL"}},
      {"WEIGHTING METHOD", ParamKind::Enum, false, {"UNIFORM", "LINEAR", "QUADRATIC", "CUBIC"}}};
  specs[3].make_handler = &make<CouplingMethodHandler>;
  return specs;
}

}  // namespace clinch
