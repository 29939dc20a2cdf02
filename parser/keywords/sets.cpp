// *NSET and *ELSET (input-syntax.md §7.4). Members are recorded as set operations and replayed
// in deck order by resolve_geometry, because labels may refer to later definitions.
#include <fmt/format.h>

#include "parser/block_context.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keywords/geometry_common.hpp"

namespace clinch {

Set& define_set(Part& part, bool element_set, const Name& name) {
  auto& sets = element_set ? part.element_sets : part.node_sets;
  auto [it, inserted] = sets.try_emplace(name.key);
  if (inserted) it->second.name = name;
  return it->second;
}

namespace {

class SetHandler : public KeywordHandler {
 public:
  explicit SetHandler(bool element_set) : element_set_(element_set) {}

  void begin(BlockContext& ctx) override {
    part_ = &ctx.model().parts[ctx.position().part];
    const char* param = element_set_ ? "ELSET" : "NSET";
    auto name = ctx.name(*ctx.params().value(param), param);
    if (!name) return;
    key_ = name->key;
    Set& set = define_set(*part_, element_set_, *name);
    if (ctx.params().has("UNSORTED")) set.unsorted_loc = ctx.params().loc("UNSORTED");
    generate_ = ctx.params().has("GENERATE");
    if (const Field* instance = ctx.params().value("INSTANCE")) {
      if (ctx.position().part != 0 || !ctx.position().in_assembly) {
        ctx.report(DiagCode::wrong_level, *instance,
                   "INSTANCE= is allowed only on sets defined at assembly level");
        key_.clear();
        return;
      }
      if (auto inst = ctx.name(*instance, "INSTANCE")) {
        instance_key_ = inst->key;
        instance_display_ = inst->display;
      }
    }
    if (!element_set_) {
      if (const Field* elset = ctx.params().value("ELSET")) {
        if (generate_) {
          ctx.report(DiagCode::conflicting_parameters, ctx.params().loc("GENERATE"),
                     "GENERATE and ELSET cannot be used together on *NSET");
          key_.clear();
          return;
        }
        if (auto source = ctx.name(*elset, "ELSET")) {
          SetOperation op;
          op.kind = SetOperation::Kind::ElementNodes;
          op.target_key = key_;
          op.source_key = source->key;
          op.source_display = source->display;
          op.instance_key = instance_key_;
          op.instance_display = instance_display_;
          op.loc = elset->loc;
          part_->set_operations.push_back(std::move(op));
        }
        from_elset_ = true;
      }
    }
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (key_.empty() || line.blank || fields.empty()) return;
    if (from_elset_) {
      ctx.report(DiagCode::unexpected_data_line, line.loc,
                 "*NSET with ELSET= takes no data lines");
      from_elset_ = false;
      return;
    }
    if (generate_) {
      generate_line(ctx, line, fields);
      return;
    }
    if (fields.size() > 16 && !many_warned_) {
      many_warned_ = true;
      ctx.report(DiagCode::too_many_entries, line.loc,
                 fmt::format("{} entries on one line; Abaqus accepts at most 16", fields.size()));
    }
    for (const Field& field : fields) {
      if (field.empty()) continue;
      auto ref = ctx.target(field, element_set_ ? "element" : "node");
      if (!ref) continue;
      if (!ref->instance_key.empty() && !instance_key_.empty()) {
        ctx.report(DiagCode::expected_name, field,
                   "a qualified label cannot be used together with INSTANCE=");
        continue;
      }
      if (!ref->instance_key.empty() && ctx.position().part != 0) {
        ctx.report(DiagCode::expected_name, field,
                   "instance-qualified labels are allowed only at assembly level");
        continue;
      }
      const std::string& instance_key =
          ref->instance_key.empty() ? instance_key_ : ref->instance_key;
      const std::string& instance_display =
          ref->instance_key.empty() ? instance_display_ : ref->instance_display;
      auto& ops = part_->set_operations;
      if (ref->is_label) {
        const bool extend = !ops.empty() && ops.back().kind == SetOperation::Kind::Labels &&
                            ops.back().element_set == element_set_ &&
                            ops.back().target_key == key_ &&
                            ops.back().instance_key == instance_key;
        if (!extend) ops.push_back(make_op(SetOperation::Kind::Labels, instance_key,
                                           instance_display, field.loc));
        ops.back().labels.push_back({ref->label, field.loc});
      } else {
        SetOperation op = make_op(SetOperation::Kind::SetName, instance_key, instance_display,
                                  field.loc);
        op.source_key = ref->set_key;
        op.source_display = ref->set_display;
        ops.push_back(std::move(op));
      }
    }
  }

  SetOperation make_op(SetOperation::Kind kind, const std::string& instance_key,
                       const std::string& instance_display, SourceLoc loc) const {
    SetOperation op;
    op.kind = kind;
    op.element_set = element_set_;
    op.target_key = key_;
    op.instance_key = instance_key;
    op.instance_display = instance_display;
    op.loc = loc;
    return op;
  }

 private:
  void generate_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) {
    if (!ctx.check_field_count(line, fields, 3, "first, last, increment")) return;
    std::int64_t values[3] = {0, 0, 1};
    const char* what[3] = {"first label", "last label", "increment"};
    for (std::size_t k = 0; k < 3; ++k) {
      if (k >= fields.size() || fields[k].empty()) {
        if (k == 2) continue;
        ctx.missing(k < fields.size() ? fields[k].loc : BlockContext::end_of_line(line),
                    what[k]);
        return;
      }
      auto v = ctx.integer(fields[k], what[k]);
      if (!v) return;
      values[k] = *v;
    }
    if (values[0] < 1 || values[1] > 2147483647 || values[0] > values[1]) {
      ctx.report(DiagCode::value_out_of_range, fields[0],
                 fmt::format("GENERATE range {}-{} is invalid (need 1 <= first <= last)",
                             values[0], values[1]));
      return;
    }
    if (values[2] < 1) {
      ctx.report(DiagCode::value_out_of_range, fields[2],
                 fmt::format("GENERATE increment {} must be at least 1", values[2]));
      return;
    }
    if ((values[1] - values[0]) % values[2] != 0) {
      const std::int64_t stop = values[1] - (values[1] - values[0]) % values[2];
      ctx.report(DiagCode::generate_range_truncated, line.loc,
                 fmt::format("range {}-{} by {} stops at {}", values[0], values[1], values[2],
                             stop));
    }
    SetOperation op;
    op.kind = SetOperation::Kind::Range;
    op.element_set = element_set_;
    op.target_key = key_;
    op.instance_key = instance_key_;
    op.instance_display = instance_display_;
    op.first = static_cast<std::int32_t>(values[0]);
    op.last = static_cast<std::int32_t>(values[1]);
    op.increment = static_cast<std::int32_t>(values[2]);
    op.loc = line.loc;
    part_->set_operations.push_back(std::move(op));
  }

  bool element_set_;
  Part* part_ = nullptr;
  std::string key_;
  std::string instance_key_, instance_display_;
  bool generate_ = false;
  bool from_elset_ = false;
  bool many_warned_ = false;
};

}  // namespace

KeywordSpec nset_keyword_spec() {
  KeywordSpec spec;
  spec.name = "NSET";
  spec.level = KeywordLevel::ModelGeometry;
  spec.params = {{"NSET", ParamKind::Value, true}, {"GENERATE", ParamKind::Flag},
                 {"INSTANCE", ParamKind::Value}, {"ELSET", ParamKind::Value},
                 {"UNSORTED", ParamKind::Flag}, {"INTERNAL", ParamKind::Flag}};
  spec.make_handler = [] { return std::unique_ptr<KeywordHandler>(new SetHandler(false)); };
  return spec;
}

KeywordSpec elset_keyword_spec() {
  KeywordSpec spec;
  spec.name = "ELSET";
  spec.level = KeywordLevel::ModelGeometry;
  spec.params = {{"ELSET", ParamKind::Value, true}, {"GENERATE", ParamKind::Flag},
                 {"INSTANCE", ParamKind::Value}, {"UNSORTED", ParamKind::Flag},
                 {"INTERNAL", ParamKind::Flag}};
  spec.make_handler = [] { return std::unique_ptr<KeywordHandler>(new SetHandler(true)); };
  return spec;
}

}  // namespace clinch
