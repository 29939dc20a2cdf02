// *NODE and *ELEMENT (keywords.md §2–§3): the bulk of large decks, so the handlers avoid any
// per-line allocation beyond the fields the lexer already made.
#include <algorithm>

#include <fmt/format.h>

#include "parser/block_context.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keywords/geometry_common.hpp"

namespace clinch {
namespace {

// Room for `lines` more entries, sized once for a block's lines; growth stays geometric, so that
// many small blocks do not reallocate each time.
template <typename T>
void reserve_for_block(std::vector<T>& v, std::size_t lines) {
  if (v.size() + lines > v.capacity()) v.reserve(std::max(v.size() + lines, 2 * v.capacity()));
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
    if (fields[0].empty()) {
      ctx.missing(fields[0].loc, "node label");
      return;
    }
    auto label = ctx.integer(fields[0], "node label");
    if (!label) return;
    if (*label < 1 || *label > 2147483647) {
      ctx.report(DiagCode::value_out_of_range, fields[0],
                 fmt::format("node label {} is out of range (1-2147483647)", *label));
      return;
    }
    Node node;
    node.label = static_cast<std::int32_t>(*label);
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

struct ElementTypeInfo {
  std::string_view name;
  ElementType type;
  int nodes;
};
constexpr ElementTypeInfo kElementTypes[] = {
    {"CONN3D2", ElementType::Conn3D2, 2}, {"CONN2D2", ElementType::Conn2D2, 2},
    {"SPRINGA", ElementType::SpringA, 2}, {"SPRING1", ElementType::Spring1, 1},
    {"SPRING2", ElementType::Spring2, 2}, {"DASHPOTA", ElementType::DashpotA, 2},
    {"DASHPOT1", ElementType::Dashpot1, 1}, {"DASHPOT2", ElementType::Dashpot2, 2},
};

// Element types other codes know that clinch does not (E0210 rather than E0208).
// Abaqus and CalculiX element families (beams B21-B33, shells, solids, trusses, membranes, rigid,
// cohesive, gasket, heat transfer, acoustic, infinite, fluid, user elements).
constexpr std::string_view kKnownUnsupportedPrefixes[] = {
    "C3D", "C2D", "CPE", "CPS", "CAX", "CGAX", "CCL", "S3", "S4", "S8", "S9", "SAX", "STRI",
    "SC", "SFM", "B2", "B3", "PIPE", "ELBOW", "FRAME", "T2D", "T3D", "TAX", "M3D", "MAX", "MGAX",
    "MASS", "ROTARYI", "HEATCAP", "GAP", "ITS", "ISL", "DASHPOT", "SPRING", "CONN", "JOINT",
    "DCOUP", "KCOUP", "R3D", "R2D", "RAX", "RB", "COH", "GK", "DC", "DS", "AC", "CIN", "ACIN",
    "F2D", "F3D", "FAX", "FC3D", "WARP", "PSI", "EMC", "Q3D", "U", "VU"};

class ElementHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    part_ = &ctx.model().parts[ctx.position().part];
    part_index_ = ctx.position().part;
    reserve_for_block(part_->elements, ctx.expected_lines());
    const Field* type = ctx.params().value("TYPE");
    if (!type) return;
    std::string folded = fold_name(type->text);
    for (const ElementTypeInfo& info : kElementTypes) {
      if (folded == info.name) info_ = &info;
    }
    if (!info_) {
      bool known = false;
      for (std::string_view prefix : kKnownUnsupportedPrefixes) {
        if (folded.rfind(prefix, 0) == 0) known = true;
      }
      ctx.report(known ? DiagCode::unsupported_option : DiagCode::invalid_value, *type,
                 fmt::format("element type '{}' is {} (supported: CONN3D2, CONN2D2, SPRINGA, "
                             "SPRING1, SPRING2, DASHPOTA, DASHPOT1, DASHPOT2)",
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
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (!info_ || line.blank || fields.empty()) return;
    const int max_fields = 1 + info_->nodes;
    if (static_cast<int>(fields.size()) > max_fields) {
      ctx.check_field_count(line, fields, max_fields,
                            info_->nodes == 1 ? "label, node" : "label, node a, node b");
      return;
    }
    if (fields[0].empty()) {
      ctx.missing(fields[0].loc, "element label");
      return;
    }
    auto label = ctx.integer(fields[0], "element label");
    if (!label) return;
    if (*label < 1 || *label > 2147483647) {
      ctx.report(DiagCode::value_out_of_range, fields[0],
                 fmt::format("element label {} is out of range (1-2147483647)", *label));
      return;
    }
    Element element;
    element.label = static_cast<std::int32_t>(*label);
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
    const std::int32_t existing = part_->element_index.insert(element.label, index);
    if (existing != LabelIndex::kMissing) {
      ctx.report(DiagCode::duplicate_element, fields[0],
                 fmt::format("element {} is already defined", element.label))
          .notes.push_back({part_->elements[existing].loc(), "previous definition is here"});
      return;
    }
    part_->elements.push_back(element);
    for (Part::QualifiedNode& q : qualified) part_->qualified_nodes.push_back(std::move(q));
    if (set_) set_->members.push_back(index);
  }

 private:
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
