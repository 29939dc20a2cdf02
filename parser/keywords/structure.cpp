// The keywords of the meshed model around the connectors (keywords.md): the sections of held
// elements, *MATERIAL and its sub-options, *SURFACE and *DISPLAY BODY. They are read and kept in
// StructureModel with their numbers validated; resolve_structure follows their references.
#include <fmt/format.h>

#include <array>

#include "parser/block_context.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keywords/geometry_common.hpp"
#include "parser/keywords/keyword_families.hpp"

namespace clinch {
namespace {

// Every field of a data line as a number (an empty field is 0, not given); nullopt after a
// reported field.
std::optional<NumberRow> number_row(BlockContext& ctx, const DataLine& line,
                                    const std::vector<Field>& fields, std::string_view what) {
  NumberRow row;
  row.loc = line.loc;
  for (const Field& field : fields) {
    if (field.empty()) {
      row.values.push_back(0.0);
      row.given.push_back(false);
      continue;
    }
    auto value = ctx.real(field, what);
    if (!value) return std::nullopt;
    row.values.push_back(*value);
    row.given.push_back(true);
  }
  return row;
}

// The parameters of the keyword line except those the handler reads itself.
std::vector<KeptParameter> kept_parameters(BlockContext& ctx,
                                           std::initializer_list<std::string_view> skip) {
  std::vector<KeptParameter> kept;
  for (const ParamSet::Entry& entry : ctx.params().entries()) {
    bool skipped = false;
    for (std::string_view name : skip) skipped = skipped || entry.spec->name == name;
    if (skipped) continue;
    const Field* value = ctx.params().value(entry.spec->name);
    kept.push_back({std::string(entry.spec->name),
                    !entry.enum_value.empty() ? entry.enum_value
                                              : (value ? value->text : std::string())});
  }
  return kept;
}

// ---------------------------------------------------------------------------------------------
// Sections of held elements

struct SectionKind {
  std::string_view keyword;
  ElementSection::Kind kind;
  bool needs_material;
};
constexpr SectionKind kSectionKinds[] = {
    {"SOLID SECTION", ElementSection::Kind::Solid, true},
    {"SHELL SECTION", ElementSection::Kind::Shell, true},
    {"MEMBRANE SECTION", ElementSection::Kind::Membrane, true},
    {"BEAM SECTION", ElementSection::Kind::Beam, true},
    {"TRUSS SECTION", ElementSection::Kind::Truss, true},
    {"MASS", ElementSection::Kind::Mass, false},
    {"ROTARY INERTIA", ElementSection::Kind::RotaryInertia, false},
};

class ElementSectionHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    const SectionKind* kind = nullptr;
    for (const SectionKind& k : kSectionKinds) {
      if (k.keyword == ctx.spec().name) kind = &k;
    }
    auto elset = elset_param(ctx);
    if (!kind || !elset) return;
    ElementSection section;
    section.kind = kind->kind;
    section.keyword = std::string(kind->keyword);
    section.keyword_loc = ctx.keyword().loc;
    section.elset = *elset;
    if (kind->needs_material) {
      if (auto material = ctx.name_param("MATERIAL")) section.material = *material;
    }
    section.parameters = kept_parameters(ctx, {"ELSET", "MATERIAL"});
    auto& sections = ctx.model().structure.sections;
    sections.push_back(std::move(section));
    section_ = &sections.back();
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (!section_ || line.blank) return;
    if (auto row = number_row(ctx, line, fields, "section property")) {
      section_->rows.push_back(std::move(*row));
    }
  }

 private:
  ElementSection* section_ = nullptr;
};

// ---------------------------------------------------------------------------------------------
// *MATERIAL and its sub-options

class MaterialHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    auto name = ctx.name_param("NAME");
    if (!name) return;
    StructureModel& structure = ctx.model().structure;
    auto [it, inserted] = structure.material_by_key.try_emplace(
        name->key, static_cast<std::int32_t>(structure.materials.size()));
    if (!inserted) {
      ctx.report(DiagCode::duplicate_name, name->loc,
                 fmt::format("material '{}' is already defined", name->display))
          .notes.push_back({structure.materials[static_cast<std::size_t>(it->second)].keyword_loc,
                            "previous definition is here"});
    }
    Material material;
    material.name = *name;
    material.keyword_loc = ctx.keyword().loc;
    structure.materials.push_back(std::move(material));
  }
};

// A sub-option: kept on the material it follows (the reader checks that one is open).
class MaterialOptionHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    auto& materials = ctx.model().structure.materials;
    if (materials.empty()) return;  // the *MATERIAL line was refused: reported there
    MaterialOption option;
    option.keyword = std::string(ctx.spec().name);
    option.loc = ctx.keyword().loc;
    option.parameters = kept_parameters(ctx, {});
    materials.back().options.push_back(std::move(option));
    option_ = &materials.back().options.back();
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (!option_ || line.blank) return;
    if (auto row = number_row(ctx, line, fields, "material property")) {
      option_->rows.push_back(std::move(*row));
    }
  }

 private:
  MaterialOption* option_ = nullptr;
};

// ---------------------------------------------------------------------------------------------
// *SURFACE

constexpr std::array<std::string_view, 8> kFaces{"S1", "S2", "S3",   "S4",
                                                 "S5", "S6", "SPOS", "SNEG"};

class SurfaceHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    const std::string_view type = ctx.params().enum_value("TYPE");
    if (!type.empty() && type != "ELEMENT" && type != "NODE") {
      ctx.report(DiagCode::unsupported_option, ctx.params().loc("TYPE", true),
                 fmt::format("*SURFACE, TYPE={} is not supported by clinch (TYPE=ELEMENT and "
                             "TYPE=NODE are read)",
                             type));
      return;
    }
    auto name = ctx.name_param("NAME");
    if (!name) return;
    StructureModel& structure = ctx.model().structure;
    const std::int32_t part = ctx.position().part;
    auto [it, inserted] = structure.surface_by_key.try_emplace(
        scoped_name_key(part, name->key), static_cast<std::int32_t>(structure.surfaces.size()));
    if (!inserted) {
      ctx.report(DiagCode::duplicate_name, name->loc,
                 fmt::format("surface '{}' is already defined", name->display))
          .notes.push_back({structure.surfaces[static_cast<std::size_t>(it->second)].keyword_loc,
                            "previous definition is here"});
      return;
    }
    Surface surface;
    surface.name = *name;
    surface.keyword_loc = ctx.keyword().loc;
    surface.part = part;
    surface.type = type == "NODE" ? Surface::Type::Node : Surface::Type::Element;
    structure.surfaces.push_back(std::move(surface));
    surface_ = &structure.surfaces.back();
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (!surface_ || line.blank || fields.empty()) return;
    const bool nodes = surface_->type == Surface::Type::Node;
    if (!ctx.check_field_count(line, fields, 2,
                               nodes ? "node or node set, area" : "element or element set, face")) {
      return;
    }
    if (fields[0].empty()) {
      ctx.missing(fields[0].loc, nodes ? "node or node set" : "element or element set");
      return;
    }
    auto target = ctx.target(fields[0], nodes ? "node" : "element");
    if (!target) return;
    Surface::Item item;
    item.target = *target;
    if (fields.size() > 1 && !fields[1].empty()) {
      if (nodes) {
        auto area = ctx.real(fields[1], "area");
        if (!area) return;
        item.area = *area;
      } else {
        auto face = ctx.word(fields[1], kFaces, "face identifier");
        if (!face) return;
        item.face = *face;
      }
    }
    surface_->items.push_back(std::move(item));
  }

 private:
  Surface* surface_ = nullptr;
};

// ---------------------------------------------------------------------------------------------
// *DISPLAY BODY

class DisplayBodyHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    auto instance = ctx.name_param("INSTANCE");
    if (!instance) return;
    DisplayBody body;
    body.keyword_loc = ctx.keyword().loc;
    body.instance = *instance;
    auto& bodies = ctx.model().structure.display_bodies;
    bodies.push_back(std::move(body));
    body_ = &bodies.back();
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (!body_ || line.blank || fields.empty()) return;
    if (ctx.line_index() > 1) {
      ctx.report(DiagCode::unexpected_data_line, line.loc,
                 "*DISPLAY BODY has one data line (up to three reference nodes)");
      return;
    }
    if (!ctx.check_field_count(line, fields, 3, "node 1, node 2, node 3")) return;
    for (const Field& field : fields) {
      if (field.empty()) continue;
      auto ref = ctx.label_ref(field, "node");
      if (!ref) return;
      ref->part = ctx.position().part;
      body_->reference_nodes.push_back(*ref);
    }
  }

 private:
  DisplayBody* body_ = nullptr;
};

template <typename H>
std::unique_ptr<KeywordHandler> make() {
  return std::unique_ptr<KeywordHandler>(new H);
}

KeywordSpec spec_of(std::string_view name, KeywordLevel level, std::vector<ParamSpec> params,
                    std::unique_ptr<KeywordHandler> (*handler)()) {
  KeywordSpec spec;
  spec.name = name;
  spec.level = level;
  spec.params = std::move(params);
  spec.make_handler = handler;
  return spec;
}

KeywordSpec material_option(std::string_view name, std::vector<ParamSpec> params) {
  KeywordSpec spec = spec_of(name, KeywordLevel::Model, std::move(params),
                             &make<MaterialOptionHandler>);
  spec.material_suboption = true;
  return spec;
}

}  // namespace

std::vector<KeywordSpec> structure_keyword_specs() {
  constexpr auto kGeometry = KeywordLevel::ModelGeometry;
  const ParamSpec elset{"ELSET", ParamKind::Value, true};
  const ParamSpec material{"MATERIAL", ParamKind::Value, true};
  const ParamSpec orientation{"ORIENTATION", ParamKind::Value};
  const ParamSpec controls{"CONTROLS", ParamKind::Value};
  const ParamSpec dependencies{"DEPENDENCIES", ParamKind::Value};
  std::vector<KeywordSpec> specs;
  auto section = [&](std::string_view name, std::vector<ParamSpec> params) {
    specs.push_back(spec_of(name, kGeometry, std::move(params), &make<ElementSectionHandler>));
  };
  section("SOLID SECTION", {elset, material, orientation, controls,
                            {"COMPOSITE", ParamKind::Flag},
                            {"STACK DIRECTION", ParamKind::Value},
                            {"REF NODE", ParamKind::Value}});
  section("SHELL SECTION", {elset, material, orientation, controls,
                            {"OFFSET", ParamKind::Value},
                            {"SECTION INTEGRATION", ParamKind::Enum, false, {"SIMPSON", "GAUSS"}},
                            {"COMPOSITE", ParamKind::Flag},
                            {"LAYUP", ParamKind::Value},
                            {"NODAL THICKNESS", ParamKind::Flag},
                            {"POISSON", ParamKind::Value},
                            {"DENSITY", ParamKind::Value},
                            {"SHELL THICKNESS", ParamKind::Value},
                            {"STACK DIRECTION", ParamKind::Value},
                            {"SYMMETRIC", ParamKind::Flag},
                            {"TEMPERATURE", ParamKind::Value}});
  section("MEMBRANE SECTION", {elset, material, orientation, controls,
                               {"DENSITY", ParamKind::Value},
                               {"NODAL THICKNESS", ParamKind::Flag},
                               {"POISSON", ParamKind::Value}});
  section("BEAM SECTION",
          {elset, material,
           {"SECTION", ParamKind::Enum, true,
            {"ARBITRARY", "BOX", "CIRC", "ELBOW", "HEX", "I", "L", "PIPE", "RECT", "THICK PIPE",
             "TRAPEZOID"}},
           {"POISSON", ParamKind::Value},
           {"TEMPERATURE", ParamKind::Enum, false, {"GRADIENTS", "VALUES"}},
           {"ROTARY INERTIA", ParamKind::Enum, false, {"EXACT", "ISOTROPIC"}},
           {"LUMPED", ParamKind::FlagOrYesNo}});
  section("TRUSS SECTION", {elset, material});
  section("MASS", {elset,
                   {"ALPHA", ParamKind::Value},
                   {"TYPE", ParamKind::Enum, false, {"ISOTROPIC", "ANISOTROPIC"}},
                   {"ORIENTATION", ParamKind::Value}});
  section("ROTARY INERTIA", {elset,
                             {"ALPHA", ParamKind::Value},
                             {"ORIENTATION", ParamKind::Value},
                             {"COMPOSITE", ParamKind::Value}});

  specs.push_back(spec_of("MATERIAL", KeywordLevel::Model, {{"NAME", ParamKind::Value, true}},
                          &make<MaterialHandler>));
  specs.back().data = DataMode::None;
  specs.push_back(material_option(
      "ELASTIC", {{"TYPE", ParamKind::Enum, false,
                   {"ISOTROPIC", "ENGINEERING CONSTANTS", "LAMINA", "ORTHOTROPIC", "ANISOTROPIC",
                    "TRACTION", "SHEAR"}},
                  dependencies,
                  {"MODULI", ParamKind::Value}}));
  specs.push_back(material_option("DENSITY", {dependencies}));
  specs.push_back(material_option(
      "PLASTIC", {{"HARDENING", ParamKind::Enum, false,
                   {"ISOTROPIC", "KINEMATIC", "COMBINED", "JOHNSON COOK", "USER"}},
                  dependencies,
                  {"RATE", ParamKind::Value}}));
  specs.push_back(material_option(
      "EXPANSION", {{"TYPE", ParamKind::Enum, false, {"ISO", "ORTHO", "ANISO", "SHORT FIBER"}},
                    {"ZERO", ParamKind::Value},
                    dependencies}));
  specs.push_back(material_option("DAMPING", {{"ALPHA", ParamKind::Value},
                                              {"BETA", ParamKind::Value},
                                              {"COMPOSITE", ParamKind::Value},
                                              {"STRUCTURAL", ParamKind::Value}}));
  specs.back().data = DataMode::None;
  specs.push_back(material_option(
      "CONDUCTIVITY", {{"TYPE", ParamKind::Enum, false, {"ISO", "ORTHO", "ANISO"}},
                       dependencies}));
  specs.push_back(material_option("SPECIFIC HEAT", {dependencies}));

  specs.push_back(spec_of("SURFACE", kGeometry,
                          {{"NAME", ParamKind::Value, true},
                           {"TYPE", ParamKind::Enum, false,
                            {"ELEMENT", "NODE", "SEGMENTS", "CYLINDER", "REVOLUTION",
                             "CUTTING SURFACE", "EULERIAN MATERIAL"}},
                           {"INTERNAL", ParamKind::Flag}},
                          &make<SurfaceHandler>));
  specs.push_back(spec_of("DISPLAY BODY", kGeometry,
                          {{"INSTANCE", ParamKind::Value, true}}, &make<DisplayBodyHandler>));
  return specs;
}

}  // namespace clinch
