// *PART, *ASSEMBLY, *INSTANCE and their ends (input-syntax.md §7.2). The deck reader tracks the
// structural position (parser/reader/deck_structure.hpp); these handlers create the parts and
// instances and read the placement.
#include <cmath>

#include <fmt/format.h>

#include "parser/block_context.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keywords/geometry_common.hpp"
#include "base/suggest.hpp"

namespace clinch {
namespace {

// Rotation by `angle` (radians) about the unit axis n (right-hand rule): Rodrigues' formula.
Mat3 axis_rotation(const Vec3& n, double angle) {
  const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
  return {{{t * n[0] * n[0] + c, t * n[0] * n[1] - s * n[2], t * n[0] * n[2] + s * n[1]},
           {t * n[0] * n[1] + s * n[2], t * n[1] * n[1] + c, t * n[1] * n[2] - s * n[0]},
           {t * n[0] * n[2] - s * n[1], t * n[1] * n[2] + s * n[0], t * n[2] * n[2] + c}}};
}

class InstanceHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    Model& model = ctx.model();
    for (const char* unsupported : {"LIBRARY", "INSTANCE"}) {
      if (ctx.params().has(unsupported)) {
        ctx.report(DiagCode::unsupported_option, ctx.params().loc(unsupported),
                   fmt::format("*INSTANCE with {}= is not supported by clinch", unsupported));
        return;
      }
    }
    auto name = ctx.name(*ctx.params().value("NAME"), "NAME");
    auto part = ctx.name(*ctx.params().value("PART"), "PART");
    if (!name || !part) return;
    auto part_it = model.part_by_key.find(part->key);
    if (part_it == model.part_by_key.end()) {
      Diagnostic& d = ctx.report(DiagCode::undefined_instance, *ctx.params().value("PART"),
                                 fmt::format("part '{}' is not defined", part->display));
      std::vector<std::string> names;
      for (const auto& p : model.parts) {
        if (!p.name.empty()) names.push_back(p.name.display);
      }
      if (auto guess = closest_match_of(part->display, names)) {
        d.notes.push_back({part->loc, fmt::format("did you mean '{}'?", *guess)});
      }
      return;
    }
    auto [it, inserted] = model.instance_by_key.try_emplace(
        name->key, static_cast<std::int32_t>(model.instances.size()));
    if (!inserted) {
      ctx.report(DiagCode::duplicate_name, *ctx.params().value("NAME"),
                 fmt::format("instance '{}' is already defined", name->display))
          .notes.push_back({model.instances[it->second].loc, "previous definition is here"});
      return;
    }
    Instance instance;
    instance.name = *name;
    instance.loc = ctx.keyword().loc;
    instance.part = part_it->second;
    model.instances.push_back(instance);
    instance_ = static_cast<std::int32_t>(model.instances.size() - 1);
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (instance_ < 0) return;
    Instance& instance = ctx.model().instances[instance_];
    const std::uint32_t index = ctx.line_index();
    if (index == 1) {
      if (!ctx.check_field_count(line, fields, 3, "tx, ty, tz")) return;
      for (std::size_t k = 0; k < fields.size(); ++k) {
        if (auto v = ctx.real(fields[k], "translation")) instance.translation[k] = *v;
      }
      return;
    }
    if (index == 2) {
      if (!ctx.check_field_count(line, fields, 7, "ax, ay, az, bx, by, bz, angle")) return;
      double v[7] = {0, 0, 0, 0, 0, 0, 0};
      for (std::size_t k = 0; k < fields.size(); ++k) {
        if (auto value = ctx.real(fields[k], "rotation")) v[k] = *value;
      }
      Vec3 a{v[0], v[1], v[2]}, b{v[3], v[4], v[5]};
      Vec3 axis{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
      const double length = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
      if (length == 0.0) {
        if (v[6] != 0.0) {
          ctx.report(DiagCode::value_out_of_range, fields.empty() ? Field{} : fields[0],
                     "rotation axis points a and b coincide but the angle is not zero");
        }
        return;
      }
      for (double& c : axis) c /= length;
      instance.axis_point = a;
      instance.rotation = axis_rotation(axis, v[6] * M_PI / 180.0);
      return;
    }
    ctx.report(DiagCode::unexpected_data_line, line.loc,
               "*INSTANCE takes at most two data lines (translation, rotation)");
  }

 private:
  static std::optional<std::string> closest_match_of(const std::string& name,
                                                     const std::vector<std::string>& names);
  std::int32_t instance_ = -1;
};

std::optional<std::string> InstanceHandler::closest_match_of(
    const std::string& name, const std::vector<std::string>& names) {
  std::optional<std::string> best;
  std::size_t best_distance = 3;
  for (const std::string& n : names) {
    std::size_t d = folded_edit_distance(name, n);
    if (d < best_distance) {
      best_distance = d;
      best = n;
    }
  }
  return best;
}

KeywordSpec block(std::string_view name, std::vector<ParamSpec> params = {}) {
  KeywordSpec spec;
  spec.name = name;
  spec.level = KeywordLevel::Block;
  spec.data = DataMode::None;
  spec.params = std::move(params);
  return spec;
}

}  // namespace

std::vector<KeywordSpec> part_assembly_keyword_specs() {
  std::vector<KeywordSpec> specs;
  specs.push_back(block("PART", {{"NAME", ParamKind::Value, true}}));
  specs.push_back(block("END PART"));
  specs.push_back(block("ASSEMBLY", {{"NAME", ParamKind::Value, true}}));
  specs.push_back(block("END ASSEMBLY"));
  KeywordSpec instance = block("INSTANCE", {{"NAME", ParamKind::Value, true},
                                            {"PART", ParamKind::Value, true},
                                            {"LIBRARY", ParamKind::Value},
                                            {"INSTANCE", ParamKind::Value}});
  instance.data = DataMode::Fields;
  instance.make_handler = [] { return std::unique_ptr<KeywordHandler>(new InstanceHandler); };
  specs.push_back(std::move(instance));
  specs.push_back(block("END INSTANCE"));
  return specs;
}

std::vector<KeywordSpec> geometry_keyword_specs() {
  std::vector<KeywordSpec> specs = part_assembly_keyword_specs();
  specs.push_back(node_keyword_spec());
  specs.push_back(element_keyword_spec());
  specs.push_back(nset_keyword_spec());
  specs.push_back(elset_keyword_spec());
  return specs;
}

}  // namespace clinch
