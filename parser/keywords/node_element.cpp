// *NODE and *ELEMENT (keywords.md §2–§3): the bulk of large decks, so the handlers avoid any
// per-line allocation beyond the fields the lexer already made.
#include <algorithm>

#include <fmt/format.h>

#include "parser/block_context.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keywords/geometry_common.hpp"
#include "src/model/element_library.hpp"

namespace clinch {
namespace {

// Room for `lines` more entries, sized once for a block's lines; growth stays geometric, so that
// many small blocks do not reallocate each time.
template <typename T>
void reserve_for_block(std::vector<T>& v, std::size_t lines) {
  if (v.size() + lines > v.capacity()) v.reserve(std::max(v.size() + lines, 2 * v.capacity()));
}

// A node or element label 1…2147483647 in the first field of a line; nullopt after a report.
std::optional<std::int32_t> line_label(BlockContext& ctx, const Field& field,
                                       std::string_view field_name) {
  if (field.empty()) {
    ctx.missing(field.loc, field_name);
    return std::nullopt;
  }
  auto label = ctx.integer(field, field_name);
  if (!label) return std::nullopt;
  if (*label < 1 || *label > 2147483647) {
    ctx.report(DiagCode::value_out_of_range, field,
               fmt::format("{} {} is out of range (1-2147483647)", field_name, *label));
    return std::nullopt;
  }
  return static_cast<std::int32_t>(*label);
}

class NodeHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    part_ = &ctx.model().parts[ctx.position().part];
    reserve_for_block(part_->nodes, ctx.expected_lines());
    if (auto system = ctx.params().enum_value("SYSTEM"); !system.empty() && system != "R") {
      ctx.report(DiagCode::unsupported_option, ctx.params().loc("SYSTEM", true),
                 fmt::format("SYSTEM={} is not supported by clinch (only R)", system));
    }
    if (const Field* nset = ctx.params().value("NSET")) {
      if (auto name = ctx.name(*nset, "NSET")) set_ = &define_set(*part_, false, *name);
    }
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (line.blank || fields.empty()) return;
    if (fields.size() > 7) {
      ctx.check_field_count(line, fields, 7, "label, x, y, z, nx, ny, nz");
      return;
    }
    auto label = line_label(ctx, fields[0], "node label");
    if (!label) return;
    Node node;
    node.label = *label;
    node.line = line.loc.line;
    node.file = line.loc.file;
    for (std::size_t k = 1; k < fields.size() && k < 4; ++k) {
      if (fields[k].empty()) continue;
      auto value = ctx.real(fields[k], "coordinate");
      if (!value) return;
      node.x[k - 1] = *value;
    }
    if (fields.size() > 4 && !normal_warned_) {
      normal_warned_ = true;
      ctx.report(DiagCode::parameter_ignored, fields[4],
                 "node normal directions (fields 5-7) are ignored by clinch");
    }
    const auto index = static_cast<std::int32_t>(part_->nodes.size());
    const std::int32_t existing = part_->node_index.insert(node.label, index);
    if (existing != LabelIndex::kMissing) {
      ctx.report(DiagCode::duplicate_node, fields[0],
                 fmt::format("node {} is already defined", node.label))
          .notes.push_back({part_->nodes[existing].loc(), "previous definition is here"});
      return;
    }
    part_->nodes.push_back(node);
    if (set_) set_->members.push_back(index);
  }

 private:
  Part* part_ = nullptr;
  Set* set_ = nullptr;
  bool normal_warned_ = false;
};

// Element types other codes know that clinch does not (E0210 rather than E0208): the families of
// the Abaqus and CalculiX libraries beyond element_library.hpp (cohesive, gasket, heat transfer,
// acoustic, infinite, fluid, user elements, and other variants of the listed families).
constexpr std::string_view kKnownUnsupportedPrefixes[] = {
    "C3D", "C2D", "CPE", "CPS", "CAX", "CGAX", "CCL", "S3", "S4", "S8", "S9", "SAX", "STRI",
    "SC", "SFM", "B2", "B3", "PIPE", "ELBOW", "FRAME", "T2D", "T3D", "TAX", "M3D", "MAX", "MGAX",
    "MASS", "ROTARYI", "HEATCAP", "GAP", "ITS", "ISL", "DASHPOT", "SPRING", "CONN", "JOINT",
    "DCOUP", "KCOUP", "R3D", "R2D", "RAX", "RB", "COH", "GK", "DC", "DS", "AC", "CIN", "ACIN",
    "F2D", "F3D", "FAX", "FC3D", "WARP", "PSI", "EMC", "Q3D", "U", "VU"};

// An element line holds at most 16 entries; an element with more nodes goes on over the
// following lines, each full line ending with a comma (Abaqus Analysis User's Guide, "Element
// definition"; Abaqus/CAE writes a C3D20 as 16 fields and a line of 5).
constexpr std::size_t kEntriesPerLine = 16;

class ElementHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    part_ = &ctx.model().parts[ctx.position().part];
    part_index_ = ctx.position().part;
    reserve_for_block(part_->elements, ctx.expected_lines());
    const Field* type = ctx.params().value("TYPE");
    if (!type) return;
    std::string folded = fold_name(type->text);
    info_ = find_element_type(folded);
    if (!info_) {
      bool known = false;
      for (std::string_view prefix : kKnownUnsupportedPrefixes) {
        if (folded.rfind(prefix, 0) == 0) known = true;
      }
      ctx.report(known ? DiagCode::unsupported_option : DiagCode::invalid_value, *type,
                 fmt::format("element type '{}' is {} (analysed: CONN3D2, CONN2D2, SPRINGA, "
                             "SPRING1, SPRING2, DASHPOTA, DASHPOT1, DASHPOT2; read as nodes: "
                             "the solids, shells, membranes, rigid elements, beams, trusses, "
                             "planar continua and point masses of docs/keywords.md)",
                             type->text, known ? "not supported by clinch" : "unknown"));
      // The set still exists, as a failed definition: references to it stay silent (§10: a
      // diagnostic that follows only from an earlier error is not reported).
      if (const Field* elset = ctx.params().value("ELSET")) {
        if (auto name = ctx.name(*elset, "ELSET")) define_set(*part_, true, *name).defined_ok = false;
      }
      return;
    }
    if (const Field* elset = ctx.params().value("ELSET")) {
      if (auto name = ctx.name(*elset, "ELSET")) set_ = &define_set(*part_, true, *name);
    }
    if (info_->type == ElementType::Held) {
      ElementBlock block;
      block.type = std::string(info_->name);
      block.family = static_cast<std::uint8_t>(info_->family);
      block.nodes_per_element = info_->nodes;
      block.keyword_loc = ctx.keyword().loc;
      block.type_loc = type->loc;
      block.first_element = static_cast<std::int32_t>(part_->elements.size());
      part_->element_blocks.push_back(std::move(block));
    }
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (!info_ || line.blank || fields.empty()) return;
    if (info_->type == ElementType::Held) {
      held_line(ctx, line, fields);
      return;
    }
    const int max_fields = 1 + info_->nodes;
    if (static_cast<int>(fields.size()) > max_fields) {
      ctx.check_field_count(line, fields, max_fields,
                            info_->nodes == 1 ? "label, node" : "label, node a, node b");
      return;
    }
    auto label = line_label(ctx, fields[0], "element label");
    if (!label) return;
    Element element;
    element.label = *label;
    element.type = info_->type;
    element.line = line.loc.line;
    element.file = line.loc.file;
    element.keyword_line = ctx.keyword().loc.line;
    const auto index = static_cast<std::int32_t>(part_->elements.size());
    bool ok = true;
    // Qualified node fields are kept aside until the element is accepted.
    std::vector<Part::QualifiedNode> qualified;
    for (int slot = 0; slot < info_->nodes; ++slot) {
      const std::size_t k = static_cast<std::size_t>(slot) + 1;
      if (k >= fields.size() || fields[k].empty()) {
        element.nodes[slot] = kGround;
        continue;
      }
      auto ref = ctx.label_ref(fields[k], "node");
      if (!ref) {
        ok = false;
        continue;
      }
      element.node_columns[slot] = static_cast<std::uint16_t>(
          std::min<std::uint32_t>(fields[k].loc.column, 65535));
      if (!ref->instance_key.empty()) {
        if (part_index_ != 0) {
          ctx.report(DiagCode::expected_integer, fields[k],
                     "instance-qualified node labels are allowed only at assembly level");
          ok = false;
          continue;
        }
        qualified.push_back({index, slot, ref->instance_key, ref->instance_display, ref->label,
                             fields[k].loc});
        element.nodes[slot] = 0;
      } else {
        element.nodes[slot] = ref->label;  // a label until resolve_geometry resolves it
      }
    }
    if (!ok) return;
    if (!check_ends(ctx, line, fields, element)) return;
    if (!add_element(ctx, fields[0], element)) return;
    for (Part::QualifiedNode& q : qualified) part_->qualified_nodes.push_back(std::move(q));
    if (set_) set_->members.push_back(index);
  }

  void end(BlockContext& ctx) override {
    if (!pending_.empty()) {
      ctx.missing(pending_end_, fmt::format("node {} of {} element {} (the element's line ends "
                                            "with a comma but no line follows)",
                                            pending_.size(), info_->name, pending_[0].text));
    }
  }

 private:
  // Appends `element` at the next index unless its label is taken (E0510 at `label_field`).
  bool add_element(BlockContext& ctx, const Field& label_field, const Element& element) {
    const auto index = static_cast<std::int32_t>(part_->elements.size());
    const std::int32_t existing = part_->element_index.insert(element.label, index);
    if (existing != LabelIndex::kMissing) {
      ctx.report(DiagCode::duplicate_element, label_field,
                 fmt::format("element {} is already defined", element.label))
          .notes.push_back({part_->elements[existing].loc(), "previous definition is here"});
      return false;
    }
    part_->elements.push_back(element);
    return true;
  }

  // A line of a held element, or the continuation of one (kEntriesPerLine).
  void held_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    const std::size_t needed = 1 + static_cast<std::size_t>(info_->nodes);
    const bool continues = line.text.find_last_not_of(" \t") != std::string_view::npos &&
                           line.text[line.text.find_last_not_of(" \t")] == ',';
    for (Field& f : fields) pending_.push_back(std::move(f));
    if (pending_.size() < needed && (continues || fields.size() == kEntriesPerLine)) {
      pending_end_ = BlockContext::end_of_line(line);
      return;
    }
    std::vector<Field> element_fields = std::move(pending_);
    pending_.clear();
    if (element_fields.size() > needed) {
      ctx.report(DiagCode::too_many_fields, element_fields[needed],
                 fmt::format("{} element has {} nodes; this line gives {} (expected: label, "
                             "then {} node labels)",
                             info_->name, info_->nodes, element_fields.size() - 1, info_->nodes));
      return;
    }
    add_held_element(ctx, line, element_fields);
  }

  void add_held_element(BlockContext& ctx, const DataLine& line, const std::vector<Field>& fields) {
    const std::size_t needed = 1 + static_cast<std::size_t>(info_->nodes);
    auto label = line_label(ctx, fields[0], "element label");
    if (!label) return;
    if (fields.size() < needed) {
      ctx.report(DiagCode::missing_field, BlockContext::end_of_line(line),
                 fmt::format("{} element {} has {} nodes; {} given (a line that goes on to "
                             "the next ends with a comma)",
                             info_->name, *label, info_->nodes, fields.size() - 1));
      return;
    }
    ElementBlock& block = part_->element_blocks.back();
    std::vector<std::int32_t> nodes(static_cast<std::size_t>(info_->nodes));
    std::vector<ElementBlock::QualifiedNode> qualified;
    const auto base = static_cast<std::int32_t>(block.nodes.size());
    for (std::size_t k = 1; k < needed; ++k) {
      if (fields[k].empty()) {
        ctx.missing(fields[k].loc, fmt::format("node {}", k));
        return;
      }
      auto ref = ctx.label_ref(fields[k], "node");
      if (!ref) return;
      if (!ref->instance_key.empty()) {
        if (part_index_ != 0) {
          ctx.report(DiagCode::expected_integer, fields[k],
                     "instance-qualified node labels are allowed only at assembly level");
          return;
        }
        qualified.push_back({base + static_cast<std::int32_t>(k - 1), ref->instance_key,
                             ref->instance_display, ref->label});
        nodes[k - 1] = kGround;
      } else {
        nodes[k - 1] = ref->label;  // a label until resolve_geometry resolves it
      }
    }
    Element element;
    element.label = *label;
    element.type = ElementType::Held;
    element.line = fields[0].loc.line;
    element.file = fields[0].loc.file;
    element.keyword_line = ctx.keyword().loc.line;
    const auto index = static_cast<std::int32_t>(part_->elements.size());
    if (!add_element(ctx, fields[0], element)) return;
    block.nodes.insert(block.nodes.end(), nodes.begin(), nodes.end());
    for (std::size_t k = 1; k < needed; ++k) block.node_locs.push_back(fields[k].loc);
    for (auto& q : qualified) block.qualified.push_back(std::move(q));
    ++block.count;
    if (set_) set_->members.push_back(index);
  }

  // Ground and same-node rules (keywords.md §3).
  bool check_ends(BlockContext& ctx, const DataLine& line, const std::vector<Field>& fields,
                  const Element& element) {
    const bool a_missing = element.nodes[0] == kGround;
    const bool b_missing = info_->nodes > 1 && element.nodes[1] == kGround;
    if (is_connector(element.type)) {
      if (a_missing && b_missing) {
        ctx.missing(fields.size() > 1 ? fields[1].loc : BlockContext::end_of_line(line),
                    "node a or node b (a connector needs at least one node)");
        return false;
      }
    } else if (a_missing || b_missing) {
      const std::size_t k = a_missing ? 1 : 2;
      ctx.missing(k < fields.size() ? fields[k].loc : BlockContext::end_of_line(line),
                  a_missing ? "node 1" : "node 2");
      return false;
    }
    const bool qualified_a = element.node_columns[0] && fields.size() > 1 &&
                             fields[1].text.find('.') != std::string::npos;
    if (info_->nodes == 2 && !a_missing && !b_missing && !qualified_a &&
        element.nodes[0] == element.nodes[1] && fields[1].text == fields[2].text) {
      if (is_connector(element.type)) {
        ctx.report(DiagCode::connector_same_node, fields[2],
                   fmt::format("connector element {} has the same node {} at both ends",
                               element.label, fields[1].text));
        return false;
      }
      if (spring_form(element.type) == ElementType::SpringA) {
        ctx.report(DiagCode::degenerate_geometry, fields[2],
                   fmt::format("{} element {} joins node {} to itself; its direction is "
                               "undefined", info_->name, element.label, fields[1].text));
        return false;
      }
    }
    return true;
  }

  Part* part_ = nullptr;
  std::int32_t part_index_ = 0;
  const ElementTypeInfo* info_ = nullptr;
  Set* set_ = nullptr;
  std::vector<Field> pending_;  // fields of a held element whose line goes on
  SourceLoc pending_end_;
};

}  // namespace

KeywordSpec node_keyword_spec() {
  KeywordSpec spec;
  spec.name = "NODE";
  spec.level = KeywordLevel::ModelGeometry;
  spec.params = {{"NSET", ParamKind::Value}, {"SYSTEM", ParamKind::Enum, false, {"R", "C", "S"}}};
  spec.make_handler = [] { return std::unique_ptr<KeywordHandler>(new NodeHandler); };
  return spec;
}

KeywordSpec element_keyword_spec() {
  KeywordSpec spec;
  spec.name = "ELEMENT";
  spec.level = KeywordLevel::ModelGeometry;
  spec.params = {{"TYPE", ParamKind::Value, true}, {"ELSET", ParamKind::Value}};
  spec.make_handler = [] { return std::unique_ptr<KeywordHandler>(new ElementHandler); };
  return spec;
}

}  // namespace clinch
