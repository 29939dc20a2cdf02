// Reference lookup (reference_lookup.hpp).
#include "src/resolve/reference_lookup.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "base/diagnostic.hpp"
#include "base/suggest.hpp"
#include "src/model/model.hpp"

namespace clinch {

namespace {

std::vector<std::string> instance_names(const Model& model) {
  std::vector<std::string> names;
  for (const Instance& i : model.instances) {
    if (!i.name.empty()) names.push_back(i.name.display);
  }
  return names;
}

}  // namespace

std::int32_t find_instance(const Model& model, const std::string& key, const std::string& display,
                           SourceLoc loc, DiagnosticSink& sink) {
  auto it = model.instance_by_key.find(key);
  if (it != model.instance_by_key.end()) return it->second;
  Diagnostic& d = sink.report(DiagCode::undefined_instance, loc,
                              fmt::format("'{}' is not an instance of the assembly", display));
  if (auto guess = closest_match(display, instance_names(model))) {
    d.notes.push_back({loc, fmt::format("did you mean '{}'?", *guess)});
  }
  return -1;
}

void report_undefined_set(const Part& part, bool element_set, const std::string& display,
                          SourceLoc loc, const std::string& where, DiagnosticSink& sink) {
  Diagnostic& d = sink.report(
      DiagCode::undefined_set, loc,
      fmt::format("undefined {} set '{}'{}", element_set ? "element" : "node", display, where));
  std::vector<std::string> names;
  for (const auto& [key, set] : element_set ? part.element_sets : part.node_sets) {
    names.push_back(set.name.display);
  }
  std::sort(names.begin(), names.end());
  if (auto guess = closest_match(display, names)) {
    const bool case_only = folded_edit_distance(*guess, display) == 0;
    d.notes.push_back({loc, fmt::format("did you mean '{}'?{}", *guess,
                                        case_only ? " (quoted names are case-sensitive)" : "")});
  }
}

namespace {

bool resolve(const Model& model, const TargetRef& ref, bool element_kind,
             std::vector<std::int32_t>& out, DiagnosticSink& sink) {
  out.clear();
  // Instances whose copies the reference denotes, with the part to look the name up in.
  std::vector<std::int32_t> instances;
  std::int32_t lookup_part = ref.part;
  if (!ref.instance_key.empty()) {
    std::int32_t inst = find_instance(model, ref.instance_key, ref.instance_display, ref.loc, sink);
    if (inst < 0) return false;
    instances.push_back(inst);
    lookup_part = model.instances[inst].part;
  } else if (ref.part == 0) {
    instances.push_back(0);
  } else {
    for (std::int32_t i = 0; i < static_cast<std::int32_t>(model.instances.size()); ++i) {
      if (model.instances[i].part == ref.part && i != 0) instances.push_back(i);
    }
  }
  const Part& part = model.parts[lookup_part];
  std::vector<std::int32_t> local;
  if (ref.is_label) {
    const LabelIndex& index = element_kind ? part.element_index : part.node_index;
    std::int32_t found = index.find(ref.label);
    if (found == LabelIndex::kMissing) {
      sink.report(
          element_kind ? DiagCode::undefined_element : DiagCode::undefined_node, ref.loc,
          fmt::format("{} {} is not defined{}", element_kind ? "element" : "node", ref.label,
                      ref.instance_key.empty()
                          ? std::string()
                          : fmt::format(" in instance '{}'", ref.instance_display)));
      return false;
    }
    local.push_back(found);
  } else {
    const auto& sets = element_kind ? part.element_sets : part.node_sets;
    auto it = sets.find(ref.set_key);
    if (it == sets.end()) {
      report_undefined_set(part, element_kind, ref.set_display, ref.loc,
                           ref.instance_key.empty()
                               ? std::string()
                               : fmt::format(" in instance '{}'", ref.instance_display),
                           sink);
      return false;
    }
    if (!it->second.defined_ok && it->second.members.empty()) return false;
    local = it->second.members;
  }
  if (lookup_part == 0) {
    out = std::move(local);  // root-part indices are global
    return true;
  }
  for (std::int32_t inst : instances) {
    const Instance& instance = model.instances[inst];
    const std::int32_t offset = element_kind ? instance.element_offset : instance.node_offset;
    for (std::int32_t m : local) out.push_back(m + offset);
  }
  return true;
}

}  // namespace

bool resolve_nodes(const Model& model, const TargetRef& ref, std::vector<std::int32_t>& out,
                   DiagnosticSink& sink) {
  return resolve(model, ref, false, out, sink);
}

bool resolve_elements(const Model& model, const TargetRef& ref, std::vector<std::int32_t>& out,
                      DiagnosticSink& sink) {
  return resolve(model, ref, true, out, sink);
}

}  // namespace clinch
